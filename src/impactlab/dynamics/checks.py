"""Validation of the engine's Python inputs (one place for simulate, simulate_batch, run_arrays
and the reference implementation): gravity, tolerance, angle, velocity, body and flat."""

from __future__ import annotations

import math
from typing import Any

from impactlab._validation import check_finite, check_nonnegative
from impactlab.bodies import Rod, Sphere
from impactlab.dynamics.core.layout import DEFAULT_RTOL
from impactlab.materials import G0, Material

#: Range of the relative tolerance accepted by the Python API.
RTOL_RANGE = (1e-13, 1e-3)


def gravity_value(gravity: bool | float | None) -> float:
    """True -> standard gravity 9.80665 m/s^2, False (or None) -> 0, a number -> that value
    (>= 0) [m/s^2]."""
    if gravity is True:
        return G0
    if gravity is False or gravity is None:
        return 0.0
    return check_nonnegative("gravity", gravity, "m/s^2")


def check_rtol(rtol: float | None) -> float:
    """The relative tolerance (None: ``DEFAULT_RTOL``), in [1e-13, 1e-3]."""
    if rtol is None:
        return DEFAULT_RTOL
    r = check_finite("rtol", rtol)
    if not RTOL_RANGE[0] <= r <= RTOL_RANGE[1]:
        raise ValueError(f"rtol must lie in [1e-13, 1e-3], got {r!r}")
    return r


def check_angle(angle: Any, body: Rod | Sphere) -> float:
    """Validate the rod angle (radians, in (0, pi/2]); ignored (pi/2) for a sphere."""
    if isinstance(body, Sphere):
        if angle is not None:
            check_finite("angle", angle)
        return 0.5 * math.pi
    if angle is None:
        raise ValueError(
            "angle is required for a Rod: the rod axis to the flat, in radians, in (0, pi/2]"
        )
    th = check_finite("angle", angle)
    if th > 0.5 * math.pi + 1e-12:
        hint = ""
        if th <= 90.0 + 1e-9:
            hint = (
                f"; {th!r} looks like degrees: pass math.radians({th!r}) = "
                f"{math.radians(th):.6g} rad"
            )
        raise ValueError(f"angle must be in radians in (0, pi/2], got {th!r}{hint}")
    if th <= 0.0:
        raise ValueError(f"angle must be in radians in (0, pi/2], got {th!r}")
    return th


def check_velocity(velocity: Any) -> tuple[float, float]:
    """(vx, vy) [m/s] from a pair of finite numbers."""
    try:
        vx, vy = velocity
    except (TypeError, ValueError):
        raise ValueError(f"velocity must be a pair (vx, vy) in m/s, got {velocity!r}") from None
    return check_finite("velocity[0] (vx)", vx), check_finite("velocity[1] (vy)", vy)


def check_body(body: Any) -> Rod | Sphere:
    """``body`` if it is a Rod or a Sphere, else ValueError."""
    if not isinstance(body, Rod | Sphere):
        raise ValueError(f"body must be an impactlab Rod or Sphere, got {type(body).__name__}")
    return body


def check_flat(flat: Any) -> Material:
    """``flat`` if it is a Material, else ValueError."""
    if not isinstance(flat, Material):
        raise ValueError(f"flat must be an impactlab Material, got {type(flat).__name__}")
    return flat


__all__ = [
    "RTOL_RANGE",
    "check_angle",
    "check_body",
    "check_flat",
    "check_rtol",
    "check_velocity",
    "gravity_value",
]
