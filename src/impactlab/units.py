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
import numbers
import re
import unicodedata
from functools import lru_cache
from typing import TYPE_CHECKING, Any

import numpy as np

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


#: A leading number (sign, digits, decimal point, exponent) and what follows it.
_LEADING_NUMBER = re.compile(r"\s*[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?(.*)")
#: A number not glued to a name or to another number (the 2 of ``m2`` is none); the same with
#: its exponent (``1.41e-3``): the first number of a text (``"(2*3) m"``).
_NUMBER = re.compile(r"(?<![\w.])(?:\d+\.?\d*|\.\d+)")
_FIRST_NUMBER = re.compile(r"(?<![\w.])(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?")
#: What precedes the exponent of a unit (``m^2``, ``s**-1``): a unit or a bracket, ``^`` or ``**``,
#: a sign; right after the leading number it makes a power of that number (``2**2 m``).
_POWER = re.compile(r"\S\s*(?:\^|\*\*)\s*[+-]?\s*$")
#: Minus signs besides '-' and Unicode's dashes (Pd), which pint drops without a word
#: (``"\u22120.3 m/s"`` would be +0.3 m/s): minus, modifier, commercial, heavy; soft hyphen.
_MINUS_SIGNS = "\u2212\u02d7\u2052\u2796\u00ad"
_DIGIT_AHEAD = re.compile(r"\.?[0-9]")  # what makes a dash a minus sign: a number after it
_TIMES = "\u00b7\u00d7\u22c5\u2219"  # multiplication signs (pint drops most): written ``*``
_ASCII = ".+-*/^()_%,"  # the ASCII text holds besides letters, digits, spaces (a comma: refused)
_SYMBOLS = "°‰⁰¹²³⁴⁵⁶⁷⁸⁹⁻"  # others pint reads: degree, per mille, superscript digits, minus
#: The 1 of a reciprocal unit (``1/s``, ``(1/s)``): a unit, not a second number (``1/2`` is one).
_RECIPROCAL = re.compile(r"(^|[\s(])1\s*/(?=\s*[A-Za-z(])")


def _angle_power(items: Any) -> float:
    """The summed power of the dimensionless units (angles, percent; not pi) among ``items``
    ((unit name, exponent) pairs)."""
    reg = registry()
    return sum(e for u, e in items if u != "pi" and reg.Unit(u).dimensionless)


def _one_number(name: str, text: str, shown: str, unit: str) -> None:
    """ValueError naming ``name`` unless ``text`` (the user's ``shown``) holds one number: pint
    computes with numbers side by side or joined by arithmetic, so ``"20 deg 3"`` would be
    60 deg, ``"1.41 m/s 2"`` and ``"2*1.41 m/s"`` 2.82 m/s, ``"1.41/2 m/s"`` 0.705 m/s and
    ``"2**2 m"`` 4 m. The 1 of a reciprocal unit (``"6500 1/s"``) and the exponent of a unit
    (``m^2``, ``s**-1``) are no second number."""
    lead = _LEADING_NUMBER.fullmatch(text)
    if lead is not None:
        rest = lead.group(1)
    else:  # "(2*3) m", "- 0.3 m/s": the first number, wherever it stands
        first = _FIRST_NUMBER.search(text)
        rest = text if first is None else f"{text[: first.start()]} {text[first.end() :]}"
    rest = _RECIPROCAL.sub(r"\1/", rest)  # "6500 1/s" holds one number
    if _plain(unit) and rest.strip() == "1":  # "0.02 1": a pure number in the unit 1
        rest = ""
    if any(not _POWER.search(rest[: m.start()]) for m in _NUMBER.finditer(rest)):
        raise ValueError(
            f"{name}: {shown!r} holds more than one number (pint would compute with them); "
            f"{_write_one(unit)}"
        )


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
                if _plain(unit)
                else f"write one number and one unit of {unit}, e.g. '1.0 {unit}'"
            )
        )


def _is_dash(c: str) -> bool:
    """True for a dash or minus sign other than ``-`` (:data:`_MINUS_SIGNS`, Unicode's Pd)."""
    return c != "-" and (c in _MINUS_SIGNS or unicodedata.category(c) == "Pd")


def read_minus(text: str) -> str:
    """``text`` with each dash or minus sign right before a number written ``-`` (``"\u22124"``
    -> ``"-4"``, ``"1.41e\u20133 m/s"`` -> ``"1.41e-3 m/s"``); the rest unchanged."""
    return "".join(
        "-" if _is_dash(c) and _DIGIT_AHEAD.match(text, i + 1) else c for i, c in enumerate(text)
    )


def bare_number(value: Any) -> float | None:
    """The number of ``value`` when it states no unit: a real number (not a bool), or text that
    is only a number (as ``float`` reads it, any dash being ``-``: ``"\u22124"`` -> -4.0); None
    for anything else (``"4 m/s"``, ``"fast"``)."""
    if isinstance(value, bool) or not isinstance(value, numbers.Real | str):
        return None
    text = "".join("-" if _is_dash(c) else c for c in value) if isinstance(value, str) else value
    try:
        return float(text)
    except ValueError:
        return None


def bare_text(value: Any) -> Any:
    """``value`` with ``-`` for its minus sign when it is text that is only a number
    (``"\u22124"`` -> ``"-4"``, :func:`bare_number`); any other value unchanged."""
    number = bare_number(value) if isinstance(value, str) else None
    return value if number is None else "".join("-" if _is_dash(c) else c for c in value)


