"""Impacting bodies: a rod with a hemispherical tip, and a sphere (SI units throughout).

Geometry convention (the paper's Eq. 1, doi:10.1007/s00419-015-1108-2): the centre of the tip's
sphere S lies ``L/2`` from the centre of mass C along the rod axis. With the rod axis at the
angle ``theta`` to the flat, the tip lowest and C at +x of the tip, the centre of mass at first
contact is at

    r_C - r_O = ((L/2) cos theta, (L/2) sin theta + R),

where O is the first contact point (the lowest point of the tip sphere, radius R). A sphere is the
special case ``L/2 = 0`` (its centre of mass is the centre of its surface).

Each body turns into a float64 vector (``to_params``) for the compiled engine; the layout is given
by the ``BP_*`` constants below. The vector also carries the effective shear modulus G* of the
contact pair (body material + flat), which the Mindlin friction model needs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from impactlab._validation import check_positive
from impactlab.materials import AISI_201, AISI_1010, Material, reduced_shear_modulus

# --- layout of the body parameter vector (``Body.to_params``) ---------------------------------
BP_KIND = 0  #: 0 = rod, 1 = sphere
BP_HALF_LENGTH = 1  #: distance C -> centre of the tip sphere, L/2 [m] (0 for a sphere)
BP_RADIUS = 2  #: tip (sphere) radius R [m]
BP_MASS = 3  #: mass m [kg]
BP_INERTIA = 4  #: moment of inertia about the centre of mass I_C [kg m^2]
BP_GSTAR = 5  #: effective shear modulus G* of the pair (body, flat) [Pa] (Mindlin friction)
NB = 6  #: length of the vector

KIND_ROD = 0
KIND_SPHERE = 1


def _check_material(name: str, value: object) -> Material:
    if not isinstance(value, Material):
        raise ValueError(f"{name} must be an impactlab Material, got {type(value).__name__}")
    return value


@dataclass(frozen=True)
class Rod:
    """A rigid rod of length ``length`` (the paper's L) [m] with a hemispherical tip of radius
    ``tip_radius`` [m].

    Parameters
    ----------
    length : rod length L [m]; the tip sphere's centre is L/2 from the centre of mass (paper
        Eq. 1). ``rod.L`` is the same value.
    tip_radius : radius R of the hemispherical tip [m].
    mass : mass m [kg].
    material : the rod's material (elastic constants for the contact pair).
    inertia : moment of inertia about the centre of mass I_C [kg m^2]; default m L^2 / 12
        (the paper does not give I_C; m L^2/12 reproduces its impact durations best).
    """

    length: float
    tip_radius: float
    mass: float
    material: Material = AISI_201
    inertia: float | None = None
    _params: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        L = check_positive("length", self.length, "m")
        R = check_positive("tip_radius", self.tip_radius, "m")
        m = check_positive("mass", self.mass, "kg")
        _check_material("material", self.material)
        inertia = m * L * L / 12.0 if self.inertia is None else check_positive(
            "inertia", self.inertia, "kg m^2")
        object.__setattr__(self, "length", L)
        object.__setattr__(self, "tip_radius", R)
        object.__setattr__(self, "mass", m)
        object.__setattr__(self, "inertia", inertia)
        p = np.array([KIND_ROD, 0.5 * L, R, m, inertia, math.nan], dtype=np.float64)
        p.setflags(write=False)
        object.__setattr__(self, "_params", p)

    @classmethod
    def paper(cls, *, inertia: float | None = None) -> Rod:
        """The paper's rod (Table 1): R = 8.8 mm, L = 0.3048 m, m = 0.4607 kg, AISI 201."""
        return cls(length=0.3048, tip_radius=0.0088, mass=0.4607, material=AISI_201,
                   inertia=inertia)

    @property
    def L(self) -> float:  # noqa: N802 - the paper's symbol
        """Rod length L [m] (the paper's symbol; same as ``length``)."""
        return self.length

    @property
    def radius(self) -> float:
        """Contact (tip) radius R [m]."""
        return self.tip_radius

    @property
    def half_length(self) -> float:
        """Distance from the centre of mass to the tip sphere's centre, L/2 [m]."""
        return 0.5 * self.L

    def to_params(self, flat: Material = AISI_1010) -> np.ndarray:
        """The float64 parameter vector (layout ``BP_*``) for contact with ``flat``."""
        p = self._params.copy()
        p[BP_GSTAR] = reduced_shear_modulus(self.material, _check_material("flat", flat))
        return p


@dataclass(frozen=True)
class Sphere:
    """A rigid sphere of radius ``radius`` [m]; I = 2/5 m R^2.

    Give either ``mass`` [kg] or ``density`` [kg/m^3]; with neither, the material's density is
    used (m = 4/3 pi R^3 rho).
    """

    radius: float
    mass: float | None = None
    material: Material = AISI_201
    density: float | None = None
    _params: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        R = check_positive("radius", self.radius, "m")
        _check_material("material", self.material)
        if self.mass is not None and self.density is not None:
            raise ValueError("give either mass or density for a Sphere, not both")
        if self.mass is not None:
            m = check_positive("mass", self.mass, "kg")
            rho = m / (4.0 / 3.0 * math.pi * R**3)
        else:
            rho = (self.material.density if self.density is None
                   else check_positive("density", self.density, "kg/m^3"))
            m = 4.0 / 3.0 * math.pi * R**3 * rho
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
        p[BP_GSTAR] = reduced_shear_modulus(self.material, _check_material("flat", flat))
        return p


Body = Rod | Sphere

#: The paper's rod (Table 1 of doi:10.1007/s00419-015-1108-2), I_C = m L^2 / 12.
PAPER_ROD = Rod.paper()

__all__ = [
    "BP_GSTAR",
    "BP_HALF_LENGTH",
    "BP_INERTIA",
    "BP_KIND",
    "BP_MASS",
    "BP_RADIUS",
    "KIND_ROD",
    "KIND_SPHERE",
    "NB",
    "PAPER_ROD",
    "Body",
    "Rod",
    "Sphere",
]
