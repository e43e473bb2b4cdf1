"""A rigid sphere (SI units); the contact point's lever arm is its radius."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from impactlab._html import dataclass_html, dataclass_rows
from impactlab._validation import check_positive, warn_implausible
from impactlab.bodies._checks import (
    MASS_RANGE,
    PLAUSIBLE_MASS,
    PLAUSIBLE_RADIUS,
    check_allowed,
    check_material,
    checked_mass,
    checked_size,
    dense_sphere_problem,
    plausible,
)
from impactlab.bodies._derived import DerivedFloat, given, note_recomputed
from impactlab.bodies.layout import BP_GSTAR, BP_INERTIA, KIND_SPHERE
from impactlab.materials import AISI_201, AISI_1010, Material, reduced_shear_modulus, summary_line

__all__ = ["Sphere"]


@dataclass(frozen=True)
class Sphere:
    """A rigid sphere of radius ``radius`` [m]; I = 2/5 m R^2.

    Give either ``mass`` [kg] or ``density`` [kg/m^3]; with neither, the material's density is
    used (m = 4/3 pi R^3 rho). Each quantity is a number in that SI unit, a string with units
    (``"5 mm"``) or a pint Quantity of any registry.

    Bounds: ValueError unless the radius, mass and density are finite and > 0, the radius in
    [1 nm, 10 km] and the mass (given, or from the radius and density) in [1e-24, 1e12] kg
    (``impactlab.bodies._checks``: beyond them the derived quantities leave the floats' range);
    ImplausibleInputWarning for a radius outside [1 um, 0.5 m] or a mass outside
    [1 mg, 1000 kg]. The mass is free of the material's density (a hollow ball, or a sphere
    that stands in for a heavier body's effective mass: ``fe.impact_reference``'s rod-mass
    case is 8.8 mm with the rod's 0.46 kg); a given mass or density over a hundred times that
    of a solid sphere of the material, or under a hundredth of it
    (``bodies._checks.DENSE_SPHERE_FACTOR``; a rod striking along its axis is 3 L / (4 R)
    times, the rod-mass case 21; a thin hollow shell a tenth or a twentieth) draws an
    ImplausibleInputWarning: ``Sphere(radius="5 mm", mass=1.0)`` is 245 times steel's, 1 kg
    where 1 g was meant; ``density=7.8`` is g/cm^3 read as kg/m^3.
    """

    radius: float
    mass: float | None = None
    material: Material = AISI_201
    density: float | None = None
    _params: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        R = plausible("radius", checked_size("radius", self.radius), PLAUSIBLE_RADIUS, "m")
        object.__setattr__(self, "material", check_material("material", self.material))
        if given(self.mass) and given(self.density):
            raise ValueError("give either mass or density for a Sphere, not both")
        if given(self.mass):
            m = checked_mass("mass", self.mass)
            rho: float = DerivedFloat(m / (4.0 / 3.0 * math.pi * R**3))
            problem = dense_sphere_problem(R, m, self.material)
            if problem is not None:
                warn_implausible(problem)
        else:
            rho = (
                DerivedFloat(
                    self.material.require_density(
                        "a Sphere's mass from its radius", "give the Sphere mass= or density="
                    )
                )
                if not given(self.density)
                else check_positive("density", self.density, "kg/m^3")
            )
            m = DerivedFloat(4.0 / 3.0 * math.pi * R**3 * rho)
            problem = dense_sphere_problem(R, m, self.material) if given(self.density) else None
            if problem is not None:  # a density of its own, far from the material's
                warn_implausible(problem)
            check_allowed("mass", m, MASS_RANGE, "kg", "4/3 pi R^3 rho, from the radius")
        plausible("mass", m, PLAUSIBLE_MASS, "kg")
        note_recomputed("mass", self.mass, m)
        note_recomputed("density", self.density, rho)
        object.__setattr__(self, "radius", R)
        object.__setattr__(self, "mass", m)
        object.__setattr__(self, "density", rho)
        p = np.array([KIND_SPHERE, 0.0, R, m, 0.4 * m * R * R, math.nan], dtype=np.float64)
        p.setflags(write=False)
        object.__setattr__(self, "_params", p)

    @property
    def inertia(self) -> float:
        """Moment of inertia about the centre, 2/5 m R^2 [kg m^2]."""
        return float(self._params[BP_INERTIA])

    @property
    def tip_radius(self) -> float:
        """Contact radius (the sphere's radius) [m]."""
        return self.radius

    @property
    def half_length(self) -> float:
        """0: the contact sphere's centre is the centre of mass."""
        return 0.0

    def to_params(self, flat: Material = AISI_1010) -> np.ndarray:
        """The float64 parameter vector (layout ``BP_*``) for contact with ``flat``."""
        p = self._params.copy()
        p[BP_GSTAR] = reduced_shear_modulus(self.material, check_material("flat", flat))
        return p

    def _repr_html_(self) -> str:
        return dataclass_html(self, {"inertia": self.inertia})

    def __str__(self) -> str:
        """One line in display units (``repr`` stays the dataclass's, in SI)."""
        return summary_line(type(self).__name__, dataclass_rows(self, {"inertia": self.inertia}))
