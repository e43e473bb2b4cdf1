"""Quantities with units at the edge (command line, study files): parsed once, SI inside."""

from __future__ import annotations

import math
from functools import lru_cache
from typing import Any

import pint


@lru_cache(maxsize=1)
def registry() -> pint.UnitRegistry:
    """The shared pint registry (kgf, HB-style units included by pint's defaults)."""
    return pint.UnitRegistry()


def to_si(value: Any, unit: str, *, name: str = "value") -> float:
    """Convert ``value`` (a number already in ``unit``, or a string such as ``"8.8 mm"``) to the SI
    magnitude of ``unit``'s dimension. ValueError naming ``name`` for unparsable input or wrong
    dimensions. Example: ``to_si("8.8 mm", "m") == 0.0088``."""
    ureg = registry()
    target = ureg.Unit(unit)
    if isinstance(value, int | float):
        q = float(value) * target
    else:
        text = str(value).strip()
        if not text:
            raise ValueError(f"{name} is empty; expected a quantity in {unit}, e.g. '1.0 {unit}'")
        try:
            q = ureg.Quantity(text)
        except Exception as exc:  # pint raises several unrelated types
            raise ValueError(f"{name}: cannot parse {text!r} as a quantity ({exc})") from None
        if q.unitless:
            q = float(q.magnitude) * target  # a bare number means "in the stated unit"
    try:
        si = q.to(target).to_base_units()
    except pint.DimensionalityError:
        raise ValueError(
            f"{name}: {value!r} has the wrong dimension; expected a quantity convertible to {unit}"
        ) from None
    x = float(si.magnitude)
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {value!r}")
    return x


def angle_to_rad(value: Any, *, name: str = "angle") -> float:
    """An angle (bare numbers are degrees) in radians."""
    return to_si(value, "degree", name=name)
