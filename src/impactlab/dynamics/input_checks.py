"""Checks of the engine's Python inputs one at a time: gravity, mu, a speed, the spin, the
tolerance, the angle, the velocity (or speed and incidence), body and flat. The rules themselves
(the bounds, the angle's range) are those of ``dynamics.kernels.inputs``, which the compiled
cores apply too; these functions read the inputs' units and types and word the errors.

Quantities follow ``impactlab.units.magnitude`` (a number in SI, a string with units such as
``"20 deg"`` or ``"1.41 m/s"``, or a pint Quantity of any registry); dimensionless inputs (mu,
rtol) follow the number rule of ``impactlab._validation`` (no strings, no bools).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._input_limits import PAST_NORMAL, degrees_hint
from impactlab._validation import (
    check_finite,
    check_flag,
    check_nonnegative,
    check_positive,
    value_text,
    warn_implausible,
)
from impactlab.bodies import Rod, Sphere
from impactlab.bodies._checks import check_material
from impactlab.dynamics.kernels.inputs import (
    MAX_GRAVITY,
    MAX_MU,
    MAX_SPEED,
    angle_allowed,
    gravity_allowed,
    incidence_allowed,
    mu_allowed,
    speed_allowed,
    spin_allowed,
)
from impactlab.dynamics.rtol_checks import (
    DROP_RTOL_MAX,
    MINDLIN_RTOL_MAX,
    PARTIAL_SLIP_RTOL_MAX,
    check_friction_rtol,
    check_partial_slip_rtol,
    check_rtol,
    friction_rtol_max,
)
from impactlab.dynamics.velocity_inputs import batch_velocity, velocity_given
from impactlab.friction import PARTIAL_SLIP_CELLS, PARTIAL_SLIP_CELLS_MAX, PARTIAL_SLIP_CELLS_MIN
from impactlab.materials import G0, Material
from impactlab.units import has_unit, magnitude

#: Speeds above this [m/s] (of the centre of mass or of the contact point) draw an
#: ImplausibleInputWarning: most likely a unit mistake (mm/s taken as m/s).
PLAUSIBLE_SPEED = 100.0


def gravity_value(gravity: Any) -> float:
    """True -> standard gravity 9.80665 m/s^2, False -> 0, a value (>= 0; a number in m/s^2, a
    string with units or a pint Quantity) -> that value [m/s^2]; None is refused (ValueError:
    it could mean either)."""
    if gravity is None:
        raise ValueError(
            "gravity must be True (9.80665 m/s^2), False (none) or a value in m/s^2, got None"
        )
    if isinstance(gravity, bool | np.bool_):
        return G0 if gravity else 0.0
    try:
        g = check_nonnegative("gravity", gravity, "m/s^2")
    except ValueError as exc:
        if not isinstance(gravity, str) or "cannot parse" not in str(exc):
            raise
        raise ValueError(
            f"{exc}; gravity must be True (9.80665 m/s^2), False (none) or a value in m/s^2 "
            "(for example '9.81 m/s^2')"
        ) from None
    if not gravity_allowed(g):
        raise ValueError(
            f"gravity must lie in [0, {MAX_GRAVITY:g}] m/s^2 (a million g), got {g!r} m/s^2"
        )
    return g


def check_mu(mu: Any) -> float:
    """The friction coefficient, in [0, MAX_MU]; a ValueError in ``mu_problem``'s words."""
    if why := mu_problem(m := check_finite("mu", mu)):
        raise ValueError(why)
    return m


def mu_problem(mu: float) -> str:
    """Why a finite ``mu`` is refused ("" if not), as one run and a batch's case say it."""
    if mu < 0.0:
        return f"mu must be >= 0, got {value_text(mu)}"
    if mu_allowed(mu):
        return ""
    why = "dry friction stays below about 2; a larger mu only sticks"
    return f"mu must lie in [0, {MAX_MU:g}] ({why}), got {mu!r}"


