"""Materials and contact pairs (SI units throughout).

Every quantity is SI except the Brinell hardness, which is kept in its customary unit kgf/mm^2
(the "HB" number) and converted by :func:`brinell_to_pa` where a law needs a pressure.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab._html import dataclass_html, dataclass_rows
from impactlab._validation import (
    check_finite,
    check_positive,
    check_range,
    value_text,
    warn_implausible,
)

#: Standard gravity [m/s^2], used to convert kgf to N.
G0 = 9.80665
#: The unit of a Brinell hardness number.
_HB = "kgf/mm^2"


def summary_line(title: str, rows: list[tuple[str, str, str]]) -> str:
    """``"title: name = value unit, ..."``: the ``(name, text, unit)`` rows of
    ``impactlab._html.dataclass_rows`` (display units) on one line, unset values (``-``)
    left out and a body's ``material`` (a name) last. The ``__str__`` of materials and bodies."""
    items = [
        f"{name} = {text} {unit}".rstrip() if unit not in ("", "-") else f"{name} = {text}"
        for name, text, unit in sorted(rows, key=lambda r: r[0] == "material")
        if text != "-"
    ]
    return f"{title}: {', '.join(items)}"


def brinell_to_pa(hb: float) -> float:
    """Brinell hardness number (kgf/mm^2) to pressure in Pa: ``HB * g0 * 1e6``."""
    return hb * G0 * 1.0e6


#: Plausible values of a solid a drop test strikes (field -> (low, high, unit, the unit a bare
#: number outside them most likely left out)): a modulus or a strength below 10 kPa (softer
#: than a soft silicone or a foam's crush strength) is one given in MPa or GPa but read in Pa;
#: a density below 5 kg/m^3 (lighter than any foam) one in g/cm^3; a hardness above 10^4
#: kgf/mm^2 (the hardest metals are below 10^3) one in Pa.
PLAUSIBLE: dict[str, tuple[float, float, str, str]] = {
    "E": (1e4, 1e13, "Pa", "GPa"),
    "yield_strength": (1e4, 1e11, "Pa", "MPa"),
    "density": (5.0, 3e4, "kg/m^3", "g/cm^3"),
    "brinell_hardness": (0.1, 1e4, _HB, "Pa"),
}

#: The largest plausible yield strain S_y / E: metals 0.001-0.01, PMMA 0.04; above it one of
#: the two is most likely in another unit (69 GPa written as 690 MPa).
MAX_YIELD_STRAIN = 0.1

#: How far below :data:`PLAUSIBLE` a value is refused rather than warned about (a factor): no
#: solid has it, and the contact laws' closed forms overflow or divide by zero long before (a
#: yield strength of 1e-100 Pa). Above, only the warning: a stand-in for a rigid body is a
#: material 10^9 times stiffer than steel on purpose.
BEYOND_PLAUSIBLE = 1e3

#: The fields that hold a material's values (what a library entry's source gives).
_VALUES = ("E", "nu", "yield_strength", "brinell_hardness", "meyer_index", "density")


#: A Brinell hardness written with its symbol: ``105 HB``, ``105 HBW`` or ``HBW 105``.
_HB_TEXT = re.compile(r"^\s*(?:(?P<a>[^\sA-Za-z][^\s]*)\s*HBW?|HBW?\s+(?P<b>\S+))\s*$")


def brinell_text(value: Any) -> Any:
    """A Brinell hardness written with its symbol HB or HBW (``"105 HB"``, ``"HBW 105"``) as
    ``"105 kgf/mm^2"`` (a Brinell number is kgf/mm^2); any other value unchanged."""
    m = _HB_TEXT.match(value) if isinstance(value, str) else None
    return value if m is None else f"{m.group('a') or m.group('b')} kgf/mm^2"


def _is_nan(value: Any) -> bool:
    """True for a NaN float of any precision (``math.nan``, ``np.float32("nan")``)."""
    return isinstance(value, float | np.floating) and math.isnan(value)


