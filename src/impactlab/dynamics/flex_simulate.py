"""``impactlab.simulate`` with a FlexibleRod: the flexible drop
(``impactlab.dynamics.drop.simulate_drop``) called with ``simulate``'s arguments, and the error
of ``simulate_batch`` with a FlexibleRod."""

from __future__ import annotations

import difflib
from typing import Any

from impactlab._validation import check_flag
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.materials import Material

__all__ = ["DROP_OPTIONS", "FLEXIBLE_BATCH_ERROR", "simulate_flexible"]


#: Options of ``impactlab.simulate`` that only the flexible drop takes.
DROP_OPTIONS = ("rate", "stop", "t_max")
#: simulate's arguments that ``simulate_drop`` takes under the same name.
_SIMULATE_ARGS: tuple[str, ...] = ("law", "friction", "mu", "angle", "velocity", "spin")
_SIMULATE_ARGS += ("law_params", "gravity", "rtol")


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
    history) and the drop's options ``rate``, ``stop``, ``t_max``. ``constant_angle`` must be
    False (the drop follows the rod's rotation). TypeError for a drop option with another body
    or an unknown keyword."""
    known = (*_SIMULATE_ARGS, "constant_angle", "history", "speed", "incidence", *DROP_OPTIONS)
    extra = sorted(set(kwargs) - set(known))
    if extra:
        hints = [
            f"{k} (did you mean {close[0]}?)" if close else k
            for k in extra
            for close in [difflib.get_close_matches(k, known, n=1)]
        ]
        raise TypeError(
            f"simulate() got unexpected keyword argument(s) {', '.join(hints)}; it takes "
            f"{', '.join(sorted(known))} ({', '.join(DROP_OPTIONS)}: a FlexibleRod's drop)"
        )
    if not isinstance(body, FlexibleRod):
        given = sorted(set(kwargs) & set(DROP_OPTIONS))
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
    return simulate_drop(body, flat, history=check_flag("history", history), **kwargs)


#: The error of ``simulate_batch`` with a FlexibleRod.
FLEXIBLE_BATCH_ERROR = (
    "simulate_batch runs the rigid engine; many drops of a FlexibleRod run in "
    "impactlab.simulate_drops(FlexibleRod(...), angle=..., vy=...), or a study file with "
    'body = "flexible_rod" (impactlab.sweep)'
)
