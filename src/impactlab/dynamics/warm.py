"""Compile (or load from the disk cache) every compiled part of impactlab ahead of its first use.

``warm()`` runs one small case through each part: the rigid impact with each friction model,
the parallel batch, the partial-slip impact, the flexible-rod drop and its parallel batch. The
first run after installing or updating impactlab compiles them (announced on stderr, see
``impactlab._compile_notice``); later runs load them from the cache in a second or two.
``impactlab warm`` and ``python3 tasks.py warm`` call it.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from dataclasses import dataclass

from impactlab._compiled_cache import compiled_cache_dir


@dataclass(frozen=True)
class WarmPart:
    """One compiled part: its name and the CPU and wall seconds its first call took here."""

    name: str
    cpu_s: float
    wall_s: float


def _rigid() -> None:
    from impactlab.bodies import PAPER_ROD
    from impactlab.dynamics.simulate import simulate

    for fr in ("impulse_ratio", "coulomb", "mindlin"):
        for history in (False, True):
            r = simulate(
                PAPER_ROD,
                law="ghaednia",
                friction=fr,
                mu=0.2,
                angle=math.radians(20),
                velocity=(0.0, -1.41),
                history=history,
            )
    r.dent(nx=21, ny=11)  # the dent map's kernels


def _batch() -> None:
    from impactlab.bodies import PAPER_ROD
    from impactlab.dynamics.simulate_many import simulate_batch

    simulate_batch(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        vy=[-1.0, -1.41],
    )


def _partial_slip() -> None:
    from impactlab.bodies import PAPER_ROD
    from impactlab.dynamics.simulate import simulate
    from impactlab.dynamics.simulate_many import simulate_batch

    for history in (False, True):
        simulate(
            PAPER_ROD,
            law="ghaednia",
            friction="partial_slip",
            mu=0.2,
            angle=math.radians(20),
            velocity=(0.0, -1.41),
            history=history,
        )
    simulate_batch(  # the parallel loop over cases
        PAPER_ROD,
        law="ghaednia",
        friction="partial_slip",
        mu=0.2,
        angle=math.radians(20),
        vy=[-1.0, -1.41],
    )


def _flexible() -> None:
    from impactlab.bodies import FlexibleRod
    from impactlab.dynamics.simulate import simulate

    simulate(
        FlexibleRod.paper(),
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )


def _flexible_batch() -> None:
    from impactlab.bodies import FlexibleRod
    from impactlab.dynamics.drop_batch import simulate_drops

    simulate_drops(
        FlexibleRod.paper(n_axial=1, n_bending=2),
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        vy=[-1.0, -1.41],
    )


def _contact_laws() -> None:
    from impactlab.bodies import PAPER_ROD
    from impactlab.contact import builtin_law_names, get_law
    from impactlab.materials import AISI_201, AISI_1010, ContactPair

    pair = ContactPair(AISI_201, AISI_1010)
    for name in builtin_law_names():
        model = get_law(name).build(pair, PAPER_ROD.tip_radius)
        model.force([1e-7, 1e-5])
        model.contact_radius([1e-7, 1e-5])
        model.unload(1e-5)


#: The parts in the order ``warm`` compiles them.
PARTS: dict[str, Callable[[], None]] = {
    "contact laws": _contact_laws,
    "rigid impact": _rigid,
    "batch": _batch,
    "partial slip": _partial_slip,
    "flexible rod": _flexible,
    "flexible batch": _flexible_batch,
}


def warm(parts: tuple[str, ...] | None = None) -> list[WarmPart]:
    """Compile or load ``parts`` (names of ``PARTS``; default all); returns their timings."""
    names = tuple(PARTS) if parts is None else parts
    unknown = [n for n in names if n not in PARTS]
    if unknown:
        raise ValueError(f"unknown engine part {unknown[0]!r}; choose from {', '.join(PARTS)}")
    done = []
    for name in names:
        c0, w0 = time.process_time(), time.perf_counter()
        PARTS[name]()
        done.append(WarmPart(name, time.process_time() - c0, time.perf_counter() - w0))
    return done


__all__ = ["PARTS", "WarmPart", "compiled_cache_dir", "warm"]
