"""The seed paper's data, transcribed once, with the corrections it needs recorded as data.

H. Ghaednia, D. B. Marghitu, R. L. Jackson, "Permanent deformation during the oblique impact with
friction", Archive of Applied Mechanics 86 (2016) 121-134, doi:10.1007/s00419-015-1108-2.

Everything is in SI (m, s, N, kg, rad) except where a field name says otherwise (``angle_deg``).
Signs follow the paper's tables: dent depth ``delta_p`` and sliding length ``L_s`` negative, drop
velocity ``v_i`` negative. Where the paper's text and tables disagree, both values are kept (see
:data:`DISCREPANCIES` and :data:`TEXT_ROWS`); nothing here is silently resolved. The derivations
behind the corrections are in ``docs/paper/errata.md``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from impactlab.bodies import PAPER_ROD as PAPER_ROD  # Table 1's rod, I_C = m L^2 / 12
from impactlab.materials import AISI_201, AISI_1010, Material

DOI = "10.1007/s00419-015-1108-2"
CITATION = (
    "H. Ghaednia, D. B. Marghitu, R. L. Jackson, Permanent deformation during the oblique impact "
    "with friction, Archive of Applied Mechanics 86 (2016) 121-134, doi:10.1007/s00419-015-1108-2"
)

#: Contact laws the paper simulates (impactlab registry names), in the tables' row order.
PAPER_LAWS: tuple[str, ...] = ("ghaednia", "brake", "kogut-komvopoulos")

#: The paper's impact angles [deg].
ANGLES_DEG: tuple[int, ...] = (20, 45, 70)


# --------------------------------------------------------------------------------------------
# Table 1
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Table1Entry:
    """One printed entry of Table 1 and its SI value (with the correction applied, if any)."""

    body: str  # "rod" or "flat"
    symbol: str
    printed: str  # as printed, value and unit
    value: float  # SI (hardness: kgf/mm^2, the Brinell number)
    unit: str
    correction: str = ""


TABLE1: tuple[Table1Entry, ...] = (
    Table1Entry(
        "rod",
        "R",
        "0.0088 (m)",
        0.0088,
        "m",
        "radius of curvature of the tip, not the rod's radius (see m)",
    ),
    Table1Entry("rod", "L", "0.3048 (m)", 0.3048, "m"),
    Table1Entry(
        "rod",
        "m",
        "0.4607 (kg)",
        0.4607,
        "kg",
        "a solid 17.6 mm rod of 0.3048 m would weigh 0.578 kg; 0.4607 kg fits a 5/8 in "
        "(15.9 mm) rod with rounded ends (0.462 kg), so R is the tip's curvature radius",
    ),
    Table1Entry("rod", "rho", "7800 (kg/m^3)", 7800.0, "kg/m^3"),
    Table1Entry("rod", "E_r", "200 (GPa)", 200e9, "Pa"),
    Table1Entry(
        "rod",
        "S_yr",
        "760 (GPa)",
        760e6,
        "Pa",
        "760 MPa: a 760 GPa yield strength would exceed E (units typo)",
    ),
    Table1Entry(
        "rod",
        "H_r",
        "327 (kgf/m^2)",
        327.0,
        "kgf/mm^2",
        "Brinell number HB 327 in kgf/mm^2, 3.21 GPa (printed kgf/m^2, off by 1e6)",
    ),
    Table1Entry("rod", "nu_r", "0.3", 0.3, "-"),
    Table1Entry("flat", "rho", "7870 (kg/m^3)", 7870.0, "kg/m^3"),
    Table1Entry("flat", "E_f", "200 (GPa)", 200e9, "Pa"),
    Table1Entry("flat", "S_yf", "305 (MPa)", 305e6, "Pa", "printed with a stray superscript 5"),
    Table1Entry(
        "flat",
        "H_f",
        "105 (kgf/m^2)",
        105.0,
        "kgf/mm^2",
        "Brinell number HB 105 in kgf/mm^2, 1.03 GPa (printed kgf/m^2)",
    ),
    Table1Entry("flat", "nu_f", "0.3", 0.3, "-"),
)

#: The rod's material (AISI 201) and the flat's (AISI 1010), Table 1 with corrections.
ROD_MATERIAL: Material = AISI_201
FLAT_MATERIAL: Material = AISI_1010


# --------------------------------------------------------------------------------------------
# The experiments (Sec. 5.1.3)
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Experiment:
    """One drop of the paper (Sec. 5.1.3). SI; paper signs (v_i, delta_p, L_s negative)."""

    key: str
    angle_deg: float
    v_i: float  # vertical tip velocity before impact [m/s]
    v_rebound: float  # normal rebound velocity of the tip [m/s] (printed v_Of)
    e: float  # printed coefficient of restitution
    mu: float  # printed mean friction coefficient (Eq. 28)
    delta_p: float  # permanent dent depth [m]
    L_s: float  # sliding length [m]
    figure: str
    source: str = "Sec. 5.1.3"

    @property
    def angle(self) -> float:
        """Impact angle [rad]."""
        return math.radians(self.angle_deg)

    @property
    def e_from_velocities(self) -> float:
        """v_Of / |v_i| from the printed velocities (compare with the printed e)."""
        return self.v_rebound / abs(self.v_i)


EXPERIMENTS: Mapping[int, Experiment] = MappingProxyType(
    {
        20: Experiment("paper-20", 20.0, -1.41, 0.71, 0.50, 0.20, -22e-6, -1400e-6, "Fig. 6"),
        45: Experiment("paper-45", 45.0, -2.18, 1.08, 0.49, 0.13, -26e-6, -1650e-6, "Fig. 7"),
        70: Experiment("paper-70", 70.0, -3.45, 0.19, 0.05, 0.10, -105e-6, -200e-6, "Fig. 8"),
    }
)

#: Case names for the command line: ``paper-20``, ``paper-45``, ``paper-70``.
CASES: Mapping[str, Experiment] = MappingProxyType({x.key: x for x in EXPERIMENTS.values()})


def get_case(name: str) -> Experiment:
    """The experiment called ``name`` (``paper-20`` ...); ValueError listing the known names."""
    try:
        return CASES[name]
    except KeyError:
        raise ValueError(f"unknown case {name!r}; known cases: {', '.join(CASES)}") from None


# --------------------------------------------------------------------------------------------
# Published rows of Tables 2 and 3 and the text of Sec. 5.2
# --------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class PublishedRow:
    """A published result row. SI: delta_p, L_s [m], T [s], F [N]; None where not printed."""

    table: str  # "Table 2", "Table 3" or "Sec. 5.2 text"
    angle_deg: float
    model: str  # "experiment" or a law name of PAPER_LAWS
    delta_p: float | None
    L_s: float | None
    e: float | None
    T: float | None
    F: float | None
    note: str = ""


TABLE_ROWS: tuple[PublishedRow, ...] = (
    # Table 2, 20 deg
    PublishedRow(
        "Table 2",
        20,
        "experiment",
        -22e-6,
        -1400e-6,
        0.50,
        4.30e-3,
        79.0,
        "T and F from Eqs. 12 and 29 applied to the measurements",
    ),
    PublishedRow("Table 2", 20, "ghaednia", -67e-6, -74e-6, 0.42, 0.25e-3, 2571.0),
    PublishedRow("Table 2", 20, "brake", -77e-6, -75e-6, 0.46, 0.29e-3, 2153.0),
    PublishedRow("Table 2", 20, "kogut-komvopoulos", -64e-6, -64e-6, 0.43, 0.25e-3, 2568.0),
    # Table 3, 45 deg
    PublishedRow(
        "Table 3",
        45,
        "experiment",
        -26e-6,
        -1650e-6,
        0.49,
        1.40e-3,
        595.0,
        "T printed 'l.40' (letter l), read as 1.40 ms",
    ),
    PublishedRow(
        "Table 3",
        45,
        "ghaednia",
        -67e-6,
        -74e-6,
        0.41,
        0.30e-3,
        5041.0,
        "delta_p and L_s repeat Table 2's Ghaednia row",
    ),
    PublishedRow("Table 3", 45, "brake", -150e-6, -370e-6, 0.41, 0.36e-3, 4178.0),
    PublishedRow("Table 3", 45, "kogut-komvopoulos", -120e-6, -638e-6, 0.43, 0.30e-3, 4805.0),
)

#: The numbers Sec. 5.2 prints for the 20 deg simulations (they disagree with Table 2 in places).
TEXT_ROWS: tuple[PublishedRow, ...] = (
    PublishedRow("Sec. 5.2 text", 20, "ghaednia", -67e-6, -74e-6, 0.42, 0.256e-3, 2153.0),
    PublishedRow("Sec. 5.2 text", 20, "brake", -77e-6, -74e-6, 0.46, 0.256e-3, 2153.0),
    PublishedRow(
        "Sec. 5.2 text",
        20,
        "kogut-komvopoulos",
        -64e-6,
        -64e-6,
        0.43,
        0.25e-3,
        2568.0,
        "e printed with a hat",
    ),
)


@dataclass(frozen=True)
class Discrepancy:
    """A place where the paper contradicts itself; ``values`` keeps every printed version."""

    key: str
    where: str
    quantity: str
    values: Mapping[str, float | str] = field(default_factory=dict)
    note: str = ""


DISCREPANCIES: tuple[Discrepancy, ...] = (
    Discrepancy(
        "ghaednia-20-F",
        "Table 2 vs Sec. 5.2",
        "F [N] (Ghaednia, 20 deg)",
        MappingProxyType({"Table 2": 2571.0, "Sec. 5.2 text": 2153.0}),
        "the text's value equals Brake's Table 2 force; kept both",
    ),
    Discrepancy(
        "ghaednia-20-T",
        "Table 2 vs Sec. 5.2",
        "T [ms] (Ghaednia, 20 deg)",
        MappingProxyType({"Table 2": 0.25, "Sec. 5.2 text": 0.256}),
        "0.256 rounds to 0.26, not 0.25",
    ),
    Discrepancy(
        "brake-20-T",
        "Table 2 vs Sec. 5.2",
        "T [ms] (Brake, 20 deg)",
        MappingProxyType({"Table 2": 0.29, "Sec. 5.2 text": 0.256}),
        "the text repeats the Ghaednia duration for Brake",
    ),
    Discrepancy(
        "brake-20-Ls",
        "Table 2 vs Sec. 5.2",
        "L_s [um] (Brake, 20 deg)",
        MappingProxyType({"Table 2": -75.0, "Sec. 5.2 text": -74.0}),
    ),
    Discrepancy(
        "ghaednia-45-repeat",
        "Table 3",
        "delta_p, L_s [um] (Ghaednia, 45 deg)",
        MappingProxyType({"Table 3": "-67, -74", "Table 2 (20 deg)": "-67, -74"}),
        "Table 3's Ghaednia row repeats Table 2's dent; every other 45 deg row differs "
        "from its 20 deg row, so this is most likely a copy error",
    ),
    Discrepancy(
        "exp-45-T",
        "Table 3",
        "T [ms] (experiment, 45 deg)",
        MappingProxyType({"Table 3": "l.40"}),
        "letter l for digit 1: 1.40 ms",
    ),
    Discrepancy(
        "table-4-missing",
        "Table 4",
        "70 deg comparison",
        MappingProxyType({"Table 4": "caption only"}),
        "Table 4 has no rows; the 70 deg measurements are only in Sec. 5.1.3 and the "
        "text of Sec. 5.2 describes results that are not printed",
    ),
    Discrepancy(
        "exp-signs",
        "Sec. 5.1.3 vs Tables 2-3",
        "delta_p, L_s signs",
        MappingProxyType({"Sec. 5.1.3": "+22, +1400 um", "Table 2": "-22, -1400 um"}),
        "the text gives magnitudes, the tables signed values (tip below the surface, "
        "sliding towards -x)",
    ),
    Discrepancy(
        "exp-20-vi-direction",
        "Sec. 5.1.3",
        "v_i direction (20 deg)",
        MappingProxyType({"printed": "-1.41 i m/s", "elsewhere": "-1.41 j m/s"}),
        "unit vector typo: the drop is vertical (j)",
    ),
    Discrepancy(
        "exp-45-e",
        "Sec. 5.1.3",
        "e (45 deg)",
        MappingProxyType({"printed e": 0.49, "v_Of / |v_i|": 1.08 / 2.18}),
        "1.08/2.18 = 0.4954 rounds to 0.50; over the rounding of v_Of and v_i it lies in 0.492 "
        "to 0.499, meeting the printed 0.49 (0.485 to 0.495) only at its edge",
    ),
    Discrepancy(
        "exp-70-e",
        "Sec. 5.1.3",
        "e (70 deg)",
        MappingProxyType({"printed e": 0.05, "v_Of / |v_i|": 0.19 / 3.45}),
        "0.19/3.45 = 0.055; over the rounding of v_Of and v_i it lies in 0.0535 to 0.0566, "
        "meeting the printed 0.05 (0.045 to 0.055) only at its edge",
    ),
    Discrepancy(
        "table-headers",
        "Tables 2-3",
        "column headers",
        MappingProxyType({"printed": "delta_n; Table 2 has no header over e"}),
        "delta_n is the permanent depth delta_p of the text",
    ),
    Discrepancy(
        "alpha-sign",
        "Sec. 5.3 vs Eq. 13 and Tables",
        "sign of alpha",
        MappingProxyType({"Sec. 5.3": "alpha positive", "Eq. 13 (corrected)": "negative"}),
        "with the tables' negative L_s, Eq. 12 needs L_s = +alpha (delta_p - v_i T) and a "
        "negative alpha; see docs/paper/errata.md",
    ),
)


def published_rows(angle_deg: float | None = None) -> tuple[PublishedRow, ...]:
    """The rows of Tables 2 and 3 (optionally for one angle)."""
    return tuple(r for r in TABLE_ROWS if angle_deg is None or r.angle_deg == angle_deg)


def published_row(angle_deg: float, model: str) -> PublishedRow | None:
    """The table row for ``angle_deg`` and ``model`` (None where the paper prints none: 70 deg)."""
    for r in TABLE_ROWS:
        if r.angle_deg == angle_deg and r.model == model:
            return r
    return None
