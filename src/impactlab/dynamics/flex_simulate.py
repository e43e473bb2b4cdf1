"""``impactlab.simulate`` with a FlexibleRod: the flexible drop
(``impactlab.dynamics.drop.simulate_drop``) called with ``simulate``'s arguments, the error
of ``simulate_batch`` with a FlexibleRod, and the check of a drop's mode count
(``mode_convergence``)."""

from __future__ import annotations

import dataclasses
import itertools
import math
from collections.abc import Iterable, Sequence
from typing import Any

from impactlab._validation import check_flag, unexpected_keywords
from impactlab.bodies.flexible_rod import MAX_MODES, FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.time_limit import RENAMED_KEYWORDS, renamed_keywords
from impactlab.materials import AISI_1010, Material

__all__ = [
    "DROP_OPTIONS",
    "FLEXIBLE_BATCH_ERROR",
    "ModeConvergence",
    "check_simulate_keywords",
    "mode_convergence",
    "simulate_flexible",
]


#: Options of ``impactlab.simulate`` that only the flexible drop takes.
DROP_OPTIONS = ("rate", "stop", "time_limit")
#: simulate's arguments that ``simulate_drop`` takes under the same name.
_SIMULATE_ARGS: tuple[str, ...] = ("law", "friction", "mu", "angle", "velocity", "spin")
_SIMULATE_ARGS += ("law_params", "gravity", "rtol")


def check_simulate_keywords(given: Iterable[str]) -> None:
    """TypeError for a keyword ``simulate`` does not take, in simulate_batch's words (the
    nearest name), with the drop's options named; the drop's old names pass (read as new)."""
    known = (*_SIMULATE_ARGS, "constant_angle", "history", "speed", "incidence", *DROP_OPTIONS)
    known += ("partial_slip_cells",)  # simulate's own (checked there), not passed on here
    extra = sorted(set(given) - set(known) - set(RENAMED_KEYWORDS))
    if extra:
        text = unexpected_keywords("simulate", extra, known, {})
        raise TypeError(f"{text} ({', '.join(DROP_OPTIONS)}: a FlexibleRod's drop)")


def simulate_flexible(
    body: Any,
    flat: Material,
    *,
    constant_angle: Any = False,
    history: Any = True,
    **kwargs: Any,
) -> DropResult:
    """``impactlab.simulate`` for a FlexibleRod: the flexible drop (``simulate_drop``) with
    simulate's arguments (law, friction, mu, angle, velocity, spin, law_params, gravity, rtol,
    history) and the drop's options ``rate``, ``stop``, ``time_limit`` (``t_max``, its name
    before 0.3: a DeprecationWarning). ``constant_angle`` must be False (the drop follows the
    rod's rotation). TypeError for a drop option with another body or an unknown keyword."""
    check_simulate_keywords(kwargs)
    if not isinstance(body, FlexibleRod):
        given = sorted(set(kwargs) & {*DROP_OPTIONS, *RENAMED_KEYWORDS})
        raise TypeError(
            f"simulate() got {', '.join(given)}: options of a FlexibleRod's drop (got body "
            f"{type(body).__name__}; a rigid rod's drop: impactlab.simulate_drop)"
        )
    if check_flag("constant_angle", constant_angle):
        raise ValueError(
            "constant_angle=True freezes the rigid engine's lever arms; the flexible drop "
            "follows the rod's rotation: pass constant_angle=False with a FlexibleRod"
        )
    if kwargs.get("angle") is None:
        raise ValueError("angle is required for a FlexibleRod (radians, in (0, pi/2])")
    kwargs = renamed_keywords("simulate", kwargs)
    return simulate_drop(body, flat, history=check_flag("history", history), **kwargs)


#: The error of ``simulate_batch`` with a FlexibleRod.
FLEXIBLE_BATCH_ERROR = (
    "simulate_batch runs the rigid engine; many drops of a FlexibleRod run in "
    "impactlab.simulate_drops(FlexibleRod(...), angle=..., vy=...), or a study file with "
    'body = "flexible_rod" (impactlab.sweep)'
)


@dataclasses.dataclass(frozen=True)
class ModeConvergence:
    """One drop at growing mode counts (``mode_convergence``): ``modes`` ((n_axial, n_bending)
    of each run) and ``results`` (their DropResults, in that order)."""

    modes: tuple[tuple[int, int], ...]
    results: tuple[DropResult, ...]

    def _change(self, name: str) -> float:
        a, b = (float(getattr(r, name)) for r in self.results[-2:])
        return abs(b - a) / abs(b) if b != 0.0 else (0.0 if a == b else math.inf)

    @property
    def e_change(self) -> float:
        """|e of the last run - e of the one before| / |e of the last| [1]."""
        return self._change("e")

    @property
    def dent_change(self) -> float:
        """The same for the dent depth [1]."""
        return self._change("dent_depth")

    @property
    def same_contacts(self) -> bool:
        """Whether the last two runs have the same number of contacts."""
        return self.results[-1].n_contacts == self.results[-2].n_contacts

    def converged(self, tol: float = 0.01) -> bool:
        """The last two runs agree: the same contacts, e and the dent within ``tol`` [1]."""
        return self.same_contacts and self.e_change <= tol and self.dent_change <= tol


def mode_convergence(
    body: FlexibleRod,
    flat: Material = AISI_1010,
    *,
    factors: Sequence[float] = (1, 2, 4),
    **kwargs: Any,
) -> ModeConvergence:
    """``simulate_drop(body, flat, **kwargs)`` with ``body``'s mode counts times each of
    ``factors`` (rounded, at most ``MAX_MODES`` = 128; ``history`` False unless given), to
    check that the drop's e, dent and contacts converge in the modes: ``converged()`` when
    the last two runs agree (docs/flexible.md, "Convergence and the default"). A tighter
    rtol does not show a truncation of the modes. ValueError for a body that is no
    FlexibleRod or fewer than two growing factors; a drop's own errors as ``simulate_drop``."""
    if not isinstance(body, FlexibleRod):
        raise ValueError(
            f"body must be a FlexibleRod (its modes are refined), got {type(body).__name__}"
        )
    f = [float(x) for x in factors]
    if len(f) < 2 or not all(0.0 < a < b for a, b in itertools.pairwise(f)):
        raise ValueError(f"factors must be two or more growing numbers > 0, got {factors!r}")
    counts = [(_scaled(body.n_axial, k), _scaled(body.n_bending, k)) for k in f]
    for a, b in itertools.pairwise(counts):
        if a == b:
            capped = f" (the counts stop at {MAX_MODES})" if MAX_MODES in a else ""
            raise ValueError(
                f"factors {factors!r} give the mode counts (n_axial, n_bending) = {a} twice"
                f"{capped}; give factors whose counts grow"
            )
    kwargs.setdefault("history", False)
    results = tuple(
        simulate_drop(dataclasses.replace(body, n_axial=na, n_bending=nb), flat, **kwargs)
        for na, nb in counts
    )
    return ModeConvergence(tuple(counts), results)


def _scaled(n: int | None, factor: float) -> int:
    """The mode count ``n`` times ``factor``, rounded, in [1, MAX_MODES] (0 stays 0)."""
    return min(MAX_MODES, max(1, round(n * factor))) if n else 0
