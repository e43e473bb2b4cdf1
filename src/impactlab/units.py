"""Quantities with units: parsed once, SI inside.

Two rules, one parser:

- :func:`magnitude` is the Python API's rule for a dimensional input (a length, a speed, an
  angle, a pressure): a string **with** units (``"8.8 mm"``, ``"20 deg"``, ``"1.41 m/s"``) or a
  pint Quantity from **any** registry becomes its magnitude in the unit asked for (dimension
  checked); a bare number is taken as already in that unit (SI: m, m/s, rad, Pa, ...) and is
  checked as a number by ``impactlab._validation``; a bare number *string* (``"0.0088"``) is
  refused, since it names no unit.
- :func:`to_si` is the edge's rule (command line, study files): there a bare number, written or
  not, means "in the stated unit" -- except an angle (:func:`angle_to_rad`), which text must
  give with its unit (the angle rule, docs/glossary.md).

The Python API applies :func:`magnitude` through ``impactlab._validation`` (``check_positive``
and its siblings: the rule for numbers, never a bool or a string, and the range checks).
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

from impactlab._quantity_text import (
    bare_number,
    bare_text,
    characters,
    minus_signs,
    one_number,
    plain,
    read_minus,
    refuse_comma,
    write_one,
    written,
)

if TYPE_CHECKING:
    import pint


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The shared pint registry (kgf, HB-style units included by pint's defaults). pint is
    imported here, on first use: ``import impactlab`` does not pay its 0.2-0.3 s."""
    import pint

    return pint.UnitRegistry()


def is_quantity(value: Any) -> bool:
    """True for a pint Quantity of any registry (duck-typed: magnitude, units, dimensionality)."""
    return all(hasattr(value, a) for a in ("magnitude", "units", "dimensionality"))


def has_unit(value: Any) -> bool:
    """True for a value that states its unit: a string (text must carry one) or a pint Quantity
    with a unit. A dimensionless Quantity (``Q_(0.35, "")``) is a number, as a bare float: an
    angle given so is radians (the angle rule, docs/glossary.md), and an echo of it says so."""
    if isinstance(value, str):
        return True
    return is_quantity(value) and not getattr(value, "unitless", False)


def _angle_power(items: Any) -> float:
    """The summed power of the dimensionless units (angles, percent; not pi) among ``items``
    ((unit name, exponent) pairs)."""
    reg = registry()
    return sum(e for u, e in items if u != "pi" and reg.Unit(u).dimensionless)


def _angle_units(name: str, shown: str, q: Any, unit: str) -> None:
    """ValueError naming ``name`` when the Quantity ``q`` (of the text ``shown``) has angle units
    (dimensionless in pint) to another power than that of ``unit`` or 0 (1 for rad, deg and
    rad/s, where rpm has none; 0 for a length or a speed): ``"20 deg deg"`` (deg^2,
    dimensionless as deg is) would be 0.35 deg."""
    power = _angle_power(q.unit_items())
    if power not in (0, _angle_power(registry().Unit(unit)._units.items())):
        raise ValueError(
            f"{name}: {shown!r} has dimensionless units (angles such as deg, or percent) to the "
            f"power {power:g}; "
            + (
                "write one plain number, e.g. '0.4' (a fraction, not a percentage)"
                if plain(unit)
                else f"write one number and one unit of {unit}, e.g. '1.0 {unit}'"
            )
        )


def _parse(name: str, text: str, unit: str) -> Any:
    """``text`` as a Quantity of impactlab's registry (its minus signs read, :func:`minus_signs`;
    one number, :func:`one_number`; angle units as in ``unit``, :func:`_angle_units`; no
    comma, no temperature); ValueError naming ``name``."""
    shown = text.strip()
    if not shown:
        raise ValueError(f"{name} is empty; {write_one(unit)}")
    text = minus_signs(name, shown, unit)
    refuse_comma(name, text, unit)
    characters(name, text, shown, unit)
    one_number(name, text, shown, unit)
    try:
        q: Any = registry().Quantity(text)
    except Exception as exc:  # pint's parser raises several unrelated types
        if type(exc).__name__ == "OffsetUnitCalculusError":  # "20 degC": a temperature
            raise ValueError(
                f"{name}: {shown!r} is a temperature (an offset unit such as degC or degF); "
                f"expected a quantity in {unit}, e.g. '20 deg' for an angle"
            ) from None
        raise ValueError(f"{name}: cannot parse {shown!r} as a quantity ({exc})") from None
    written(name, text, shown, q, unit)
    _angle_units(name, shown, q, unit)
    return q


