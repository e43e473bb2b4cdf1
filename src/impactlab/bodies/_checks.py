"""Checks shared by the body constructors."""

from __future__ import annotations

from impactlab.materials import Material


def check_material(name: str, value: object) -> Material:
    """``value`` if it is a :class:`~impactlab.materials.Material`; ValueError naming ``name``."""
    if not isinstance(value, Material):
        raise ValueError(f"{name} must be an impactlab Material, got {type(value).__name__}")
    return value