def check_speed(name: str, speed: float) -> float:
    """``speed`` [m/s] unless its magnitude exceeds MAX_SPEED (ValueError naming ``name``)."""
    if not speed_allowed(speed):
        raise ValueError(
            f"{name} = {speed!r} m/s exceeds {MAX_SPEED:g} m/s in magnitude, far beyond the "
            "impacts a contact law of rigid bodies describes (and the energy balance would lose "
            f"its digits); allowed: up to {MAX_SPEED:g} m/s"
        )
    return speed


def check_spin(spin: float, reach: float) -> float:
    """``spin`` [rad/s] unless it moves the contact point, ``reach`` [m] from the centre of mass
    (L/2 + R), faster than MAX_SPEED (ValueError)."""
    if not spin_allowed(spin, reach):
        raise ValueError(
            f"spin = {spin!r} rad/s moves the contact point ({reach:.4g} m from the centre of "
            f"mass: L/2 + R for a rod, R for a sphere) at {abs(spin) * reach:.4g} m/s, beyond "
            f"{MAX_SPEED:g} m/s; allowed: "
            f"|spin| <= {MAX_SPEED / reach:.4g} rad/s"
        )
    return spin


def contact_reach(body: Rod | Sphere) -> float:
    """The farthest point of contact from the centre of mass [m]: L/2 + R."""
    return body.half_length + body.tip_radius


def check_partial_slip_cells(cells: Any, friction: str | None = None) -> int:
    """``partial_slip_cells`` as an int: an integer (not a bool, float or string) in
    [``PARTIAL_SLIP_CELLS_MIN``, ``PARTIAL_SLIP_CELLS_MAX``]; any value but the default
    ``PARTIAL_SLIP_CELLS`` is refused when ``friction`` (a model's name; None: not known here)
    is not ``partial_slip``, whose cells it sets. ValueError, one line, naming the option."""
    if (
        isinstance(cells, bool)
        or not isinstance(cells, int | np.integer)
        or not PARTIAL_SLIP_CELLS_MIN <= cells <= PARTIAL_SLIP_CELLS_MAX
    ):
        raise ValueError(
            f"partial_slip_cells must be an integer in [{PARTIAL_SLIP_CELLS_MIN}, "
            f"{PARTIAL_SLIP_CELLS_MAX}] (the cells of friction 'partial_slip' over the largest "
            f"contact radius; default {PARTIAL_SLIP_CELLS}), got {cells!r}"
        )
    n = int(cells)
    if n != PARTIAL_SLIP_CELLS and friction is not None and friction != "partial_slip":
        raise ValueError(
            f"partial_slip_cells = {n} sets the cells of friction 'partial_slip' only, and the "
            f"friction is {friction!r}: leave it out, or choose friction 'partial_slip'"
        )
    return n


def check_angle(angle: Any, body: Rod | Sphere) -> float:
    """Validate the rod angle (in (0, pi/2]; a bare number is radians, ``"20 deg"`` works). A
    sphere has none: pi/2 inside, and an angle given for it is refused (as on the command line:
    an input that does not apply to the body is refused everywhere)."""
    if isinstance(body, Sphere):
        if angle is not None:
            raise ValueError(
                f"angle ({angle!r}): a Sphere has no angle to the flat (its contact point lies "
                "below its centre); leave angle out"
            )
        return 0.5 * math.pi
    if angle is None:
        raise ValueError(
            "angle is required for a Rod: the rod axis to the flat, in radians, in (0, pi/2]"
        )
    th = check_finite("angle", angle, "rad")
    if angle_allowed(th):
        return th
    unit = has_unit(angle)  # the user gave a unit: answer in degrees
    hint = past_normal(th, unit) if 0.5 * math.pi < th < math.pi else ""
    if unit:
        raise ValueError(f"angle must be in (0, 90] deg, got {_as_given(angle)}{hint}")
    hint += degrees_hint(th)
    hint = f" ({math.degrees(th):.6g} deg){hint}" if hint else ""
    raise ValueError(f"angle must be in radians in (0, pi/2], got {th!r} rad{hint}")


