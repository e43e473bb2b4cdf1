"""A flexible rod with hemispherical ends: planar axial and bending vibration by modal
superposition of the free-free modes of a uniform rod of circular cross-section (SI units).

The body model (floating frame with mean-axis conditions, the contact at either rounded end,
the defaults from the convergence study) is documented in ``docs/flexible.md``; the drop of
such a rod on a flat is ``impactlab.dynamics.drop.simulate_drop``.

Defaults (from the convergence study of the paper's three drops, ``docs/flexible.md``):
Timoshenko beam theory, no structural damping, no geometric stiffness, and per family the fewest
modes that reach the band the contacts shape (``AXIAL_CUTOFF_HZ``, ``BENDING_CUTOFF_HZ``), at
least 8 axial (+ the 2 axial residual pseudo-modes) and 12 bending: 22 elastic coordinates for
the paper's rod, more for a longer or more slender one. At the paper's three drops they give e
within 0.6 % of a 64 axial + 48 bending model and the same contact sequence; over 200 random
drops of the paper's rod e moves by 0.25 % (median), 1.8 % at most against 24 + 36 modes, and
the number of contacts can change: check convergence with more modes, not only a tighter rtol.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass
from typing import cast

import numpy as np

from impactlab._html import dataclass_html, dataclass_rows
from impactlab._validation import check_range, warn_implausible
from impactlab.bodies._checks import DENSITY_TOLERANCE as DENSITY_TOLERANCE  # re-export
from impactlab.bodies._checks import (
    MASS_RANGE,
    PLAUSIBLE_LENGTH,
    PLAUSIBLE_MASS,
    PLAUSIBLE_RADIUS,
    SIZE_RANGE,
    check_allowed,
    check_material,
    check_tip_width,
    checked_mass,
    checked_size,
    density_problem,
    mass_diameter,
    plausible,
    tip_mass_problem,
)
from impactlab.bodies._derived import DerivedFloat, DerivedInt, given, note_recomputed
from impactlab.bodies._keywords import FLEXIBLE_ROD_NOTES, refuse_unknown_fields
from impactlab.bodies.beam_modes import axial_frequencies, eb_frequencies
from impactlab.bodies.geometric import geometric_tensor
from impactlab.bodies.modal import ModalBasis, modal_basis
from impactlab.bodies.rod import Rod
from impactlab.bodies.rod_section import EULER_BERNOULLI, TIMOSHENKO, RodSection, check_theory
from impactlab.bodies.timoshenko import timoshenko_frequencies
from impactlab.materials import AISI_201, Material, summary_line

__all__ = [
    "AXIAL_CUTOFF_HZ",
    "BENDING_CUTOFF_HZ",
    "DEFAULT_N_AXIAL",
    "DEFAULT_N_BENDING",
    "MAX_MODES",
    "FlexibleRod",
    "check_mode_count",
    "default_mode_count",
]

#: Fewest axial modes by default (plus the two axial residual pseudo-modes): the paper's rod's.
DEFAULT_N_AXIAL = 8
#: Fewest bending modes by default: the paper's rod's.
DEFAULT_N_BENDING = 12
#: The band [Hz] that the default mode counts cover, per family. The contacts of the paper's
#: drops shape the response up to 20-40 kHz (docs/flexible.md), and its rod converged with 8
#: axial and 12 bending modes: its 8th axial mode is at 66.45 kHz (k c / 2L, c = 5064 m/s; the
#: 7th at 58.15 kHz) and its 12th Timoshenko bending mode at 38.02 kHz (the 11th at 33.36 kHz).
#: Rounded down to 66 and 38 kHz, the paper's rod gets exactly 8 + 12; a rod of another length,
#: diameter or material gets the modes that reach the same frequencies (axial ones go as 1/L,
#: bending ones as 1/L^2 at first). The paper's rod lies 0.06 % below a step: 0.1 mm longer,
#: it gets 13 bending modes (e moves by 1e-4, within the defaults' accuracy). Cutoffs further
#: below its modes (36 kHz: 0.6 m rod 15 + 24) gave the 0.6 m rod at 20 deg a 10th contact that
#: 24 + 36 modes and the FE reference do not have; 16 + 25 has their 9.
AXIAL_CUTOFF_HZ = 66e3
#: See ``AXIAL_CUTOFF_HZ``.
BENDING_CUTOFF_HZ = 38e3
#: Most modes of either family: the converged reference of docs/flexible.md uses 64 axial + 48
#: bending modes; 128 bending modes already resolve wavelengths (2 L / n) a third of the
#: paper's rod's diameter, where beam theory no longer holds, and the step of the drop shrinks
#: with the highest frequency (128 + 128 modes: 2.4 s for the paper's 20 deg drop).
MAX_MODES = 128


def check_mode_count(name: str, value: object) -> int:
    """``value`` as a mode count, an integer in [0, ``MAX_MODES``]; else ValueError naming
    ``name`` (the keyword, or the option as the user gave it)."""
    if isinstance(value, float | np.floating) and float(value).is_integer():
        raise ValueError(
            f"{name} must be an integer (a mode count), not a float: got {value!r}; write "
            f"{int(value)}"
        )
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < 0:
        raise ValueError(f"{name} must be an integer >= 0, got {value!r}")
    if value > MAX_MODES:
        raise ValueError(
            f"{name} must be an integer in [0, {MAX_MODES}], got {int(value)} (higher modes "
            "resolve wavelengths below the rod's diameter, where beam theory does not hold, "
            "and only slow the drop; to check convergence, compare twice and four times the "
            "default counts: impactlab.dynamics.mode_convergence)"
        )
    return int(value)


@functools.lru_cache(maxsize=64)
def _band_count(sec: RodSection, theory: str, axial: bool) -> tuple[int, float]:
    """(the fewest modes of the family, at least its default, at most MAX_MODES, whose highest
    reaches its cutoff; the frequency of that highest mode [Hz])."""
    fewest, cutoff = (
        (DEFAULT_N_AXIAL, AXIAL_CUTOFF_HZ) if axial else (DEFAULT_N_BENDING, BENDING_CUTOFF_HZ)
    )
    om_cut = 2.0 * math.pi * cutoff
    om = axial_frequencies(sec, MAX_MODES) if axial else eb_frequencies(sec, MAX_MODES)
    n = max(fewest, min(MAX_MODES, int(np.searchsorted(om, om_cut)) + 1))
    if axial or theory == EULER_BERNOULLI:  # closed forms
        return n, float(om[n - 1]) / (2.0 * math.pi)
    while True:  # Timoshenko: doubling from the Euler-Bernoulli count (shear lowers every mode)
        om = timoshenko_frequencies(sec, n)
        if om[-1] >= om_cut or n == MAX_MODES:
            break
        n = min(MAX_MODES, 2 * n)
    # the first k of n roots are the k roots of a scan for k (near-double roots above the
    # shear cut-off included: timoshenko_frequencies)
    k = max(fewest, min(n, int(np.searchsorted(om, om_cut)) + 1))
    return k, float(om[k - 1]) / (2.0 * math.pi)


def default_mode_count(sec: RodSection, theory: str, family: str) -> int:
    """The default number of ``family`` (``"axial"`` or ``"bending"``) modes of a rod of
    section ``sec`` and beam ``theory``: the fewest whose highest frequency reaches the
    family's cutoff (``AXIAL_CUTOFF_HZ``, ``BENDING_CUTOFF_HZ``), at least ``DEFAULT_N_AXIAL``
    / ``DEFAULT_N_BENDING``; ``MAX_MODES`` with an ImplausibleInputWarning when even those do
    not reach it."""
    axial = family == "axial"
    n, top = _band_count(sec, theory, axial)
    cutoff = AXIAL_CUTOFF_HZ if axial else BENDING_CUTOFF_HZ
    if top < cutoff:
        warn_implausible(
            f"n_{family}: the rod's {MAX_MODES} {family} modes (MAX_MODES) reach "
            f"{top / 1e3:.3g} kHz, below the {cutoff / 1e3:g} kHz that the default counts "
            "cover: the drop resolves less of the contacts' response than for the paper's rod"
        )
    return n


#: What needs a FlexibleRod's material density (``Material.require_density``'s words).
FLEX_NEEDS = "a FlexibleRod (its mass, section and wave speeds)"
#: Smallest slenderness L/d of a flexible rod: the beam modes describe a rod, not a block.
MIN_SLENDERNESS = 2.0


def _check_geometry(L: float, R: float, m: float, d: float | None, material: Material) -> None:
    """ValueError when the mass, the diameter (if given), the length and the material's density
    disagree (``_checks.density_problem``), when the mass alone makes the rod wider than 2R
    (``_checks.tip_mass_problem``), when a given diameter exceeds 2R, or when the rod is
    thicker than L / MIN_SLENDERNESS (the diameter from the mass if not given)."""
    rho = material.require_density(FLEX_NEEDS)
    problem = None
    if d is not None:
        problem = density_problem(L, R, m, d, material)
        if problem is not None:
            raise ValueError(problem)
    else:
        d = math.sqrt(4.0 * m / (math.pi * rho * L))
        check_allowed("diameter", d, SIZE_RANGE, "m", "sqrt(4 m / (pi rho L)), from the mass")
        problem = tip_mass_problem(L, R, m, rho)
        if problem is None:  # the mass fits a rod at most as wide as its tip
            d = mass_diameter(L, R, m, rho) or d
    if not L / d >= MIN_SLENDERNESS:
        raise ValueError(
            f"the rod (length {L!r} m, mass {m!r} kg, {material.name!r} at {rho:.4g} kg/m^3) has "
            f"a diameter of {d:.4g} m, L/d = {L / d:.3g} < {MIN_SLENDERNESS:g}: not a rod (check "
            "the mass and the length and their units)"
        )
    if problem is not None:
        raise ValueError(problem)
    check_tip_width(R, d)


@functools.lru_cache(maxsize=64)
def _basis(
    sec: RodSection, n_axial: int, n_bending: int, theory: str, axial_residual: bool
) -> ModalBasis:
    return modal_basis(sec, n_axial, n_bending, theory, axial_residual=axial_residual)


@functools.lru_cache(maxsize=16)
def _tensor(
    sec: RodSection, n_axial: int, n_bending: int, theory: str, axial_residual: bool
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    arrays = geometric_tensor(_basis(sec, n_axial, n_bending, theory, axial_residual))
    for a in arrays:
        a.setflags(write=False)
    return arrays


@refuse_unknown_fields(FLEXIBLE_ROD_NOTES)
@dataclass(frozen=True)
class FlexibleRod:
    """A uniform flexible rod of circular cross-section with hemispherical ends.

    Parameters
    ----------
    length : rod length L [m], between the centres of the end spheres (they lie on the end
        sections, L/2 from the centre of mass); the overall length, tip to tip, is L + 2R
        (``overall_length``), as for ``Rod``.
    tip_radius : radius R of the hemispherical ends [m].
    mass : mass m [kg], the weighed one: the cylinder between the end-sphere centres and up
        to two hemispherical ends of radius R (``_checks.MASS_CONVENTION``); None: from the
        diameter, the length and the material's density, rho pi d^2 / 4 L (ends weightless).
    diameter : diameter d [m]; None: from the mass, the length and the material's density,
        sqrt(4 m / (pi rho L)), at most 2R: a heavier mass is the ends' (the paper's rod:
        15.71 mm; a 10 mm brass rod 200 mm long with 5 mm hemispherical ends, 0.1379 kg: 10 mm;
        the field stays None, ``section.d`` holds it).
        At least one of ``mass`` and ``diameter`` is required; given both, the mass must lie
        between rho pi d^2 / 4 L and rho (pi d^2 / 4 L + 4/3 pi R^3) to within
        ``DENSITY_TOLERANCE`` (2 %), the mass alone at most 2 % above rho pi R^2 (L + 4 R / 3);
        the beam carries the whole mass along L (its density m / (A L)). L/d must be at least
        ``MIN_SLENDERNESS`` (2); a given diameter must not exceed 2R (else the end face's rim,
        not the tip, strikes the flat at shallow angles). Lengths, tip radii and
        masses outside the bounds of ``impactlab.bodies._checks`` give an
        ImplausibleInputWarning, as for ``Rod``; outside its allowed ranges (sizes 1 nm to
        10 km, the diameter given or implied by the mass; masses 1e-24 to 1e12 kg) a
        ValueError.
    material : the rod's material (E, nu, density; the contact pair's elastic constants).
    n_axial, n_bending : numbers of axial and bending free-free modes (integers in
        [0, ``MAX_MODES``] = [0, 128]); None (default): per family the fewest whose highest
        frequency reaches ``AXIAL_CUTOFF_HZ`` = 66 kHz / ``BENDING_CUTOFF_HZ`` = 38 kHz, at
        least 8 / 12 (``default_mode_count``; the paper's rod: 8 and 12, a 0.6 m rod of the
        same diameter: 16 and 25). The fields hold the counts used (``dataclasses.replace``
        keeps them: give ``n_axial=None, n_bending=None`` to choose them again).
    axial_residual : add the two axial residual pseudo-modes (static compliance of all the
        truncated axial modes; needs n_axial >= 1); None (default): with any axial mode.
    damping : modal damping ratio zeta [1] of every elastic mode, in [0, 1) (default 0).
    theory : ``"timoshenko"`` (default) or ``"euler-bernoulli"``.
    geometric : add the geometric stiffness of the axial force (cubic modal potential); more
        accurate for contact forces near the Euler load, 5 to 100 times slower.
    """

    length: float
    tip_radius: float
    mass: float | None = None
    diameter: float | None = None
    material: Material = AISI_201
    n_axial: int | None = None
    n_bending: int | None = None
    axial_residual: bool | None = None
    damping: float = 0.0
    theory: str = TIMOSHENKO
    geometric: bool = False

    def __post_init__(self) -> None:
        L = plausible("length", checked_size("length", self.length), PLAUSIBLE_LENGTH, "m")
        R = checked_size("tip_radius", self.tip_radius)
        if R > 0.5 * L:
            raise ValueError(
                f"tip_radius ({R!r} m) must not exceed half the length (L/2 = {0.5 * L!r} m)"
            )
        plausible("tip_radius", R, PLAUSIBLE_RADIUS, "m")
        object.__setattr__(self, "material", check_material("material", self.material))
        rho = self.material.require_density(FLEX_NEEDS)
        if not given(self.mass) and self.diameter is None:
            raise ValueError("give the mass [kg] or the diameter [m] of the rod (or both)")
        d = None if self.diameter is None else checked_size("diameter", self.diameter)
        if not given(self.mass):
            m: float = DerivedFloat(rho * math.pi * cast(float, d) ** 2 / 4.0 * L)
            check_allowed("mass", m, MASS_RANGE, "kg", "rho pi d^2 / 4 L, from the diameter")
        else:
            m = checked_mass("mass", self.mass)
        plausible("mass", m, PLAUSIBLE_MASS, "kg")
        note_recomputed("mass", self.mass, m)
        _check_geometry(L, R, m, d, self.material)
        for name, value in (("length", L), ("tip_radius", R), ("mass", m), ("diameter", d)):
            object.__setattr__(self, name, value)
        z = check_range("damping", self.damping, 0.0, 1.0, high_inclusive=False)
        object.__setattr__(self, "damping", z)
        object.__setattr__(self, "theory", check_theory(self.theory))
        for family in ("axial", "bending"):
            name, value = f"n_{family}", getattr(self, f"n_{family}")
            if not given(value):  # by frequency: the band of the paper's rod's defaults
                count = default_mode_count(self.section, self.theory, family)
                note_recomputed(name, value, count)
                object.__setattr__(self, name, DerivedInt(check_mode_count(name, count)))
            else:
                object.__setattr__(self, name, check_mode_count(name, value))
        n_axial = cast(int, self.n_axial)
        if self.axial_residual is None:  # the CLI's and the study files' rule
            object.__setattr__(self, "axial_residual", n_axial >= 1)
        if self.axial_residual is True and n_axial < 1:
            raise ValueError(
                f"axial_residual=True needs n_axial >= 1, got n_axial={n_axial} (leave "
                "axial_residual out: it follows n_axial)"
            )
        for flag in ("axial_residual", "geometric"):
            if not isinstance(getattr(self, flag), bool):
                raise ValueError(f"{flag} must be True or False, got {getattr(self, flag)!r}")

    @classmethod
    def paper(cls, **overrides: object) -> FlexibleRod:
        """The paper's rod (Table 1 of doi:10.1007/s00419-015-1108-2) as a flexible body:
        L = 0.3048 m, R = 8.8 mm, m = 0.4607 kg, AISI 201 (E 200 GPa, nu 0.3, rho 7800 kg/m^3),
        so d = 15.71 mm (L/d = 19.4); ``overrides`` replace any field (``n_bending=24``, ...)."""
        args: dict[str, object] = {
            "length": 0.3048,
            "tip_radius": 0.0088,
            "mass": 0.4607,
            "material": AISI_201,
        }
        args.update(overrides)
        return cls(**args)  # type: ignore[arg-type]  # checked by __post_init__

    @property
    def section(self) -> RodSection:
        """The rod's cross-section data (``impactlab.bodies.rod_section.RodSection``); without
        a diameter, its diameter is sqrt(4 m / (pi rho L)), at most 2R (the mass convention)."""
        m, rho = cast(float, self.mass), self.material.require_density(FLEX_NEEDS)
        d = self.diameter
        if d is None:
            d = mass_diameter(self.length, self.tip_radius, m, rho)
        return RodSection(
            length=self.length,
            mass=m,
            density=rho,
            E=self.material.E,
            nu=self.material.nu,
            diameter=d,
        )

    @property
    def overall_length(self) -> float:
        """Tip-to-tip length L + 2R [m] (``length`` is L, between the end-sphere centres)."""
        return self.length + 2.0 * self.tip_radius

    @property
    def half_length(self) -> float:
        """Distance from the centre of mass to the centre of an end sphere, L/2 [m]."""
        return 0.5 * self.length

    @property
    def inertia(self) -> float:
        """Moment of inertia about the centre of mass I_C [kg m^2], consistent with the
        beam theory: m L^2 / 12 (Euler-Bernoulli) or m (L^2 / 12 + d^2 / 16) (Timoshenko)."""
        return self.section.inertia(self.theory)

    def basis(self) -> ModalBasis:
        """The free-free modal basis (cached by value)."""
        return _basis(self.section, *self._modes())

    def geometric_tensor(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """The geometric-stiffness tensor and its index arrays
        (``impactlab.bodies.geometric.geometric_tensor``; cached by value)."""
        return _tensor(self.section, *self._modes())

    def _modes(self) -> tuple[int, int, str, bool]:
        """(n_axial, n_bending, theory, axial_residual): ints and a bool after __post_init__."""
        n_ax, n_b, res = (
            cast(int, self.n_axial),
            cast(int, self.n_bending),
            bool(self.axial_residual),
        )
        return n_ax, n_b, self.theory, res

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Natural frequencies of the elastic modes [Hz] (axial, bending, residual)."""
        return self.basis().frequencies_hz

    def _repr_html_(self) -> str:
        return dataclass_html(self, self._derived())

    def _derived(self) -> dict[str, float]:
        return {"inertia": self.inertia, "overall_length": self.overall_length}

    def __str__(self) -> str:
        """One line in display units, with I_C and the overall length L + 2R (``repr`` stays
        the dataclass's, in SI)."""
        return summary_line(type(self).__name__, dataclass_rows(self, self._derived()))

    def rigid(self) -> Rod:
        """The rigid rod with the same length, tip radius, mass, material and I_C."""
        return Rod(
            length=self.length,
            tip_radius=self.tip_radius,
            mass=float(cast(float, self.mass)),  # given: a plain float (``_derived``)
            material=self.material,
            inertia=self.inertia,
        )