@contextmanager
def _float_range(name: str, value: Any, unit: str = "") -> Iterator[None]:
    """ValueError naming ``name`` for a number beyond a float's range (``10**400``), which
    ``float()`` refuses with an OverflowError."""
    try:
        yield
    except OverflowError:
        text = repr(value)
        text = text if len(text) <= 24 else f"{text[:12]}... ({len(text)} characters)"
        raise ValueError(
            f"{name} must be a finite number{f' in {unit}' if unit else ''}, got {text}: beyond "
            "the largest float, about 1.8e308"
        ) from None


def hardness_below_yield(material: Material) -> str:
    """Why ``material``'s Brinell hardness cannot be right ("" when it can): its pressure (HB
    in kgf/mm^2, :func:`brinell_to_pa`) lies below the yield strength, while a hardness is about
    3 S_y (Tabor): a unit slip. Checked where a user gives the values (``get_material``), not on
    every Material: a copy with a changed yield strength (a sweep, a calibration) keeps the
    library's hardness, which only Brake's law reads (and refuses in its own words)."""
    if not material.has_hardness:
        return ""
    h = brinell_to_pa(material.brinell_hardness)
    if h >= material.yield_strength:
        return ""
    return (
        f"brinell_hardness HB = {material.brinell_hardness:.4g} "
        f"{_HB} ({h / 1e6:.4g} MPa) lies below the yield strength S_y = "
        f"{material.yield_strength / 1e6:.4g} MPa, while a hardness is about 3 S_y; HB is in "
        f"{_HB} (a Brinell number: HB 95 is 932 MPa), check its unit"
    )


