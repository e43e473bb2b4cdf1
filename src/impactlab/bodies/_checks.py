"""Checks shared by the body constructors: materials, quantities and the plausibility bounds.

Bounds (SI). Refused, because impossible: a length, tip radius, radius, mass, inertia or
density that is not a finite number > 0, a rod whose tip radius exceeds half its length, and a
size or mass outside the allowed ranges (:data:`SIZE_RANGE`, :data:`MASS_RANGE`,
:data:`INERTIA_RANGE`: given, or derived from the others, as a sphere's mass from its radius).
Warned with :class:`~impactlab._validation.ImplausibleInputWarning`, because most likely a unit
mistake: a length outside :data:`PLAUSIBLE_LENGTH`, a tip radius or sphere radius outside
:data:`PLAUSIBLE_RADIUS`, a mass outside :data:`PLAUSIBLE_MASS`, a rigid rod's mass over
:data:`HEAVY_ROD_FACTOR` times that of a uniform rod as wide as its tip, and a sphere's mass
over :data:`DENSE_SPHERE_FACTOR` times that of a solid sphere of its material.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

from impactlab._validation import check_positive, warn_implausible
from impactlab.materials import Material, get_material

#: Plausible rod length [m]: 1 mm to 10 m.
PLAUSIBLE_LENGTH = (1e-3, 10.0)
#: Plausible tip (sphere) radius [m]: 1 um to 0.5 m.
PLAUSIBLE_RADIUS = (1e-6, 0.5)
#: Plausible mass [kg]: 1 mg to 1 t.
PLAUSIBLE_MASS = (1e-6, 1e3)
#: Allowed size [m] of a body, refused outside: a length, tip radius, sphere radius or
#: diameter, given or derived (a rod's diameter from its mass), from 1 nm (a few atoms: no
#: continuum contact) to 10 km (a thousand times the longest plausible rod). Within it the
#: derived quantities stay normal floats (a sphere's R^3, Hertz's force at first yield, the
#: frequencies of a flexible rod's modes); far outside it they under- or overflow. Every
#: plausible value, and each one a thousand times off (mm given as m, or m as mm), lies inside.
SIZE_RANGE = (1e-9, 1e4)
#: Allowed mass [kg], refused outside: from 1e-24 kg (about ten atoms; a 1 nm steel sphere is
#: 3e-23 kg) to 1e12 kg (a steel sphere of 300 m radius), for the same reasons.
MASS_RANGE = (1e-24, 1e12)
#: Allowed moment of inertia [kg m^2], refused outside: the least and the most mass at the
#: least and the most size, MASS_RANGE x SIZE_RANGE^2, the lower end a hundred times lower to
#: hold m L^2 / 12 and 2/5 m R^2 of the smallest bodies.
INERTIA_RANGE = (1e-2 * MASS_RANGE[0] * SIZE_RANGE[0] ** 2, MASS_RANGE[1] * SIZE_RANGE[1] ** 2)


def checked_size(name: str, value: object) -> float:
    """``value`` [m] as a finite number > 0 within :data:`SIZE_RANGE`; ValueError naming
    ``name`` otherwise."""
    return check_allowed(name, check_positive(name, value, "m"), SIZE_RANGE, "m")


def checked_mass(name: str, value: object) -> float:
    """``value`` [kg] as a finite number > 0 within :data:`MASS_RANGE`; ValueError naming
    ``name`` otherwise."""
    return check_allowed(name, check_positive(name, value, "kg"), MASS_RANGE, "kg")


def check_allowed(
    name: str, value: float, bounds: tuple[float, float], unit: str, derived: str = ""
) -> float:
    """``value`` [``unit``], a finite number > 0 already; ValueError naming ``name`` (and
    ``derived``, how it follows from the given values) when it lies outside ``bounds`` (by more
    than the round-off of a unit conversion, 1e-9 relative: 1 um / 1000 is 1 nm)."""
    lo, hi = bounds
    if lo * (1.0 - 1e-9) <= value <= hi * (1.0 + 1e-9):
        return value
    how = f" ({derived})" if derived else ""
    raise ValueError(
        f"{name} = {value!r} {unit}{how} lies outside the allowed range [{lo:g}, {hi:g}] {unit}"
        f" (far {'below' if value < lo else 'above'} any body impactlab models; beyond it the "
        "derived quantities, a sphere's R^3 or the contact force, under- or overflow); check "
        f"the value and its unit (SI: {unit})"
    )


def tip_width_problem(
    tip_radius: float, diameter: float | None, what: str = "diameter"
) -> str | None:
    """Why a rod's ``diameter`` [m] is too wide for its ``tip_radius`` [m] (None when it is
    not): above twice the tip radius (to 1e-9) the end face would stand out beside the
    hemispherical tip, and at angles to the flat below arccos(2R/d) its rim, not the tip, would
    strike first. ``what`` names the diameter in the message (one the mass implies, say)."""
    if diameter is None or not diameter > 2.0 * tip_radius * (1.0 + 1e-9):
        return None
    rim = math.degrees(math.acos(2.0 * tip_radius / diameter))
    return (
        f"{what} ({diameter!r} m) exceeds twice the tip radius ({2.0 * tip_radius!r} m): "
        "the rod's end face would stand out beside its hemispherical tip, and below "
        f"{rim:.3g} deg to the flat its rim would strike before the tip (allowed: "
        "diameter <= 2 tip_radius; the tip as wide as the rod or wider)"
    )


def check_tip_width(tip_radius: float, diameter: float | None, what: str = "diameter") -> None:
    """ValueError when a rod's ``diameter`` [m] exceeds twice its ``tip_radius`` [m]
    (:func:`tip_width_problem`)."""
    problem = tip_width_problem(tip_radius, diameter, what)
    if problem is not None:
        raise ValueError(problem)


#: How the message of :func:`tip_width_problem` names a diameter implied by the mass.
IMPLIED_DIAMETER = "the diameter that the mass, length and density imply, sqrt(4 m / (pi rho L))"


#: A rigid rod's mass (given with neither its diameter nor its inertia) above this multiple of
#: the heaviest uniform rod of its material that its tip covers, rho pi R^2 L (an implied
#: diameter above sqrt(10) 2R), draws an ImplausibleInputWarning: a denser material alone
#: cannot make it up (tungsten is 2.5 times steel), a unit mistake can.
HEAVY_ROD_FACTOR = 10.0


def heavy_rod_problem(L: float, R: float, m: float, material: Material) -> str | None:
    """Why a rigid rod's mass ``m`` [kg] is implausible for its length ``L`` and tip radius
    ``R`` [m] (None when it is not): the diameter a uniform rod of the material's density
    would have, sqrt(4 m / (pi rho L)), exceeds 2R (:func:`tip_width_problem`, the text
    ``FlexibleRod`` refuses with) and the mass is over :data:`HEAVY_ROD_FACTOR` times that of
    a uniform rod as wide as the tip; None without the material's density."""
    rho = material.density
    if rho is None:
        return None
    ratio = m / (rho * math.pi * R * R * L)
    if not ratio > HEAVY_ROD_FACTOR:
        return None
    d = math.sqrt(4.0 * m / (math.pi * rho * L))
    problem = tip_width_problem(R, d, IMPLIED_DIAMETER)
    return (
        f"{problem}; the mass is {ratio:.3g} times that of a uniform rod of the material "
        f"(rho = {rho:.4g} kg/m^3) as wide as the tip (warned above "
        f"{HEAVY_ROD_FACTOR:g}: a unit mistake?); a Rod takes its mass as given: for one that "
        "is not a uniform section (a heavy head), give its inertia"
    )