def warn_degrees(refused: np.ndarray) -> None:
    """An ImplausibleInputWarning, once per batch, when every angle it refused (``refused``
    [rad], outside (0, pi/2]) lies in (pi/2 + ``PAST_NORMAL``, 90]: bare numbers in degrees
    (:func:`degrees_hint`), which fail case by case (status 7) otherwise."""
    if refused.size == 0 or not all(degrees_hint(float(th)) for th in refused):
        return
    lo, hi = float(refused.min()), float(refused.max())
    span = f"{lo:g}" if lo == hi else f"{lo:g} to {hi:g}"
    warn_implausible(
        f"angle: every refused angle ({refused.size} case(s), {span}) lies in (pi/2 + "
        f"{math.degrees(PAST_NORMAL):g} deg, 90]: "
        "degrees? a bare angle is radians, as every bare number of the Python API is SI; pass "
        "np.radians(...), a Quantity or strings such as '20 deg'"
    )


def past_normal(th: float, deg: bool) -> str:
    """What a rod's angle ``th`` [rad] in (pi/2, pi) means (``deg``: said in degrees)."""
    m = math.pi - th
    mirror = f"{math.degrees(m):.6g} deg" if deg else f"{m:.6g} rad ({math.degrees(m):.6g} deg)"
    return (
        f": the rod leans past the flat's normal, the mirror of a drop at angle = {mirror} with "
        "vx (or incidence) and spin negated (x runs from the tip towards the centre of mass)"
    )


def check_constant_angle(constant_angle: Any, body: Rod | Sphere) -> bool:
    """``constant_angle`` (True or False); True for a Sphere is refused, as an angle given for
    it is (``check_angle``): a sphere has no angle to freeze."""
    frozen = check_flag("constant_angle", constant_angle)
    if frozen and isinstance(body, Sphere):
        raise ValueError(
            "constant_angle=True: a Sphere has no angle to freeze (its contact point always lies "
            "straight below its centre); leave constant_angle out"
        )
    return frozen


def _as_given(angle: Any) -> str:
    """An angle with a unit as the user wrote it: the string, or a Quantity's magnitude and
    unit (``95 deg``)."""
    if isinstance(angle, str):
        return angle.strip()
    return f"{float(angle.magnitude)!r} {angle.units:~}".replace(".0 ", " ", 1)


def check_velocity(velocity: Any) -> tuple[float, float]:
    """(vx, vy) [m/s] from a pair of finite numbers, strings with units or pint Quantities (or
    one pint Quantity holding the pair)."""
    given = velocity
    velocity = magnitude("velocity", velocity, "m/s")
    if isinstance(velocity, float | int | np.number) or (
        isinstance(velocity, np.ndarray) and velocity.ndim == 0
    ):  # one number, not a pair: say it as the user wrote it
        raise ValueError(
            f"velocity must be a pair (vx, vy) in m/s, got one number, {velocity_given(given)} "
            f"(a vertical drop: velocity=(0.0, {-abs(float(velocity)):g}))"
        )
    if isinstance(velocity, Mapping | set | frozenset):  # no order, or keys for values
        raise ValueError(
            f"velocity must be a pair (vx, vy) in m/s (a tuple or a list), got a "
            f"{type(velocity).__name__}: {velocity!r}"
        )
    try:
        vx, vy = velocity
    except (TypeError, ValueError):
        raise ValueError(f"velocity must be a pair (vx, vy) in m/s, got {velocity!r}") from None
    return tuple(  # type: ignore[return-value]
        check_speed(name, check_finite(name, v, "m/s"))
        for name, v in (("velocity[0] (vx)", vx), ("velocity[1] (vy)", vy))
    )