def _minus_signs(name: str, text: str, unit: str) -> str:
    """``text`` with its minus signs read (:func:`read_minus`), spaces ``" "``, multiplication
    signs ``*``; ValueError naming ``name`` for a dash elsewhere (``"0.3 \u2013 m/s"``)."""
    out = read_minus(text)
    bad = next((c for c in out if _is_dash(c)), None)
    if bad is not None:
        example = "-0.4" if _plain(unit) else f"-1.0 {unit}"
        raise ValueError(
            f"{name}: {text!r} holds a dash (U+{ord(bad):04X}) that is not a minus sign right "
            f"before a number; write a negative value with '-', e.g. '{example}'"
        )
    return "".join(" " if c.isspace() else "*" if c in _TIMES else c for c in out)


def _characters(name: str, text: str, shown: str, unit: str) -> None:
    """ValueError naming ``name`` for a character of ``text`` (the user's ``shown``) that pint
    would drop or misread (``"0.3 m # note"``, a zero-width space): text holds letters (``µm``,
    ``Å``), ASCII digits, spaces, :data:`_ASCII` and :data:`_SYMBOLS` (``°``, ``s⁻¹``)."""
    for c in text:
        if c.isascii() and (c.isalnum() or c == " " or c in _ASCII):
            continue
        nfkc = unicodedata.normalize("NFKC", c)
        letter = c.isalpha() and nfkc.isalpha() and f"a{c}".isidentifier()
        if not c.isascii() and (letter or c in _SYMBOLS):  # not a mark pint drops: U+0E33
            continue
        what = f"U+{ord(c):04X} {unicodedata.name(c, '')}".rstrip()
        raise ValueError(
            f"{name}: {shown!r} holds {c!r} ({what}), which quantity text cannot hold (pint "
            f"would drop or misread it); {_write_one(unit)}"
        )


def _written(name: str, text: str, shown: str, q: Any, unit: str) -> None:
    """ValueError naming ``name`` unless pint read the number written in ``text`` (the user's
    ``shown``; its reciprocal after a slash, ``"pi/4 rad"``): a power computes another
    (``"(2)^2 m"`` is 4 m, ``"10\u207b\u00b3 m"`` 0.001 m)."""
    first = _FIRST_NUMBER.search(text)
    m, x = abs(float(q.magnitude)), float(first.group()) if first else 1.0
    over = first is not None and text[: first.start()].rstrip().endswith("/")  # pi/4: 1/4
    if first and not math.isclose(m, 1.0 / x if over and x else x, rel_tol=1e-12):
        raise ValueError(
            f"{name}: {shown!r} holds more than one number (pint would compute with them: "
            f"{q:~}); {_write_one(unit)}"
        )


def _plain(unit: str) -> bool:
    """True for the unit of a pure number (``"1"`` or empty)."""
    return unit.strip() in ("", "1")


def _write_one(unit: str) -> str:
    """The hint of a refused quantity text: one number with ``unit`` (a plain one for a pure
    number: ``'1.0 1'`` would itself be refused)."""
    if _plain(unit):
        return "write one plain number, e.g. '0.4'"
    return f"write one number and its unit, e.g. '1.0 {unit}'"


def refuse_comma(name: str, text: str, unit: str) -> None:
    """ValueError naming ``name`` when the quantity text ``text`` holds a comma: pint drops it
    as a thousands separator, so a decimal comma ``"2,5 mm"`` would read as 25 mm."""
    if "," in text:
        if text.strip()[:1] in "([":  # a pair written as one string: its values one by one
            raise ValueError(
                f"{name}: {text!r} is one string; give each component as its own quantity, "
                f"e.g. ('0 {unit}', '-1.41 {unit}')"
            )
        example = text.strip().replace(",", ".") if text.count(",") == 1 else f"2.5 {unit}"
        raise ValueError(
            f"{name}: {text!r} holds a comma; write one quantity with a decimal point, e.g. "
            f"'{example}' (a comma would be read as a thousands separator: '2,5' as 25)"
        )


def _parse(name: str, text: str, unit: str) -> Any:
    """``text`` as a Quantity of impactlab's registry (its minus signs read, :func:`_minus_signs`;
    one number, :func:`_one_number`; angle units as in ``unit``, :func:`_angle_units`; no
    comma, no temperature); ValueError naming ``name``."""
    shown = text.strip()
    if not shown:
        raise ValueError(f"{name} is empty; {_write_one(unit)}")
    text = _minus_signs(name, shown, unit)
    refuse_comma(name, text, unit)
    _characters(name, text, shown, unit)
    _one_number(name, text, shown, unit)
    try:
        q: Any = registry().Quantity(text)
    except Exception as exc:  # pint's parser raises several unrelated types
        if type(exc).__name__ == "OffsetUnitCalculusError":  # "20 degC": a temperature
            raise ValueError(
                f"{name}: {shown!r} is a temperature (an offset unit such as degC or degF); "
                f"expected a quantity in {unit}, e.g. '20 deg' for an angle"
            ) from None
        raise ValueError(f"{name}: cannot parse {shown!r} as a quantity ({exc})") from None
    _written(name, text, shown, q, unit)
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
        q = _parse(name, value, unit)
        _check_finite(name, q, value)
        if q.unitless and _plain(unit):  # a pure number asked for: "0.4"
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
    if is_quantity(value):
        m = _convert(name, _foreign(name, value), unit, value).magnitude
        return float(m) if np.ndim(m) == 0 else np.asarray(m, dtype=np.float64)
    return value


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
            if not _plain(unit) and bare_number(str(value)) is None:
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
    if q is None or q.unitless:
        raise ValueError(
            f"{name} {str(value).strip()} has no unit: give a unit, e.g. '20 deg' or '0.35 rad'"
        )
    if dict(q.to_base_units().unit_items()) != {"radian": 1}:  # pint: sr, count are numbers
        raise ValueError(
            f"{name}: {str(value).strip()!r} is not an angle (its unit is {q.units:~}); give "
            f"deg, rad, turn or arcmin, e.g. '20 deg'"
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