#: A sphere's given mass above this multiple of a solid sphere of its material draws an
#: ImplausibleInputWarning. Higher than :data:`HEAVY_ROD_FACTOR`: a sphere may stand in for a
#: heavier body's effective mass, a rod of length L striking along its axis weighing 3 L / (4 R)
#: solid spheres of its tip (the paper's rod on its 8.8 mm tip: 21 times; L/R up to 130 stays
#: below), while a gram given as a kilogram is a thousand times.
DENSE_SPHERE_FACTOR = 100.0


def dense_sphere_problem(R: float, m: float, material: Material) -> str | None:
    """Why a sphere's mass ``m`` [kg] is implausible for its radius ``R`` [m] (None when it is
    not): over :data:`DENSE_SPHERE_FACTOR` times that of a solid sphere of the material; None
    without the material's density."""
    if material.density is None:
        return None
    rho = m / (4.0 / 3.0 * math.pi * R**3)
    ratio = rho / material.density
    if not ratio > DENSE_SPHERE_FACTOR:
        return None
    return (
        f"mass = {m!r} kg and radius = {R!r} m imply a density of {rho:.4g} kg/m^3: the mass is "
        f"{ratio:.3g} times that of a solid sphere of the material (rho = "
        f"{material.density:.4g} kg/m^3) of this radius (warned above {DENSE_SPHERE_FACTOR:g}: a "
        "unit mistake?); a Sphere takes its mass as given: for one that stands in for a heavier "
        "body's effective mass (a rod striking along its axis), the warning can be ignored"
    )


#: Largest relative difference between the density that mass, diameter and length imply
#: (m / (pi d^2 / 4 L)) and the material's density when both mass and diameter are given.
DENSITY_TOLERANCE = 0.02


def rod_mass(L: float, m: float | None, d: float | None, material: Material) -> float:
    """The mass [kg] of a uniform rod of circular section: ``m`` as given, or (None) from the
    diameter ``d``, the length ``L`` between the end-sphere centres and the material's density,
    rho pi d^2 / 4 L. ValueError when neither is given, or when both are and the density they
    imply differs from the material's by more than :data:`DENSITY_TOLERANCE` (not checked
    without the material's density; the mass from the diameter needs it)."""
    rho = material.density
    if m is None and d is None:
        raise ValueError("give the mass [kg] or the diameter [m] of the rod (or both)")
    if m is None:
        rho = material.require_density("a rod's mass from its diameter", "give its mass=")
        return rho * math.pi * d * d / 4.0 * L  # type: ignore[operator]
    if d is not None and rho is not None:
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
