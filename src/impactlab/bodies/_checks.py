"""Checks shared by the body constructors: materials, quantities and the plausibility bounds.

Bounds (SI). Refused, because impossible: a length, tip radius, radius, mass, inertia or
density that is not a finite number > 0, and a rod whose tip radius exceeds half its length.
Warned with :class:`~impactlab._validation.ImplausibleInputWarning`, because most likely a unit
mistake: a length outside :data:`PLAUSIBLE_LENGTH`, a tip radius or sphere radius outside
:data:`PLAUSIBLE_RADIUS`, a mass outside :data:`PLAUSIBLE_MASS`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

from impactlab._validation import warn_implausible
from impactlab.materials import Material, get_material

#: Plausible rod length [m]: 1 mm to 10 m.
PLAUSIBLE_LENGTH = (1e-3, 10.0)
#: Plausible tip (sphere) radius [m]: 1 um to 0.5 m.
PLAUSIBLE_RADIUS = (1e-6, 0.5)
#: Plausible mass [kg]: 1 mg to 1 t.
PLAUSIBLE_MASS = (1e-6, 1e3)


def check_tip_width(tip_radius: float, diameter: float | None, what: str = "diameter") -> None:
    """ValueError when a rod's ``diameter`` [m] exceeds twice its ``tip_radius`` [m] (to 1e-9):
    the end face would then stand out beside the hemispherical tip, and at angles to the flat
    below arccos(2R/d) its rim, not the tip, would strike first. ``what`` names the diameter
    in the message (one the mass implies, say)."""
    if diameter is not None and diameter > 2.0 * tip_radius * (1.0 + 1e-9):
        rim = math.degrees(math.acos(2.0 * tip_radius / diameter))
        raise ValueError(
            f"{what} ({diameter!r} m) exceeds twice the tip radius ({2.0 * tip_radius!r} m): "
            "the rod's end face would stand out beside its hemispherical tip, and below "
            f"{rim:.3g} deg to the flat its rim would strike before the tip (allowed: "
            "diameter <= 2 tip_radius; the tip as wide as the rod or wider)"
        )


#: Largest relative difference between the density that mass, diameter and length imply
#: (m / (pi d^2 / 4 L)) and the material's density when both mass and diameter are given.
DENSITY_TOLERANCE = 0.02


def rod_mass(L: float, m: float | None, d: float | None, material: Material) -> float:
    """The mass [kg] of a uniform rod of circular section: ``m`` as given, or (None) from the
    diameter ``d``, the length ``L`` between the end-sphere centres and the material's density,
    rho pi d^2 / 4 L. ValueError when neither is given, or when both are and the density they
    imply differs from the material's by more than :data:`DENSITY_TOLERANCE`."""
    rho = material.density
    if m is None and d is None:
        raise ValueError("give the mass [kg] or the diameter [m] of the rod (or both)")
    if m is None:
        return rho * math.pi * d * d / 4.0 * L  # type: ignore[operator]
    if d is not None:
        implied = m / (math.pi * d * d / 4.0 * L)
        if not abs(implied / rho - 1.0) <= DENSITY_TOLERANCE:
            raise ValueError(
                f"mass ({m!r} kg), diameter ({d!r} m) and length ({L!r} m) imply a density of "
                f"{implied:.4g} kg/m^3, but the material {material.name!r} has {rho:.4g} kg/m^3 "
                f"(allowed: within {DENSITY_TOLERANCE:.0%}); give the mass or the diameter, not "
                "both, or the material they belong to"
            )
    return m


def check_material(name: str, value: object) -> Material:
    """The :class:`~impactlab.materials.Material` ``value`` is or names: a Material, a library
    name, a definition by values (text or mapping) or a TOML file
    (:func:`~impactlab.materials.get_material`); ValueError naming ``name`` otherwise."""
    if isinstance(value, Material):
        return value
    if isinstance(value, str | Mapping | Path):
        return get_material(value, name)
    raise ValueError(
        f"{name} must be an impactlab Material, a library name (impactlab materials) or a "
        f"material by values ('E=..., nu=..., Sy=..., rho=...'), got {type(value).__name__}"
    )


def plausible(name: str, value: float, bounds: tuple[float, float], unit: str) -> float:
    """``value``; an ImplausibleInputWarning when it lies outside ``bounds``."""
    lo, hi = bounds
    if not lo <= value <= hi:
        warn_implausible(
            f"{name} = {value!r} {unit} lies outside the plausible range [{lo:g}, {hi:g}] {unit}"
            f"; check the units (impactlab takes SI: a bare number is in {unit})"
        )
    return value
