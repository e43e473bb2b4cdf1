"""The uniform rod of solid circular cross-section behind the flexible rod's modes (SI units).

The rod occupies the body-frame coordinate s in [-L/2, L/2] (s along the axis from the centre
of mass C); end 0 is s = -L/2 (the tip that touches the flat first), end 1 is s = +L/2. The
diameter is given, or derived from the mass, length and density (A = m / (rho L)). Section
properties: A = pi d^2 / 4, I = pi d^4 / 64, radius of gyration r_g = d / 4. Shear coefficient
of a solid circle (Timoshenko beam): kappa = 6 (1 + nu) / (7 + 6 nu), G. R. Cowper, The shear
coefficient in Timoshenko's beam theory, J. Appl. Mech. 33 (1966) 335-340,
doi:10.1115/1.3625046.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab._validation import check_positive, check_range

__all__ = ["EULER_BERNOULLI", "THEORIES", "TIMOSHENKO", "RodSection", "check_theory", "gauss"]

#: Beam theory names (``FlexibleRod.theory``).
EULER_BERNOULLI = "euler-bernoulli"
TIMOSHENKO = "timoshenko"
THEORIES = (TIMOSHENKO, EULER_BERNOULLI)

_GL_X, _GL_W = np.polynomial.legendre.leggauss(24)


def check_theory(theory: object) -> str:
    """``theory`` if it is a beam theory name; ValueError naming the allowed ones."""
    if theory not in THEORIES:
        raise ValueError(f"theory must be one of {THEORIES}, got {theory!r}")
    return str(theory)


def gauss(L: float, panels: int) -> tuple[np.ndarray, np.ndarray]:
    """Nodes x in [0, L] [m] and weights [m] of a composite 24-point Gauss-Legendre rule on
    ``panels`` equal panels."""
    edges = np.linspace(0.0, L, panels + 1)
    h = 0.5 * (edges[1:] - edges[:-1])
    mid = 0.5 * (edges[1:] + edges[:-1])
    x = (mid[:, None] + h[:, None] * _GL_X[None, :]).ravel()
    w = (h[:, None] * _GL_W[None, :]).ravel()
    return x, w


@dataclass(frozen=True)
class RodSection:
    """A uniform rod of solid circular cross-section.

    length [m], mass [kg], density [kg/m^3], E [Pa], nu [1]; diameter [m] (None: from the mass,
    length and density); shear_coefficient [1] (None: Cowper's value for a solid circle).
    When both the diameter and the mass are given, the density consistent with them
    (``rho_eff`` = m / (A L)) is the one the modes use.
    """

    length: float
    mass: float
    density: float
    E: float
    nu: float
    diameter: float | None = None
    shear_coefficient: float | None = None

    def __post_init__(self) -> None:
        for name, unit in (("length", "m"), ("mass", "kg"), ("density", "kg/m^3"), ("E", "Pa")):
            object.__setattr__(self, name, check_positive(name, getattr(self, name), unit))
        nu = check_range("nu", self.nu, -1.0, 0.5, low_inclusive=False, high_inclusive=False)
        object.__setattr__(self, "nu", nu)
        if self.diameter is None:
            d = math.sqrt(4.0 * self.mass / (self.density * self.length) / math.pi)
        else:
            d = check_positive("diameter", self.diameter, "m")
        object.__setattr__(self, "diameter", d)
        if self.shear_coefficient is not None:
            k = check_positive("shear_coefficient", self.shear_coefficient)
            object.__setattr__(self, "shear_coefficient", k)

    @classmethod
    def paper(cls, **overrides: float) -> RodSection:
        """The paper's rod (Table 1 of doi:10.1007/s00419-015-1108-2): L = 0.3048 m,
        m = 0.4607 kg, AISI 201 (rho 7800 kg/m^3, E 200 GPa, nu 0.3); d = 15.71 mm from m, L and
        rho (L/d = 19.4). ``overrides`` replace any of these."""
        args: dict[str, float] = {
            "length": 0.3048,
            "mass": 0.4607,
            "density": 7800.0,
            "E": 200e9,
            "nu": 0.3,
        }
        args.update(overrides)
        return cls(**args)

    @property
    def d(self) -> float:
        """Diameter [m]."""
        d = self.diameter
        return math.nan if d is None else d

    @property
    def area(self) -> float:
        """Cross-section area A [m^2]."""
        return math.pi * self.d**2 / 4.0

    @property
    def second_moment(self) -> float:
        """Second moment of area I [m^4]."""
        return math.pi * self.d**4 / 64.0

    @property
    def rho_a(self) -> float:
        """Mass per unit length m / L [kg/m] (the rod's mass is what is given)."""
        return self.mass / self.length

    @property
    def rho_eff(self) -> float:
        """Density consistent with m, L and d [kg/m^3] (equals ``density`` when d is
        derived)."""
        return self.rho_a / self.area

    @property
    def G(self) -> float:
        """Shear modulus E / (2 (1 + nu)) [Pa]."""
        return self.E / (2.0 * (1.0 + self.nu))

    @property
    def kappa(self) -> float:
        """Shear coefficient [1] (Cowper 1966, solid circle, unless given)."""
        if self.shear_coefficient is not None:
            return float(self.shear_coefficient)
        return 6.0 * (1.0 + self.nu) / (7.0 + 6.0 * self.nu)

    @property
    def bar_speed(self) -> float:
        """Bar wave speed c = sqrt(E / rho) [m/s]."""
        return math.sqrt(self.E / self.rho_eff)

    @property
    def slenderness(self) -> float:
        """L / d [1]."""
        return self.length / self.d

    @property
    def radius_of_gyration(self) -> float:
        """r_g = d / 4 [m]."""
        return self.d / 4.0

    def inertia(self, theory: str = EULER_BERNOULLI) -> float:
        """Moment of inertia about C [kg m^2]: m L^2 / 12 (Euler-Bernoulli: no rotary inertia
        of the sections) or m (L^2 / 12 + r_g^2) (Timoshenko, consistent with its mass
        matrix)."""
        base = self.mass * self.length**2 / 12.0
        if check_theory(theory) == TIMOSHENKO:
            return base + self.mass * self.radius_of_gyration**2
        return base