def _convert(name: str, q: Any, unit: str, shown: Any) -> Any:
    """``q`` expressed in ``unit``; ValueError naming ``name`` on a wrong dimension, and on a
    frequency in hertz asked for as an angular velocity (pint converts 1 Hz to 1 rad/s, but a
    spin of 5 Hz usually means 5 turns per second)."""
    import pint  # loaded already: ``q`` is a Quantity of the registry

    if unit == "rad/s" and "hertz" in str(q.units):
        raise ValueError(
            f"{name}: {shown!r} is a frequency in hertz, ambiguous as an angular velocity "
            "(cycles or radians per second); give rad/s, or turns as 'turn/s' or 'rpm'"
        )
    try:
        out = q.to(unit)
    except pint.DimensionalityError:
        raise ValueError(
            f"{name}: {shown!r} has the wrong dimension; expected a quantity convertible to {unit}"
        ) from None
    # pint converts any dimensionless unit into another: a solid angle (sr = rad^2) or a count
    # would pass for an angle. A pure number stays one (radians, the angle rule); otherwise the
    # powers of the radian must agree.
    base = dict(q.to_base_units().unit_items())
    want = dict(registry().Quantity(1.0, unit).to_base_units().unit_items())
    if base and (base.get("radian", 0) != want.get("radian", 0) or "count" in base):
        raise ValueError(f"{name}: {shown!r} is not a quantity of {unit} (its unit is {q.units:~})")
    return out


def _foreign(name: str, q: Any) -> Any:
    """A Quantity of any registry as one of impactlab's (via its magnitude and unit string)."""
    try:
        return registry().Quantity(q.magnitude, str(q.units))
    except Exception as exc:  # an unknown unit name: pint raises several types
        raise ValueError(f"{name}: cannot read the unit of {q!r} ({exc})") from None


def _check_finite(name: str, q: Any, shown: Any) -> None:
    """ValueError naming ``name`` when the number or Quantity ``q`` (of ``shown``) is not finite."""
    m = getattr(q, "magnitude", q)
    if np.ndim(m) == 0 and not math.isfinite(float(m)):
        raise ValueError(f"{name} must be finite, got {shown!r}")


def magnitude(name: str, value: Any, unit: str) -> Any:
    """The magnitude of ``value`` in ``unit`` under the Python API's rule (module docstring).

    - ``str``: parsed; it must carry units of ``unit``'s dimension (``"8.8 mm"`` -> 0.0088 for
      ``unit="m"``); a bare number string is refused with a hint;
    - a pint Quantity of any registry (scalar or array): converted (dimension checked);
    - anything else is returned unchanged (a number is taken as already in ``unit``).

    ValueError naming ``name`` for unparsable text, a missing unit or a wrong dimension.
    Examples: ``magnitude("angle", "20 deg", "rad") == math.radians(20)``,
    ``magnitude("mass", 0.46, "kg") == 0.46``.
    """
    if isinstance(value, str):
        hit = _TEXT_VALUES.get((value, unit))
        if hit is not None:
            return hit
        x = _text_magnitude(name, value, unit)
        if len(_TEXT_VALUES) >= _TEXT_KEPT:
            _TEXT_VALUES.clear()
        _TEXT_VALUES[(value, unit)] = x
        return x
    if is_quantity(value):
        m = _convert(name, _foreign(name, value), unit, value).magnitude
        return float(m) if np.ndim(m) == 0 else np.asarray(m, dtype=np.float64)
    return value


#: (text, unit) -> the magnitude that :func:`magnitude` read from it: pint's parse costs
#: about 0.1 ms, most of a ``simulate`` call given an angle as text. Only texts that passed
#: are kept (a refusal names its parameter, and is raised anew).
_TEXT_VALUES: dict[tuple[str, str], float] = {}
_TEXT_KEPT = 512