@dataclass(frozen=True)
class Material:
    """An isotropic elastic-plastic material.

    Parameters
    ----------
    name : label.
    E : Young's modulus [Pa].
    nu : Poisson's ratio, in (-1, 0.5).
    yield_strength : uniaxial yield strength S_y [Pa].
    brinell_hardness : Brinell hardness number HB [kgf/mm^2] (used by Brake's law); text may
        carry its symbol (``"95 HB"``, ``"95 HBW"``); NaN of any float type (the default): not
        given.
    meyer_index : Meyer's strain-hardening index n (Brake's law), typically 2 to 2.5; must be > 2.
    density : mass density [kg/m^3]; None (the default): not given, and whatever needs it (a
        Sphere's or a Rod's mass from it, a FlexibleRod) refuses the material
        (:meth:`require_density`). A flat's density plays no part in a rigid-body impact.
    condition : temper or condition the values belong to ("T6", "annealed", ...; text).
    source : key of the reference the values come from (``impactlab.references``; "" for
        values given by the user).
    note : what the source gives and how it was read (text).
    brittle : True for a material that cracks rather than yields (glass, ceramics, cemented
        carbides): its ``yield_strength`` holds the compressive strength, and an impact whose
        contact pressure passes its first yield is flagged ``ResultFlag.BRITTLE`` (impactlab
        has no fracture model; ``impactlab.contact.brittle``).

    E, yield_strength, density and brinell_hardness are numbers in the units above, strings
    with units (``"200 GPa"``) or pint Quantities of any registry; nu and meyer_index are plain
    numbers. ValueError unless E, yield_strength, density and brinell_hardness (when given) are
    finite and > 0, nu lies in (-1, 0.5), meyer_index in (2, 3] and yield_strength < E; an
    ImplausibleInputWarning for a value outside :data:`PLAUSIBLE` (most likely a unit left out),
    a ValueError for one :data:`BEYOND_PLAUSIBLE` times below it, and for a number beyond a
    float's range (``10**400``). A name of the library (its key, an alias or its display name)
    with other values is refused (``impactlab.materials.naming``), except on a library entry
    changed in part (``dataclasses.replace``), which is renamed. A material by values
    (``impactlab.get_material``'s text, mapping or TOML form) is also refused when its hardness
    lies below its yield strength (:func:`hardness_below_yield`).
    """

    name: str
    E: float
    nu: float
    yield_strength: float
    brinell_hardness: float = math.nan
    meyer_index: float = 2.2
    density: float | None = None
    condition: str = ""
    source: str = ""
    note: str = field(default="", compare=False, repr=False)
    brittle: bool = False

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name:
            raise ValueError(f"name must be a non-empty string, got {self.name!r}")
        for text in ("condition", "source", "note"):
            if not isinstance(getattr(self, text), str):
                raise ValueError(f"{text} must be a string, got {getattr(self, text)!r}")
        if not isinstance(self.brittle, bool | np.bool_):
            raise ValueError(f"brittle must be True or False, got {self.brittle!r}")
        object.__setattr__(self, "brittle", bool(self.brittle))
        for name, unit in (("E", "Pa"), ("yield_strength", "Pa"), ("density", "kg/m^3")):
            if name == "density" and self.density is None:
                continue
            with _float_range(name, getattr(self, name), unit):
                value = check_positive(name, getattr(self, name), unit)
            object.__setattr__(self, name, value)
        with _float_range("nu", self.nu):
            nu = check_range("nu", self.nu, -1.0, 0.5, low_inclusive=False, high_inclusive=False)
        object.__setattr__(self, "nu", nu)
        hb = self.brinell_hardness  # NaN (any float precision): not given
        if _is_nan(hb):
            hb = math.nan
        else:
            with _float_range("brinell_hardness", hb, _HB):
                hb = check_positive("brinell_hardness", brinell_text(hb), _HB)
        object.__setattr__(self, "brinell_hardness", hb)
        with _float_range("meyer_index", self.meyer_index):
            n = check_finite("meyer_index", self.meyer_index)
        if not 2.0 < n <= 3.0:
            raise ValueError(f"meyer_index must lie in (2, 3], got {n!r}")
        object.__setattr__(self, "meyer_index", n)
        for name, (low, high, unit, _) in PLAUSIBLE.items():
            value = getattr(self, name)
            if value is not None and value < low / BEYOND_PLAUSIBLE:
                raise ValueError(
                    f"material {self.name!r}: {name} = {value!r} {unit} lies below "
                    f"{low / BEYOND_PLAUSIBLE:g} {unit}, {BEYOND_PLAUSIBLE:g} times below the "
                    f"plausible [{low:g}, {high:g}] {unit}: a unit left out or a typo "
                    f"(impactlab reads SI: {unit})"
                )
            if value is not None and not (low <= value <= high or math.isnan(value)):
                warn_implausible(
                    f"material {self.name!r}: {name} = {value!r} {unit} lies outside the "
                    f"plausible range [{low:g}, {high:g}] {unit}; check the units (impactlab "
                    f"takes SI: a bare number is in {unit})"
                )
        if self.yield_strength >= self.E:
            raise ValueError(
                f"yield_strength ({value_text(self.yield_strength, 'Pa')}) must be smaller than "
                f"E ({value_text(self.E, 'Pa')}); check the units"
            )
        if self.yield_strength > MAX_YIELD_STRAIN * self.E:
            warn_implausible(
                f"material {self.name!r}: yield_strength ({value_text(self.yield_strength, 'Pa')})"
                f" is {self.yield_strength / self.E:.3g} of E ({value_text(self.E, 'Pa')}): a "
                f"yield strain above {MAX_YIELD_STRAIN:g}, beyond any solid a drop test strikes "
                "(metals 0.001-0.01, polymers to 0.05); one of them in another unit?"
            )
        self._relabel_if_changed()

    def require_density(self, needed_for: str, instead: str = "") -> float:
        """The density [kg/m^3]; ValueError where it was not given, naming the material,
        ``needed_for`` (what needs it, e.g. "a Sphere's mass from its radius") and ``instead``
        (another way, e.g. "give the Sphere mass= or density=")."""
        if self.density is None:
            other = f"; or {instead}" if instead else ""
            raise ValueError(
                f"material {self.name!r} has no density, which {needed_for} needs: give it "
                "density= (kg/m^3; rho in the text form, e.g. 'E=69GPa, nu=0.33, Sy=276MPa, "
                f"rho=2700kg/m^3'){other}"
            )
        return self.density

    def _relabel_if_changed(self) -> None:
        """A library entry changed in part (``dataclasses.replace(AISI_1010, E=69e9)``: its
        display name and a source) keeps no library label: its name says what changed and the
        entry's source is cleared, so that no result names a library material it did not use;
        such a copy changed again, with a source of one's own or none, is labelled by what
        differs from the entry then (changed back: the entry's name, and its source unless the
        copy was given one). Any other
        material named as a library entry (its key, an alias or its display name) with other
        values is refused (``impactlab.materials.naming.library_name_clash``), as
        ``get_material`` refuses it."""
        from impactlab.materials import naming  # imports the library's names lazily

        relabelled = naming.modified_entry(self.name)
        entry = relabelled or naming.library_entry(self.name)
        if entry is None:
            return
        if relabelled is None and not (self.source and self.name == entry.name):
            clash = naming.library_name_clash(self)
            if clash:
                raise ValueError(clash)
            return
        differ = naming.values_differ  # exactly: a copy that changed anything is another material
        changed = [f for f in naming.COMPARED if differ(getattr(self, f), getattr(entry, f))]
        own = "" if self.source == entry.source else self.source  # a source of one's own
        if changed:
            object.__setattr__(self, "name", f"{entry.name}, modified ({', '.join(changed)})")
            object.__setattr__(self, "source", own)
        elif relabelled is not None:  # changed back: the library entry again
            object.__setattr__(self, "name", entry.name)
            object.__setattr__(self, "source", own or entry.source)

    @property
    def has_hardness(self) -> bool:
        """True when a Brinell hardness is set."""
        return not math.isnan(self.brinell_hardness)

    @property
    def plane_strain_compliance(self) -> float:
        """(1 - nu^2) / E [1/Pa]."""
        return (1.0 - self.nu**2) / self.E

    @property
    def shear_modulus(self) -> float:
        """G = E / (2 (1 + nu)) [Pa]."""
        return self.E / (2.0 * (1.0 + self.nu))

    def _repr_html_(self) -> str:
        return dataclass_html(self)

    def __repr__(self) -> str:
        """A library entry, unchanged: ``get_material('aisi-1010')`` (the call that gives it,
        short enough for a signature in ``help()``); any other material: every field, in SI."""
        library = sys.modules.get("impactlab.materials.library")
        presets: dict[str, Material] = getattr(library, "PRESETS", None) or {}
        key = next((k for k, m in presets.items() if m == self), None)
        if key is not None:
            return f"get_material({key!r})"
        values = ", ".join(
            f"{f}={getattr(self, f)!r}"
            for f in ("name", *_VALUES, "condition", "source", "brittle")
        )
        return f"Material({values})"

    def __str__(self) -> str:
        """One line in display units: ``Material NAME: E = 200 GPa, nu = 0.3, ...``
        (``repr``: the library call of a library entry, else every field in SI)."""
        rows = [
            r
            for r in dataclass_rows(self)
            if r[0] not in ("name", "source", "brittle") and r[1] != ""
        ]
        if self.brittle:
            rows.append(("brittle", "yes", ""))
        return summary_line(f"Material {self.name}", rows)


def reduced_modulus(a: Material, b: Material | None = None) -> float:
    """Reduced (effective) modulus E* = [(1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b]^-1 [Pa].

    With ``b=None`` the second body is rigid: E* = E_a / (1 - nu_a^2).
    """
    c = a.plane_strain_compliance + (b.plane_strain_compliance if b is not None else 0.0)
    return 1.0 / c


def reduced_shear_modulus(a: Material, b: Material | None = None) -> float:
    """Effective shear modulus G* = [(2 - nu_a)/G_a + (2 - nu_b)/G_b]^-1 [Pa] (Mindlin)."""
    c = (2.0 - a.nu) / a.shear_modulus
    if b is not None:
        c += (2.0 - b.nu) / b.shear_modulus
    return 1.0 / c
