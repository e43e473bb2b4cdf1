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
        f"{what} ({diameter:.4g} m) exceeds twice the tip radius ({2.0 * tip_radius:.4g} m): "
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


#: Largest relative difference allowed between the material's density and the density that a
#: rod's mass and diameter imply (:func:`density_problem`): given both, or the mass alone with
#: the rod as wide as its tip (:func:`tip_mass_problem`).
DENSITY_TOLERANCE = 0.02
#: How the message of :func:`tip_width_problem` names the diameter a mass implies: the
#: narrowest reading of the mass convention (:func:`rod_mass`), both ends full hemispheres.
IMPLIED_DIAMETER = (
    "the diameter that the mass, length and density imply with both hemispherical ends "
    "counted, sqrt(4 (m / rho - 4/3 pi R^3) / (pi L))"
)
#: The mass convention of a rod of uniform section, as the messages state it.
MASS_CONVENTION = (
    "the mass convention: the cylinder of length L between the end-sphere centres and "
    "diameter d, plus up to two hemispherical ends of radius R (ends of the rod's own radius: "
    "m = rho pi d^2 (L + 2 d / 3) / 4); from the mass alone d = sqrt(4 m / (pi rho L)), at "
    "most 2R"
)


def ends_volume(tip_radius: float) -> float:
    """Volume [m^3] of two hemispherical ends of radius ``tip_radius`` [m], 4/3 pi R^3: the
    most that a rod's ends beyond its end-sphere centres hold (its section is at most 2R)."""
    return 4.0 / 3.0 * math.pi * tip_radius**3


def mass_diameter(L: float, R: float, m: float, rho: float) -> float | None:
    """The diameter [m] of a uniform rod of density ``rho`` [kg/m^3], length ``L`` between
    the end-sphere centres and tip radius ``R`` [m] from its mass ``m`` [kg] alone: None when
    the cylinder of that mass over L, sqrt(4 m / (pi rho L)), is at most 2R (to 1e-9; the
    caller takes that one), else 2R, the rest of the mass being its ends (:data:`MASS_CONVENTION`;
    :func:`tip_mass_problem` says whether they can hold it)."""
    d = math.sqrt(4.0 * m / (math.pi * rho * L))
    return None if tip_width_problem(R, d) is None else 2.0 * R


def tip_mass_problem(L: float, R: float, m: float, rho: float) -> str | None:
    """Why the mass ``m`` [kg] of a uniform rod of density ``rho`` [kg/m^3] (length ``L``
    between the end-sphere centres, tip radius ``R`` [m]) makes it wider than 2R (None when it
    does not): it exceeds, by more than :data:`DENSITY_TOLERANCE`, the mass of a rod as wide
    as its tip with both hemispherical ends, rho pi R^2 (L + 4 R / 3)."""
    most = rho * (math.pi * R * R * L + ends_volume(R))
    if not m > (1.0 + DENSITY_TOLERANCE) * most:
        return None
    d = math.sqrt(4.0 * (m / rho - ends_volume(R)) / (math.pi * L))
    return (
        f"{tip_width_problem(R, d, IMPLIED_DIAMETER)}; at rho = {rho:.4g} kg/m^3 a rod as "
        f"wide as its tip with both hemispherical ends weighs {most:.4g} kg, and the mass "
        f"({m!r} kg) may exceed that by {DENSITY_TOLERANCE:.0%} at most ({MASS_CONVENTION})"
    )


#: A rigid rod's mass (given with neither its diameter nor its inertia) above this multiple of
#: the heaviest uniform rod of its material that its tip covers, rho pi R^2 L (an implied
#: diameter above sqrt(10) 2R), draws an ImplausibleInputWarning: a denser material alone
#: cannot make it up (tungsten is 2.5 times steel), a unit mistake can.
HEAVY_ROD_FACTOR = 10.0


def heavy_rod_problem(L: float, R: float, m: float, material: Material) -> str | None:
    """Why a rigid rod's mass ``m`` [kg] is implausible for its length ``L`` and tip radius
    ``R`` [m] (None when it is not): the mass is over :data:`HEAVY_ROD_FACTOR` times that of
    a uniform rod of the material as wide as the tip, so the diameter it implies even with
    both hemispherical ends counted exceeds 2R (:func:`tip_width_problem`, the text
    ``FlexibleRod`` refuses with, :func:`tip_mass_problem`); None without the density."""
    rho = material.density
    if rho is None:
        return None
    ratio = m / (rho * math.pi * R * R * L)
    if not ratio > HEAVY_ROD_FACTOR:
        return None
    d = math.sqrt(4.0 * (m / rho - ends_volume(R)) / (math.pi * L))
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
    not): over :data:`DENSE_SPHERE_FACTOR` times that of a solid sphere of the material, or
    under its 1 / ``DENSE_SPHERE_FACTOR`` (a thin hollow shell is a tenth or a twentieth; a gram
    read as a kilogram a thousandth); None without the material's density."""
    if material.density is None:
        return None
    rho = m / (4.0 / 3.0 * math.pi * R**3)
    ratio = rho / material.density
    if ratio * DENSE_SPHERE_FACTOR < 1.0:
        return (
            f"mass = {m!r} kg and radius = {R!r} m imply a density of {rho:.4g} kg/m^3: the mass "
            f"is 1/{1.0 / ratio:.3g} of that of a solid sphere of the material (rho = "
            f"{material.density:.4g} kg/m^3) of this radius (warned below 1/"
            f"{DENSE_SPHERE_FACTOR:g}: a unit mistake, g/cm^3 or g read as SI?)"
        )
    if not ratio > DENSE_SPHERE_FACTOR:
        return None
    return (
        f"mass = {m!r} kg and radius = {R!r} m imply a density of {rho:.4g} kg/m^3: the mass is "
        f"{ratio:.3g} times that of a solid sphere of the material (rho = "
        f"{material.density:.4g} kg/m^3) of this radius (warned above {DENSE_SPHERE_FACTOR:g}: a "
        "unit mistake?); a Sphere takes its mass as given: for one that stands in for a heavier "
        "body's effective mass (a rod striking along its axis), the warning can be ignored"
    )