def velocity_from(velocity: Any, speed: Any, incidence: Any) -> Any:
    """``velocity`` (vx, vy), or the one that ``speed`` [m/s, > 0] and ``incidence`` [rad]
    give: vx = speed sin(incidence), vy = -speed cos(incidence). The incidence is the angle of
    the centre of mass's velocity to the flat's normal, in (-pi/2, pi/2): 0 is a normal drop,
    a positive incidence moves the body towards +x (vx > 0; for a rod, from the tip towards
    its centre of mass). Quantities as ``impactlab.units.magnitude`` (a bare incidence is
    radians, ``"30 deg"`` works). ValueError when both or neither are given."""
    if speed is None and incidence is None:
        if velocity is None:
            raise ValueError(
                "give the velocity of the centre of mass: velocity=(vx, vy) [m/s], or speed= "
                "[m/s] and incidence= (its angle to the flat's normal, e.g. '30 deg')"
            )
        return velocity
    if velocity is not None:
        raise ValueError(
            "give either velocity=(vx, vy) or speed= and incidence=, not both (they say the "
            "same thing)"
        )
    if speed is None or incidence is None:
        missing = "speed" if speed is None else "incidence"
        raise ValueError(f"speed and incidence go together: {missing} is missing")
    v = check_positive("speed", speed, "m/s")
    th = check_finite("incidence", incidence, "rad")
    if not incidence_allowed(th):
        hint = f" (a bare incidence is radians; for degrees write '{th:g} deg')"
        raise ValueError(
            f"incidence must lie in (-90, 90) deg from the flat's normal, got "
            f"{math.degrees(th):.6g} deg{'' if has_unit(incidence) else hint}"
        )
    return (v * math.sin(th), -v * math.cos(th))


#: How to build a body, for a class given where an instance is needed.
_BUILD = {
    "Rod": "Rod.paper() or Rod(length=..., tip_radius=..., mass=...)",
    "FlexibleRod": "FlexibleRod.paper() or FlexibleRod(length=..., tip_radius=..., mass=...)",
    "Sphere": "Sphere(radius=...)",
}


def given_body(body: Any) -> str:
    """What a wrong ``body`` is, for the error: "got None", "got str", or for a class "got the
    class Rod, not an instance (build one: Rod.paper() or ...)"."""
    if body is None:
        return "got None"
    if isinstance(body, type):
        build = _BUILD.get(body.__name__)
        hint = f" (build one: {build})" if build else ""
        return f"got the class {body.__name__}, not an instance{hint}"
    return f"got {type(body).__name__}"


def check_body(body: Any) -> Rod | Sphere:
    """``body`` if it is a Rod or a Sphere, else ValueError."""
    if not isinstance(body, Rod | Sphere):  # say what it is (a class: not an instance)
        raise ValueError(f"body must be an impactlab Rod or Sphere, {given_body(body)}")
    return body


def check_dent_grid(nx: Any, ny: Any, margin: Any) -> tuple[int, int, float]:
    """The grid of a dent map: ``nx`` and ``ny`` as integers >= 3 (Python or numpy integers;
    bools, floats and strings refused), ``margin`` a number >= 0 (relative padding);
    ValueError naming the parameter otherwise."""
    for name, n in (("nx", nx), ("ny", ny)):
        if isinstance(n, bool | np.bool_) or not isinstance(n, int | np.integer) or n < 3:
            raise ValueError(f"{name} must be an integer >= 3 (grid points), got {n!r}")
    return int(nx), int(ny), check_nonnegative("margin", margin)


def check_flat(flat: Any) -> Material:
    """The Material ``flat`` is or names (``bodies._checks.check_material``), else ValueError."""
    return flat if type(flat) is Material else check_material("flat", flat)


def warn_fast(what: str, speed: float) -> None:
    """An ImplausibleInputWarning when ``speed`` [m/s] exceeds :data:`PLAUSIBLE_SPEED`."""
    if speed > PLAUSIBLE_SPEED:
        warn_implausible(
            f"{what} ({speed:.6g} m/s) exceeds {PLAUSIBLE_SPEED:g} m/s, far beyond the rigid-"
            "body impacts impactlab models; check the units (SI: m/s, rad/s)"
        )


__all__ = [
    "DROP_RTOL_MAX", "MINDLIN_RTOL_MAX", "PARTIAL_SLIP_RTOL_MAX", "PAST_NORMAL", "PLAUSIBLE_SPEED",
    "batch_velocity", "check_angle", "check_body", "check_constant_angle", "check_dent_grid",
    "check_flat", "check_friction_rtol", "check_mu", "check_partial_slip_cells",
    "check_partial_slip_rtol", "check_rtol", "check_speed", "check_spin", "check_velocity",
    "contact_reach", "degrees_hint", "friction_rtol_max", "given_body", "gravity_value",
    "mu_problem", "past_normal", "velocity_from", "warn_degrees", "warn_fast",
]  # fmt: skip
