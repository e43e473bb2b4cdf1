"""A rigid rod with a hemispherical tip (SI units throughout).

The tip sphere's centre lies L/2 from the centre of mass along the rod axis (the paper's Eq. 1,
doi:10.1007/s00419-015-1108-2); :func:`impactlab.bodies.lever_arms` gives the lever arms at an
angle. ``Rod.to_params`` gives the float64 vector (layout ``impactlab.bodies.layout``) that the
compiled engine reads; it carries the effective shear modulus G* of the contact pair (Mindlin
friction).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from impactlab._html import dataclass_html, dataclass_rows
from impactlab._validation import check_positive, warn_implausible
from impactlab.bodies._checks import (
    INERTIA_RANGE,
    MASS_RANGE,
    PLAUSIBLE_LENGTH,
    PLAUSIBLE_MASS,
    PLAUSIBLE_RADIUS,
    check_allowed,
    check_material,
    check_tip_width,
    checked_mass,
    checked_size,
    heavy_rod_problem,
    inertia_ratio_problem,
    plausible,
    rod_mass,
)
from impactlab.bodies._derived import DerivedFloat, given, note_recomputed
from impactlab.bodies.layout import BP_GSTAR, BP_INERTIA, KIND_ROD
from impactlab.materials import AISI_201, AISI_1010, Material, reduced_shear_modulus, summary_line

__all__ = ["PAPER_ROD", "Rod"]


@dataclass(frozen=True)
class Rod:
    """A rigid rod of length ``length`` (the paper's L) [m] with a hemispherical tip of radius
    ``tip_radius`` [m].

    Length convention: L is the distance between the centres of the end spheres (the centre of
    mass to a tip sphere's centre is L/2, paper Eq. 1); the rod's overall length, tip to tip,
    is L + 2R (``overall_length``). The same for ``FlexibleRod``.

    Parameters
    ----------
    length : L, between the end-sphere centres [m] (overall length L + 2R). ``rod.L`` is the
        same value.
    tip_radius : radius R of the hemispherical tip [m].
    mass : mass m [kg]; None: from the diameter, L and the material's density,
        rho pi d^2 / 4 L (a uniform section over L, its ends weightless, as ``FlexibleRod``).
    material : the rod's material (elastic constants for the contact pair; its density).
    inertia : moment of inertia about the centre of mass I_C [kg m^2]; default m L^2 / 12
        (the paper does not give I_C; m L^2/12 reproduces its impact durations best); at most
        m (L/2 + R)^2, all the mass at the tips (ValueError beyond).
    diameter : the rod's diameter d [m] (optional). Give the mass, the diameter or both; given
        both, the mass must lie between that of the cylinder of length L and diameter d and
        that of the cylinder with two hemispherical ends of radius R, rho pi d^2 / 4 L to
        rho (pi d^2 / 4 L + 4/3 pi R^3), at the material's density within 2 %
        (``impactlab.bodies._checks.DENSITY_TOLERANCE``, ``MASS_CONVENTION``).

    Each quantity is a number in the SI unit above, a string with units (``"8.8 mm"``) or a
    pint Quantity of any registry; the fields hold SI floats.

    Bounds: ValueError unless every quantity is finite and > 0, within the allowed ranges of
    ``impactlab.bodies._checks`` (sizes 1 nm to 10 km, masses 1e-24 to 1e12 kg, given or
    derived: beyond them the derived quantities leave the floats' range), ``tip_radius <=
    length / 2``
    (a wider tip is not a rod), ``diameter <= 2 tip_radius`` (else the end face's rim, not the
    tip, strikes the flat at shallow angles); ImplausibleInputWarning (most likely a unit
    mistake) for a length outside [1 mm, 10 m], a tip radius outside [1 um, 0.5 m] or a mass outside
    [1 mg, 1000 kg]. A mass given without the diameter is the rigid body's own (a rod need not
    be a uniform section of its material: a heavy head, a hollow tube; ``FlexibleRod``, a
    uniform beam, refuses a mass above that of a rod as wide as its tip with two hemispherical
    ends, rho pi R^2 (L + 4 R / 3), by more than 2 %);
    given with neither the diameter nor the inertia, a mass over ten times that of a uniform
    rod as wide as the tip (``bodies._checks.HEAVY_ROD_FACTOR``) draws an
    ImplausibleInputWarning.
    """

    length: float
    tip_radius: float
    mass: float = None  # type: ignore[assignment]  # None: from the diameter; a float after
    material: Material = AISI_201
    inertia: float | None = None
    diameter: float | None = None
    _params: np.ndarray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        L = plausible("length", checked_size("length", self.length), PLAUSIBLE_LENGTH, "m")
        R = checked_size("tip_radius", self.tip_radius)
        if R > 0.5 * L:
            raise ValueError(
                f"tip_radius = {R!r} m exceeds half the rod's length ({0.5 * L!r} m): the "
                "hemispherical tip would be wider than the rod is long; check the units (SI: m)"
            )
        plausible("tip_radius", R, PLAUSIBLE_RADIUS, "m")
        object.__setattr__(self, "material", check_material("material", self.material))
        d = None if self.diameter is None else checked_size("diameter", self.diameter)
        mass = checked_mass("mass", self.mass) if given(self.mass) else None
        m = rod_mass(L, R, mass, d, self.material)
        check_allowed("mass", m, MASS_RANGE, "kg", "rho pi d^2 / 4 L, from the diameter")
        plausible("mass", m, PLAUSIBLE_MASS, "kg")
        check_tip_width(R, d)
        inertia_given = given(self.inertia)
        if d is None and not inertia_given:  # a uniform rod as far as the model knows
            problem = heavy_rod_problem(L, R, m, self.material)
            if problem is not None:
                warn_implausible(problem)
        object.__setattr__(self, "diameter", d)
        if not inertia_given:
            inertia: float = DerivedFloat(m * L * L / 12.0)
            check_allowed("inertia", inertia, INERTIA_RANGE, "kg m^2", "m L^2 / 12")
        else:
            inertia = check_positive("inertia", self.inertia, "kg m^2")
            check_allowed("inertia", inertia, INERTIA_RANGE, "kg m^2")
            problem = inertia_ratio_problem(m, inertia, L)  # as analyze and invert warn
            if problem is not None:
                warn_implausible(f"rod: {problem}")
        reach = 0.5 * L + R  # no mass of the rod lies farther from its centre of mass
        if inertia > m * reach * reach * (1.0 + 1e-12):
            raise ValueError(
                f"inertia = {inertia:g} kg m^2 exceeds m (L/2 + R)^2 = {m * reach * reach:g} kg "
                "m^2, the most a body of this mass within the rod's length can have (all of it "
                "at its ends); check the value and its unit (SI: kg m^2)"
            )
        object.__setattr__(self, "length", L)
        object.__setattr__(self, "tip_radius", R)
        note_recomputed("mass", self.mass, m)
        note_recomputed("inertia", self.inertia, inertia)
        object.__setattr__(self, "mass", m if mass is not None else DerivedFloat(m))
        object.__setattr__(self, "inertia", inertia)
        p = np.array([KIND_ROD, 0.5 * L, R, m, inertia, math.nan], dtype=np.float64)
        p.setflags(write=False)
        object.__setattr__(self, "_params", p)

    @classmethod
    def paper(cls, *, inertia: float | None = None) -> Rod:
        """The paper's rod (Table 1): R = 8.8 mm, L = 0.3048 m, m = 0.4607 kg, AISI 201."""
        return cls(
            length=0.3048, tip_radius=0.0088, mass=0.4607, material=AISI_201, inertia=inertia
        )

    @property
    def L(self) -> float:
        """Rod length L [m] (the paper's symbol; same as ``length``)."""
        return self.length

    @property
    def overall_length(self) -> float:
        """Tip-to-tip length L + 2R [m] (``length`` is L, between the end-sphere centres)."""
        return self.length + 2.0 * self.tip_radius

    @property
    def half_length(self) -> float:
        """Distance from the centre of mass to the tip sphere's centre, L/2 [m]."""
        return 0.5 * self.L

    @property
    def inertia_ratio(self) -> float:
        """I_C / (m L^2), dimensionless (1/12 for a slender rod)."""
        return float(self._params[BP_INERTIA]) / (self.mass * self.length**2)

    def to_params(self, flat: Material = AISI_1010) -> np.ndarray:
        """The float64 parameter vector (layout ``BP_*``) for contact with ``flat``."""
        p = self._params.copy()
        p[BP_GSTAR] = reduced_shear_modulus(self.material, check_material("flat", flat))
        return p

    def _repr_html_(self) -> str:
        return dataclass_html(self, {"overall_length": self.overall_length})

    def __str__(self) -> str:
        """One line in display units, with the overall length L + 2R (``repr`` stays the
        dataclass's, in SI)."""
        rows = dataclass_rows(self, {"overall_length": self.overall_length})
        return summary_line(type(self).__name__, rows)


#: The paper's rod (Table 1 of doi:10.1007/s00419-015-1108-2), I_C = m L^2 / 12.
PAPER_ROD = Rod.paper()
