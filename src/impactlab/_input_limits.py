"""The bounds of an impact's inputs that more than one layer checks: the compiled engine's input
rules (``dynamics.kernels.inputs``) and the closed forms of the inversion (``analytic``) read
them here, so one number holds everywhere (SI units)."""

from __future__ import annotations

import math

#: Largest speed [m/s] of each velocity component of the centre of mass and of the contact
#: point's circumferential speed from the spin: far beyond the impacts a contact law of rigid
#: bodies describes; faster, the energy bookkeeping (kinetic energies of order m v^2) would
#: lose the digits of the work it balances.
MAX_SPEED = 1e4
#: Largest friction coefficient [1]: dry contacts stay below about 2; a larger mu sticks.
MAX_MU = 1e3
#: Largest gravitational acceleration [m/s^2] (a million g).
MAX_GRAVITY = 1e7
#: The gravity rule in words, for the errors.
GRAVITY_RULE = f"gravity must lie in [0, {MAX_GRAVITY:g}] m/s^2 (a million g)"

#: Up to this far past pi/2 [rad] a bare angle reads as a rod past the normal, not degrees.
PAST_NORMAL = math.radians(10.0)


def degrees_hint(th: float) -> str:
    """``"; if 20.0 is meant in degrees, pass math.radians(20.0) = ..."`` for a bare angle
    ``th`` [rad] in (pi/2 + PAST_NORMAL, 90], which reads as degrees; else ``""``."""
    if not 0.5 * math.pi + PAST_NORMAL < th <= 90.0 + 1e-9:
        return ""
    return (
        f"; if {th!r} is meant in degrees, pass math.radians({th!r}) = "
        f"{math.radians(th):.6g} rad or the string '{th:g} deg'"
    )


__all__ = ["GRAVITY_RULE", "MAX_GRAVITY", "MAX_MU", "MAX_SPEED", "PAST_NORMAL", "degrees_hint"]
