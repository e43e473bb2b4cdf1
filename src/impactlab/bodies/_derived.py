"""A body's field that the body computed, not the user: ``dataclasses.replace`` passes every
field to the new body, and a computed one (a rod's m L^2/12, a sphere's density from its mass)
would be taken as given and outlive the change it follows from (a rod made twice as long kept
the inertia of the short one). Marked, it is computed again from the new fields."""

from __future__ import annotations

from typing import Any

__all__ = ["DerivedFloat", "DerivedInt", "given"]


class DerivedFloat(float):
    """A float a body computed from its other fields (a plain float everywhere else)."""

    __slots__ = ()


class DerivedInt(int):
    """An integer a body computed from its other fields (a flexible rod's mode counts)."""

    __slots__ = ()


def given(value: Any) -> bool:
    """Whether a field's ``value`` was given: not None and not computed by a body."""
    return value is not None and not isinstance(value, DerivedFloat | DerivedInt)
