"""Compile (or load from the disk cache) every compiled part of impactlab ahead of its first use.

``warm()`` runs one small case through each part: the rigid impact with each friction model,
the parallel batch, the partial-slip impact, the flexible-rod drop (with and without partial
slip) and its parallel batch. The
first run after installing or updating impactlab compiles them (announced on stderr, see
``impactlab._compile_notice``); later runs load them from the cache in a second or two.
``impactlab warm`` and ``python3 tasks.py warm`` call it.
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import threading
import time
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

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


def _flexible_partial_slip() -> None:
    from impactlab.bodies import FlexibleRod
    from impactlab.dynamics.simulate import simulate

    simulate(  # the cells of Mindlin-Deresiewicz friction at each end (the batch shares them)
        FlexibleRod.paper(),
        law="ghaednia",
        friction="partial_slip",
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
    "flexible partial slip": _flexible_partial_slip,
    "flexible batch": _flexible_batch,
}


#: Parts that share little compiled code, warmed side by side by ``warm_in_processes``: the
#: rigid engine with its batch and partial slip, and the flexible rod with its batch.
PROCESS_GROUPS: tuple[tuple[str, ...], ...] = (
    ("contact laws", "rigid impact", "batch", "partial slip"),
    ("flexible rod", "flexible partial slip", "flexible batch"),
)


def _checked(parts: tuple[str, ...] | None) -> tuple[str, ...]:
    names = tuple(PARTS) if parts is None else parts
    unknown = [n for n in names if n not in PARTS]
    if unknown:
        raise ValueError(f"unknown engine part {unknown[0]!r}; choose from {', '.join(PARTS)}")
    return names


def warm(parts: tuple[str, ...] | None = None) -> list[WarmPart]:
    """Compile or load ``parts`` (names of ``PARTS``; default all) in this process; returns
    their timings."""
    names = _checked(parts)
    done = []
    for name in names:
        c0, w0 = time.process_time(), time.perf_counter()
        PARTS[name]()
        done.append(WarmPart(name, time.process_time() - c0, time.perf_counter() - w0))
    return done


def default_jobs() -> int:
    """Processes ``warm_in_processes`` uses by default: one per usable core, at most one per
    group of ``PROCESS_GROUPS``."""
    try:
        cores = len(os.sched_getaffinity(0))
    except AttributeError:  # not on Linux
        cores = os.cpu_count() or 1
    return max(1, min(cores, len(PROCESS_GROUPS)))


def _relay(stream: Any) -> None:
    """Copy a child's stderr (its compile notices) line by line to ours."""
    for line in stream:
        sys.stderr.write(line)
        sys.stderr.flush()


def warm_in_processes(
    parts: tuple[str, ...] | None = None, jobs: int | None = None
) -> list[WarmPart]:
    """``warm`` with the groups of ``PROCESS_GROUPS`` compiled side by side, one process each
    (``jobs`` > 1, default ``default_jobs()``), into the same cache; the parts' timings are the
    processes' own (CPU seconds of the process that compiled them). The children's compile
    notices come through on stderr, one line each."""
    names = _checked(parts)
    jobs = default_jobs() if jobs is None else jobs
    if jobs < 1:
        raise ValueError(f"jobs must be a whole number >= 1, got {jobs}")
    groups = [[n for n in g if n in names] for g in PROCESS_GROUPS]
    groups = [g for g in groups if g]
    if jobs == 1 or len(groups) < 2:
        return warm(names)
    procs = []
    for group in groups:
        cmd = [sys.executable, "-m", "impactlab", "warm", "--json", "--jobs", "1"]
        for name in group:
            cmd += ["--part", name]
        proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        relay = threading.Thread(target=_relay, args=(proc.stderr,), daemon=True)
        relay.start()
        procs.append((group, proc, relay))
    timings: dict[str, WarmPart] = {}
    failed = []
    for group, proc, relay in procs:
        out = proc.stdout.read() if proc.stdout is not None else ""
        proc.wait()
        relay.join()
        if proc.returncode != 0:
            failed.append(f"{', '.join(group)} (exit code {proc.returncode})")
            continue
        for p in json.loads(out)["parts"]:
            timings[p["name"]] = WarmPart(
                p["name"], p["cpu_time"]["value"], p["wall_time"]["value"]
            )
    if failed:
        raise RuntimeError(f"warming the engine failed in: {'; '.join(failed)} (see above)")
    return [timings[n] for n in names]


__all__ = [
    "PARTS",
    "PROCESS_GROUPS",
    "WarmPart",
    "compiled_cache_dir",
    "default_jobs",
    "warm",
    "warm_in_processes",
]
