"""Input handling shared by the closed forms and the inversion: float arrays with named errors,
the rod's values, and the magnitudes the library takes where the paper prints negative values."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._input_limits import degrees_hint
from impactlab._validation import check_array_finite
from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.units import has_unit, is_quantity

HALF_PI = 0.5 * math.pi
_MEASURES = ("slip", "travel")
#: A |v_i| below this [m/s] is refused (by :func:`drop_speed`: ``invert`` and the closed forms
#: alike): a fall from under 1e-13 m (v^2/2g), less than an atom's size, is no measured drop;
#: Eq. 12's T grows as 1/|v_i|, and towards 0 T, F and their uncertainties under- or overflow.
MIN_SPEED = 1e-6


def arr(
    name: str,
    value: Any,
    *,
    unit: str = "",
    low: float | None = None,
    high: float | None = None,
    low_open: bool = False,
    high_open: bool = False,
) -> Any:
    """``value`` as a float64 array (0-d for scalars) under the input rule of
    ``impactlab._validation`` (with a ``unit``: numbers in that unit, strings with units, pint
    Quantities); ValueError naming ``name`` if it is not finite or lies outside [low, high]
    (open ends where asked)."""
    x = check_array_finite(name, value, unit)
    u = f" {unit}" if unit else ""  # the value as the rule reads it (an angle: radians)
    if low is not None:
        out = x <= low if low_open else x < low
        if out.any():
            op = ">" if low_open else ">="
            got = float(x.ravel()[np.argmax(out)])
            raise ValueError(f"{name} must be {op} {low:g}{u}, got {got!r}{u}")
    if high is not None:
        out = x >= high if high_open else x > high
        if out.any():
            op = "<" if high_open else "<="
            got = float(x.ravel()[np.argmax(out)])
            raise ValueError(f"{name} must be {op} {high:g}{u}, got {got!r}{u}")
    return x


def drop_speed(value: Any) -> Any:
    """The drop speed |v_i| [m/s] of ``v_i`` (sign ignored) as a float64 array; ValueError
    naming v_i, its value and the bound where a |v_i| is below ``MIN_SPEED`` (0 included)."""
    vi = np.abs(arr("v_i", value, unit="m/s"))
    slow = vi < MIN_SPEED
    if slow.any():
        got = float(vi.ravel()[np.argmax(slow.ravel())])
        allowed = f"allowed: |v_i| >= {MIN_SPEED:g} m/s (SI: m/s)"
        if got == 0.0:
            raise ValueError(f"v_i must be non-zero (the drop speed), got 0.0; {allowed}")
        raise ValueError(
            f"v_i = {got!r} m/s is below {MIN_SPEED:g} m/s in magnitude, a fall from under "
            "1e-13 m (less than an atom's size): no measured drop, and T (~ 1/|v_i|) and its "
            f"uncertainties overflow; {allowed}"
        )
    return vi


def finite(
    output: str, x: Any, unit: str, inputs: Mapping[str, tuple[Any, str]], allowed: str
) -> Any:
    """``x``, the ``output`` [``unit``] of a closed form (computed without numpy's warnings),
    where each entry is finite and > 0; else ValueError naming the ``inputs`` (name -> (array,
    unit)) at the first bad entry, the output that over- or underflows and what is
    ``allowed``: never an inf or a 0 returned."""
    x = np.asarray(x)
    bad = ~np.isfinite(x) | (x <= 0)
    if bad.any():
        i = int(np.argmax(bad.ravel()))
        given = ", ".join(
            f"{k} = {float(np.broadcast_to(v, x.shape).ravel()[i])!r}" + (f" {u}" if u else "")
            for k, (v, u) in inputs.items()
        )
        raise ValueError(
            f"{given} gives {output} = {float(x.ravel()[i])!r} {unit} (it over- or "
            f"underflows); allowed: {allowed}"
        )
    return x


def magnitude(name: str, value: Any, what: str) -> Any:
    """A non-negative length [m] as a float64 array; a negative value raises ValueError that names
    ``name`` and the convention (the paper's tables print these negative)."""
    x = arr(name, value, unit="m")
    if (x < 0).any():
        bad = float(x.ravel()[np.argmax(x < 0)])
        raise ValueError(
            f"{name} must be >= 0 ({what}, a magnitude in m), got {bad!r}: "
            "the paper's tables print it negative: give its magnitude"
        )
    return x


def out(x: Any) -> Any:
    """Return a Python float for 0-d results, the array otherwise."""
    x = np.asarray(x)
    return float(x) if x.ndim == 0 else x


def angle(value: Any) -> Any:
    """The angle [rad] as a float64 array, checked to lie in [0, pi/2]. An angle given with
    its unit (``"95 deg"``, a pint Quantity) out of range is echoed in degrees first, then in
    the radians a bare number would be; a bare number in (pi/2 + 10 deg, 90] gets the degrees
    hint of ``simulate``."""
    x = arr("angle", value, unit="rad")
    bad = (x < 0.0) | (x > HALF_PI)
    if bad.any():
        got = float(x.ravel()[np.argmax(bad.ravel())])
        op, deg, rad = (">=", 0, 0.0) if got < 0.0 else ("<=", 90, HALF_PI)
        if not has_unit(value):  # a bare number is radians; one that reads as degrees says so
            raise ValueError(f"angle must be {op} {rad:g} rad, got {got!r} rad{degrees_hint(got)}")
        raise ValueError(
            f"angle must be {op} {deg} deg, got {math.degrees(got):.6g} deg; in radians, as the "
            f"closed forms take a bare number: {op} {rad:g} rad, got {got!r} rad"
        )
    return x


def gravity_flag(value: Any) -> bool:
    """The closed forms' and ``invert``'s ``gravity``: True or False; ValueError otherwise (a
    number is not read as the acceleration, which is ``g``; a string is not silently true)."""
    if isinstance(value, bool | np.bool_):
        return bool(value)
    hint = f": the acceleration is g, e.g. gravity=True, g={value!r}" if _number(value) else ""
    raise ValueError(f"gravity must be True or False, got {value!r}{hint}")


def _number(value: Any) -> bool:
    """A number or a pint Quantity (what may have been meant as the acceleration)."""
    return isinstance(value, int | float | np.integer | np.floating) or is_quantity(value)


def travel(measure: str) -> bool:
    """True for ``measure="travel"`` (the contact patch), False for ``"slip"`` (the point O)."""
    if measure not in _MEASURES:
        raise ValueError(f"measure must be 'slip' or 'travel', got {measure!r}")
    return measure == "travel"


def rod_values(rod: Rod | None) -> tuple[Any, Any, Any, Any]:
    """(mass, length, tip_radius, inertia) of ``rod`` (default the paper's rod) as float arrays,
    validated; ValueError naming the attribute (``rod.mass`` ...) when one is missing or bad."""
    if rod is None:
        rod = PAPER_ROD
    if isinstance(rod, Sphere):  # it has a mass and a tip radius, but no rod's length
        raise ValueError(
            "rod: got a Sphere; invert and the closed forms need a Rod (they are a tilted "
            "rod's, its tip L/2 from the centre of mass): impactlab.Rod(length=..., "
            "tip_radius=..., mass=...), or None for the paper's rod"
        )
    try:
        raw = (rod.mass, rod.length, rod.tip_radius, getattr(rod, "inertia", None))
    except AttributeError as exc:
        raise ValueError(
            f"rod must be an impactlab.bodies.Rod (mass, length, tip_radius, inertia) ({exc})"
        ) from None
    m = arr("rod.mass", raw[0], unit="kg", low=0.0, low_open=True)
    L = arr("rod.length", raw[1], unit="m", low=0.0, low_open=True)
    R = arr("rod.tip_radius", raw[2], unit="m", low=0.0, low_open=True)
    inertia = (
        m * L * L / 12.0
        if raw[3] is None
        else arr("rod.inertia", raw[3], unit="kg m^2", low=0.0, low_open=True)
    )
    return m, L, R, inertia