def _text_magnitude(name: str, value: str, unit: str) -> float:
    """:func:`magnitude` of the text ``value``, parsed."""
    q = _parse(name, value, unit)
    _check_finite(name, q, value)
    if q.unitless and plain(unit):  # a pure number asked for: "0.4"
        return float(q.magnitude)
    if q.unitless:
        bare = bare_number(value) is not None
        shown = "deg" if unit == "rad" else unit  # an angle is written in degrees
        example = f"{bare_text(value).strip()} {shown}" if bare else f"1.0 {shown}"
        what = "has no unit" if bare else f"is a pure number ({q:~})"
        raise ValueError(
            f"{name}: the string {value!r} {what}; pass a number in {unit} or a string "
            f"with units, e.g. '{example}'"
        )
    return float(_convert(name, q, unit, value).magnitude)


def to_si(value: Any, unit: str, *, name: str = "value") -> float:
    """Convert ``value`` (a number already in ``unit``, or a string such as ``"8.8 mm"``) to the SI
    magnitude of ``unit``'s dimension. ValueError naming ``name`` for unparsable input or wrong
    dimensions. Example: ``to_si("8.8 mm", "m") == 0.0088``."""
    target = registry().Unit(unit)
    if isinstance(value, int | float):
        q = float(value) * target
    else:
        q = _parse(name, str(value), unit)
        _check_finite(name, q, value)
        if q.unitless:
            if not plain(unit) and bare_number(str(value)) is None:
                raise ValueError(
                    f"{name}: {value!r} is a pure number ({q:~}); give a number in {unit} or "
                    f"one with its unit, e.g. '1.0 {unit}'"
                )
            q = float(q.magnitude) * target  # a bare number means "in the stated unit"
    x = float(_convert(name, q, unit, value).to_base_units().magnitude)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def parse_quantity(name: str, text: str, unit: str) -> Any:
    """``text`` as a Quantity of impactlab's registry under the rules every text input follows
    (one number and one unit, no comma, no temperature, angle units to the power of ``unit``'s);
    ValueError naming ``name``. The number is not converted: :func:`convert_quantity`."""
    return _parse(name, text, unit)


def convert_quantity(name: str, q: Any, unit: str, shown: Any) -> Any:
    """The Quantity ``q`` (of impactlab's registry) expressed in ``unit``; ValueError naming
    ``name`` and the text ``shown`` on a wrong dimension, on hertz asked for as an angular
    velocity, and on powers of the radian that differ from ``unit``'s."""
    return _convert(name, q, unit, shown)


def angle_to_rad(value: Any, *, name: str = "angle") -> float:
    """An angle written as text with its unit (``"20 deg"``, ``"0.35 rad"``) in radians. A bare
    number, written or not, is refused: it could be degrees or radians (the angle rule of
    docs/glossary.md; the Python API's bare numbers are radians, ``magnitude``)."""
    q = None if isinstance(value, int | float) else _parse(name, str(value), "deg")
    _check_finite(name, value if q is None else q, value)
    if q is None or not dict(q.unit_items()):  # "20 %" has a unit, a ratio's: not an angle
        raise ValueError(
            f"{name} {str(value).strip()} has no unit: give a unit, e.g. '20 deg' or '0.35 rad'"
        )
    base = dict(q.to_base_units().unit_items())
    if base != {"radian": 1}:  # pint: sr, count are numbers
        ratio = ", a ratio's, not an angle's" if not base else ""  # %, ppm
        raise ValueError(
            f"{name}: {str(value).strip()!r} is not an angle (its unit is {q.units:~}{ratio}); "
            "give deg, rad, turn or arcmin, e.g. '20 deg'"
        )
    return to_si(value, "degree", name=name)


__all__ = [
    "angle_to_rad",
    "bare_number",
    "bare_text",
    "convert_quantity",
    "has_unit",
    "is_quantity",
    "magnitude",
    "parse_quantity",
    "read_minus",
    "refuse_comma",
    "registry",
    "to_si",
]
