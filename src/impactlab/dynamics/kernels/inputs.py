"""The rules of an impact's inputs, in one place: the angle of a rod, the speeds, the spin, the
friction coefficient, gravity and the tolerance.

Every check of these inputs reads this module: the compiled cores (``setup.check_inputs``, so
every batch and sweep case), the Python API (``dynamics.input_checks``, ``dynamics.checks``,
``simulate``'s fast path, a batch of drops), the command line and a sweep's study check. The
functions are pure and plain Python where Python calls them; where compiled code calls them,
numba compiles them inline (``register_jitable``): one definition for both.
:func:`input_problem` applies every rule at once and names the first input outside its rule
(``IN_*``); :data:`INPUT_RULES` says each rule in words for the errors.
"""

from __future__ import annotations

import math

from numba.extending import register_jitable

from impactlab._input_limits import GRAVITY_RULE, MAX_GRAVITY, MAX_MU, MAX_SPEED

# --- bounds --------------------------------------------------------------------------------------
# MAX_SPEED [m/s], MAX_MU [1] and MAX_GRAVITY [m/s^2]: ``impactlab._input_limits`` (the closed
# forms of the inversion check gravity against the same bound).
#: Largest angle of a rod to the flat [rad]: pi/2, plus 1e-12 for 90 deg converted from degrees.
MAX_ANGLE = 0.5 * math.pi + 1e-12
#: The relative tolerance's range [1].
RTOL_MIN = 1e-13
RTOL_MAX = 1e-3
RTOL_RANGE = (RTOL_MIN, RTOL_MAX)

# --- which input broke its rule (0: none) --------------------------------------------------------
IN_OK = 0
IN_ANGLE = 1
IN_VX = 2
IN_VY = 3
IN_SPIN = 4
IN_MU = 5
IN_GRAVITY = 6
IN_RTOL = 7

#: (input, its rule in words) by ``IN_*`` code.
INPUT_RULES: dict[int, tuple[str, str]] = {
    IN_ANGLE: ("angle", "a rod's angle to the flat must lie in (0, pi/2] rad, (0, 90] deg"),
    IN_VX: ("vx", f"a velocity component must be finite and at most {MAX_SPEED:g} m/s"),
    IN_VY: ("vy", f"a velocity component must be finite and at most {MAX_SPEED:g} m/s"),
    IN_SPIN: (
        "spin",
        f"the spin times the reach of the contact point (L/2 + R) must be finite and at most "
        f"{MAX_SPEED:g} m/s",
    ),
    IN_MU: ("mu", f"mu must lie in [0, {MAX_MU:g}]"),
    IN_GRAVITY: ("gravity", GRAVITY_RULE),
    IN_RTOL: ("rtol", f"rtol must lie in [{RTOL_RANGE[0]:g}, {RTOL_RANGE[1]:g}]"),
}


@register_jitable
def angle_allowed(angle: float) -> bool:
    """A rod's angle to the flat [rad] in (0, pi/2] (NaN: False)."""
    return 0.0 < angle <= MAX_ANGLE


def incidence_allowed(incidence: float) -> bool:
    """The angle [rad] of the centre of mass's velocity to the flat's normal (``speed`` and
    ``incidence`` instead of vx and vy) in (-pi/2, pi/2) (NaN: False)."""
    return abs(incidence) < 0.5 * math.pi


@register_jitable
def speed_allowed(speed: float) -> bool:
    """A speed or velocity component [m/s] of magnitude at most MAX_SPEED (NaN: False)."""
    return abs(speed) <= MAX_SPEED


@register_jitable
def spin_allowed(spin: float, reach: float) -> bool:
    """A spin [rad/s] whose contact point, ``reach`` [m] from the centre of mass (L/2 + R),
    moves at most MAX_SPEED (NaN: False)."""
    return abs(spin) * reach <= MAX_SPEED


@register_jitable
def mu_allowed(mu: float) -> bool:
    """A friction coefficient in [0, MAX_MU] (NaN: False)."""
    return 0.0 <= mu <= MAX_MU


@register_jitable
def gravity_allowed(gravity: float) -> bool:
    """A gravitational acceleration [m/s^2] in [0, MAX_GRAVITY] (NaN: False)."""
    return 0.0 <= gravity <= MAX_GRAVITY


@register_jitable
def rtol_allowed(rtol: float) -> bool:
    """A relative tolerance in RTOL_RANGE (NaN: False)."""
    return RTOL_MIN <= rtol <= RTOL_MAX


@register_jitable
def input_problem(
    rod: bool,
    angle: float,
    vx: float,
    vy: float,
    spin: float,
    reach: float,
    mu: float,
    gravity: float,
    rtol: float,
) -> int:
    """IN_OK, or the ``IN_*`` code of the first input outside its rule, in this order: vx and
    vy [m/s], the spin [rad/s] with the contact point's ``reach`` [m] (L/2 + R), mu, gravity
    [m/s^2], rtol, and last the angle [rad] (of a rod; a sphere's is not read), so that a
    status naming the angle (``ST_BAD_ANGLE``) means every other input is allowed. NaN breaks
    every rule."""
    if not speed_allowed(vx):
        return IN_VX
    if not speed_allowed(vy):
        return IN_VY
    if not spin_allowed(spin, reach):
        return IN_SPIN
    if not mu_allowed(mu):
        return IN_MU
    if not gravity_allowed(gravity):
        return IN_GRAVITY
    if not rtol_allowed(rtol):
        return IN_RTOL
    if rod and not angle_allowed(angle):
        return IN_ANGLE
    return IN_OK


def problem_text(code: int, value: float) -> str:
    """The error of an ``IN_*`` code: ``"mu = 2000.0: mu must lie in [0, 1000]"``."""
    name, rule = INPUT_RULES[code]
    return f"{name} = {value!r}: {rule}"


__all__ = [
    "INPUT_RULES",
    "IN_ANGLE",
    "IN_GRAVITY",
    "IN_MU",
    "IN_OK",
    "IN_RTOL",
    "IN_SPIN",
    "IN_VX",
    "IN_VY",
    "MAX_ANGLE",
    "MAX_GRAVITY",
    "MAX_MU",
    "MAX_SPEED",
    "RTOL_MAX",
    "RTOL_MIN",
    "RTOL_RANGE",
    "angle_allowed",
    "gravity_allowed",
    "incidence_allowed",
    "input_problem",
    "mu_allowed",
    "problem_text",
    "rtol_allowed",
    "speed_allowed",
    "spin_allowed",
]
