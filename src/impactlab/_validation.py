"""Input checks shared by the public constructors: clear errors that name the parameter."""

from __future__ import annotations

import math
from typing import Any

import numpy as np


def _describe(value: Any) -> str:
    return repr(value)


def check_finite(name: str, value: Any) -> float:
    """Return ``value`` as float; raise ValueError naming ``name`` unless it is a finite real."""
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be a real number, got {_describe(value)}") from None
    if not math.isfinite(x):
        raise ValueError(f"{name} must be finite, got {x!r}")
    return x


def check_positive(name: str, value: Any, unit: str = "") -> float:
    """Finite and > 0."""
    x = check_finite(name, value)
    if x <= 0.0:
        u = f" {unit}" if unit else ""
        raise ValueError(f"{name} must be > 0{u}, got {x!r}")
    return x


def check_nonnegative(name: str, value: Any, unit: str = "") -> float:
    """Finite and >= 0."""
    x = check_finite(name, value)
    if x < 0.0:
        u = f" {unit}" if unit else ""
        raise ValueError(f"{name} must be >= 0{u}, got {x!r}")
    return x


def check_range(
    name: str,
    value: Any,
    low: float,
    high: float,
    *,
    low_inclusive: bool = True,
    high_inclusive: bool = True,
) -> float:
    """Finite and inside the stated interval."""
    x = check_finite(name, value)
    lo_ok = x >= low if low_inclusive else x > low
    hi_ok = x <= high if high_inclusive else x < high
    if not (lo_ok and hi_ok):
        lb = "[" if low_inclusive else "("
        hb = "]" if high_inclusive else ")"
        raise ValueError(f"{name} must lie in {lb}{low}, {high}{hb}, got {x!r}")
    return x


def check_array_finite(name: str, values: Any) -> np.ndarray:
    """Return a float64 array; raise ValueError naming ``name`` if any entry is NaN or infinite."""
    arr = np.asarray(values, dtype=np.float64)
    bad = ~np.isfinite(arr)
    if bad.any():
        idx = int(np.flatnonzero(bad.ravel())[0])
        raise ValueError(f"{name} must be finite; entry {idx} is {arr.ravel()[idx]!r}")
    return arr
