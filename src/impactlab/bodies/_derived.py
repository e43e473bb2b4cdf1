"""A body's field that the body computed, not the user: ``dataclasses.replace`` passes every
field to the new body, and a computed one (a rod's m L^2/12, a sphere's density from its mass)
would be taken as given and outlive the change it follows from (a rod made twice as long kept
the inertia of the short one). Marked, it is computed again from the new fields."""

from __future__ import annotations

import math
import warnings
from typing import Any

__all__ = ["DerivedFloat", "DerivedInt", "given", "note_recomputed"]


class DerivedFloat(float):
    """A float a body computed from its other fields (a plain float everywhere else)."""

    __slots__ = ()


class DerivedInt(int):
    """An integer a body computed from its other fields (a flexible rod's mode counts)."""

    __slots__ = ()


def given(value: Any) -> bool:
    """Whether a field's ``value`` was given: not None and not computed by a body."""
    return value is not None and not isinstance(value, DerivedFloat | DerivedInt)


def note_recomputed(name: str, passed: Any, now: float) -> None:
    """A warning when ``passed`` (a field's value as passed in) is a value another body computed
    (``dataclasses.replace``, or a field copied from another body) and this body computes
    another, ``now``: the value passed is not the one used, and the user is told which is."""
    if isinstance(passed, DerivedFloat | DerivedInt) and not math.isclose(
        float(passed), float(now), rel_tol=1e-12, abs_tol=0.0
    ):
        warnings.warn(
            f"{name}: {float(passed):.6g} was computed by another body (dataclasses.replace, "
            f"or a field copied from one), so this body computes its own, {float(now):.6g}; "
            f"give {name} as a plain number to keep a value",
            UserWarning,
            stacklevel=5,
        )