def density_problem(L: float, R: float, m: float, d: float, material: Material) -> str | None:
    """Why a rod's mass ``m`` [kg] and diameter ``d`` [m] (length ``L`` between the end-sphere
    centres, tip radius ``R`` [m]) do not fit the material's density (None when they do, or
    without it). By :data:`MASS_CONVENTION` they imply a density from m / (pi d^2 / 4 L) (the
    ends weightless) down to m / (pi d^2 / 4 L + 4/3 pi R^3) (two full hemispherical ends);
    the material's must lie in that range widened by :data:`DENSITY_TOLERANCE`."""
    rho = material.density
    if rho is None:
        return None
    cylinder = math.pi * d * d / 4.0 * L
    high, low = m / cylinder, m / (cylinder + ends_volume(R))
    if high / rho - 1.0 >= -DENSITY_TOLERANCE and low / rho - 1.0 <= DENSITY_TOLERANCE:
        return None
    return (
        f"mass ({m!r} kg), diameter ({d!r} m) and length ({L!r} m) imply a density of "
        f"{high:.4g} kg/m^3 (all the mass in the cylinder of length L between the end-sphere "
        f"centres) to {low:.4g} kg/m^3 (two hemispherical ends of radius {R!r} m besides), but "
        f"the material {material.name!r} has {rho:.4g} kg/m^3 (allowed: within "
        f"{DENSITY_TOLERANCE:.0%} of that range; {MASS_CONVENTION}); give the mass or the "
        "diameter, not both, or the material they belong to"
    )


def rod_mass(L: float, R: float, m: float | None, d: float | None, material: Material) -> float:
    """The mass [kg] of a rod of circular section: ``m`` as given, or (None) from the diameter
    ``d``, the length ``L`` between the end-sphere centres and the material's density,
    rho pi d^2 / 4 L (its ends weightless, the lower end of :data:`MASS_CONVENTION`).
    ValueError when neither is given, or when both are and do not fit the material's density
    (:func:`density_problem`, with the tip radius ``R``; not checked without the density; the
    mass from the diameter needs it)."""
    if m is None and d is None:
        raise ValueError("give the mass [kg] or the diameter [m] of the rod (or both)")
    if m is None:
        rho = material.require_density("a rod's mass from its diameter", "give its mass=")
        return rho * math.pi * d * d / 4.0 * L  # type: ignore[operator]
    if d is not None:
        problem = density_problem(L, R, m, d, material)
        if problem is not None:
            raise ValueError(problem)
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


#: A rod's I_C / (m L^2) below this, 20 times below a uniform rod's 1/12, is implausible (a
#: mass in grams given in kilograms gives 1000 times below).
INERTIA_RATIO_FLOOR = 1.0 / 240.0
#: The words that open :func:`inertia_ratio_problem`'s text (``impactlab invert`` finds its
#: doubt by them).
INERTIA_MISFIT = "the mass and the inertia do not fit"


def inertia_ratio_problem(mass: float, inertia: float, length: float) -> str | None:
    """Why a rod's mass [kg] and inertia I_C [kg m^2] do not fit its length [m] (None when they
    do): I_C / (m L^2) below :data:`INERTIA_RATIO_FLOOR`, with the likely unit mistake (the most
    a rod can have, all its mass at its ends, is refused by ``Rod`` itself). Shared by
    ``impactlab.experiment.analyze`` and ``impactlab.analytic.invert``."""
    k = inertia / (mass * length * length)
    if k >= INERTIA_RATIO_FLOOR:
        return None
    hint = ""
    if INERTIA_RATIO_FLOOR <= 1e3 * k <= 0.25:
        hint = (
            f": a mass in grams given as kilograms? (mass = {mass * 1e-3:.4g} kg gives "
            f"{1e3 * k:.3g})"
        )
    return (
        f"{INERTIA_MISFIT}: I_C / (m L^2) = {k:.2g} (mass = "
        f"{mass:.4g} kg, inertia = "
        f"{inertia:.4g} kg m^2, L = {length:.4g} m), {1.0 / (12.0 * k):.3g} times below "
        f"a uniform rod's 1/12 (below {INERTIA_RATIO_FLOOR:.2g} no rod is plausible); the mass "
        f"or the inertia is in a wrong unit{hint}; check the rod (SI: kg, kg m^2)"
    )
