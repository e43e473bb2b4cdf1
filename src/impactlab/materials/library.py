"""The material library: common impact materials with cited properties (SI units; Brinell
hardness in kgf/mm^2).

Every entry names its condition (temper, heat treatment, purity) and its source, a key of
``impactlab.references``; the values are the source's, converted to SI, nothing estimated
beyond what ``note`` says. A Brinell hardness the source does not give is left unset (NaN):
Brake's law, the only law that reads it, then refuses the material instead of guessing.

The Meyer index n (Brake's law) is not in these sources: every entry keeps the default 2.2 of
:class:`~impactlab.materials.core.Material` (typical of work-hardened metals); give your own
with a material by values when Brake's law matters.

Brittle materials (tungsten carbide, alumina, glass) crack instead of yielding; the
elastic-plastic laws need a yield strength, and these entries carry the **compressive strength**
there, so that an impact below it is elastic. An impact that reaches it is outside what
impactlab models (no fracture model): these entries are ``brittle``, and a result whose largest
mean contact pressure passes a brittle member's first yield carries ``ResultFlag.BRITTLE`` (not
plain success), whichever of the two yields first (``contact.brittle``: a glass ball on steel
is marked although the steel yields first).

PMMA is a polymer: viscoelastic (its modulus, Poisson's ratio and yield stress depend on the rate
and the temperature), so it lies outside every contact law's fitted range (elastic-plastic,
rate-independent, fitted for metals). Its entry carries the quasi-static values of a data sheet
(ASTM D638/D695 at 23 degC) and the dynamic Poisson's ratio of ultrasonic wave speeds.
"""

from __future__ import annotations

from impactlab.materials.core import Material
from impactlab.references import PAPER

#: Pounds per cubic inch in kg/m^3 and ksi in Pa (the US sources' units), exact: 1 lb =
#: 0.45359237 kg, 1 in = 0.0254 m, 1 lbf = 4.4482216152605 N (as pint converts them, so that a
#: value written in the source's unit is the entry's).
_LB_PER_IN3 = 0.45359237 / 0.0254**3
_KSI = 1000.0 * 4.4482216152605 / 0.0254**2


def _steel(name: str, yield_strength: float, brinell_hardness: float, density: float) -> Material:
    """A steel of the paper's Table 1: E = 200 GPa, nu = 0.3; the Meyer index is not given in
    the paper, 2.2 is a typical value for work-hardened steel."""
    return Material(
        name, 200e9, 0.3, yield_strength, brinell_hardness, 2.2, density, "", PAPER, "Table 1"
    )


#: The paper's rod: AISI 201 stainless steel (Table 1). Unit corrections of the printed table:
#: S_y = 760 MPa (printed "760 GPa"), Brinell hardness 327 kgf/mm^2 (printed "kgf/m^2").
AISI_201 = _steel("AISI 201 stainless steel (paper's rod)", 760e6, 327.0, 7800.0)

#: The paper's flat: AISI 1010 low-carbon steel (Table 1). Unit correction: Brinell hardness
#: 105 kgf/mm^2 (printed "kgf/m^2").
AISI_1010 = _steel("AISI 1010 low-carbon steel (paper's flat)", 305e6, 105.0, 7870.0)

#: Bearing steel AISI 52100, through-hardened (HRC 60-67: beyond the Brinell scale, HB unset).
AISI_52100 = Material(
    "AISI 52100 bearing steel, hardened",
    29.5e3 * _KSI,
    0.30,
    295.0 * _KSI,
    density=0.283 * _LB_PER_IN3,
    condition="hardened, HRC 60-67",
    source="aisi-52100-ball",
    note="nu: 0.30, the upper end of the source's 0.27-0.30",
)

#: Austenitic stainless steel AISI 304, annealed.
AISI_304 = Material(
    "AISI 304 stainless steel, annealed",
    193e9,
    0.29,
    215e6,
    123.0,
    density=8000.0,
    condition="annealed",
    source="matweb-aisi-304",
    note="E: the lower end of the source's 193-200 GPa; HB converted from Rockwell B by MatWeb",
)

#: Aluminium alloy 6061 in the T6 temper.
AL_6061_T6 = Material(
    "aluminium 6061-T6",
    68.9e9,
    0.33,
    276e6,
    95.0,
    density=2700.0,
    condition="T6 (T651)",
    source="matweb-al6061-t6",
    note="HB 95: 500 kg load, 10 mm ball",
)

#: Titanium alloy Ti-6Al-4V (grade 5), annealed.
TI_6AL_4V = Material(
    "Ti-6Al-4V (grade 5), annealed",
    113.8e9,
    0.342,
    880e6,
    334.0,
    density=4430.0,
    condition="annealed",
    source="asm-matweb-ti6al4v",
    note="HB estimated from Rockwell C 36 by the source",
)

#: Free-cutting brass C36000, half hard.
BRASS_C360 = Material(
    "C36000 free-cutting brass, half hard",
    14000.0 * _KSI,
    0.31,
    45.0 * _KSI,
    density=0.307 * _LB_PER_IN3,
    condition="half hard (H02)",
    source="cda-c36000",
    note="1 in rod; no Brinell hardness in the source (Rockwell B 78)",
)

#: Oxygen-free high-conductivity copper (C10200), annealed.
COPPER_OFHC = Material(
    "OFHC copper, annealed",
    117e9,
    0.34,
    48e6,
    42.0,
    density=8940.0,
    condition="annealed",
    source="smithells-2004-copper",
    note="annealed (O) strip; S_y: the 0.2 % proof stress",
)

#: Tungsten carbide (cemented WC); brittle: yield_strength is the compressive strength.
TUNGSTEN_CARBIDE = Material(
    "tungsten carbide (WC)",
    630e9,
    0.24,
    4780e6,
    density=15000.0,
    condition="sintered",
    source="makeitfrom-wc",
    brittle=True,
    note="brittle: yield_strength holds the compressive strength; density as rounded by the "
    "source (15 g/cm^3)",
)

#: Alumina, 99.5 % or higher, sintered; brittle: yield_strength is the compressive strength.
ALUMINA_995 = Material(
    "alumina 99.5 %",
    416e9,
    0.23,
    3.0e9,
    density=3984.0,
    condition="sintered",
    source="nist-srd30-alumina",
    brittle=True,
    note=">= 99.5 % Al2O3, >= 98 % dense; brittle: yield_strength holds the compressive "
    "strength; nu: the middle of 0.22-0.24",
)

#: Soda-lime glass, annealed; brittle: yield_strength is the compressive strength.
SODA_LIME_GLASS = Material(
    "soda-lime glass, annealed",
    72e9,
    0.23,
    330e6,
    density=2520.0,
    condition="annealed",
    source="makeitfrom-soda-lime",
    brittle=True,
    note="brittle: yield_strength holds the compressive strength",
)

#: Ultrasonic wave speeds of Lucite (PMMA) [m/s]: longitudinal v_l, shear v_s (CRC Handbook,
#: "Speed of sound in various media", Table 1).
PMMA_WAVE_SPEEDS = (2680.0, 1100.0)


def dynamic_poisson_ratio(v_longitudinal: float, v_shear: float) -> float:
    """Poisson's ratio of an isotropic solid from its bulk longitudinal and shear wave speeds
    [m/s]: ``nu = (v_l^2 - 2 v_s^2) / (2 (v_l^2 - v_s^2))`` (exact for linear elasticity; the
    *dynamic* nu at the waves' frequency). ValueError unless 0 < v_s < v_l."""
    if not 0.0 < v_shear < v_longitudinal:
        raise ValueError(
            f"wave speeds must satisfy 0 < v_shear < v_longitudinal, got v_longitudinal="
            f"{v_longitudinal!r} m/s, v_shear={v_shear!r} m/s"
        )
    vl2, vs2 = v_longitudinal**2, v_shear**2
    return (vl2 - 2.0 * vs2) / (2.0 * (vl2 - vs2))


#: PMMA (acrylic sheet); a viscoelastic polymer, outside every contact law's fitted range.
PMMA = Material(
    "PMMA (acrylic sheet)",
    2800e6,
    round(dynamic_poisson_ratio(*PMMA_WAVE_SPEEDS), 3),
    117e6,
    density=1190.0,
    condition="sheet, 23 degC",
    source="usplastic-acrylic-sheet",
    note="polymer, viscoelastic: outside every contact law's fitted range; E (ASTM D638) and "
    "S_y = compressive yield strength (ASTM D695, whose standard test runs at 1.3 mm/min and "
    "23 degC) of the data sheet; nu = 0.399: dynamic, from the ultrasonic wave speeds of the "
    "CRC Handbook (crc-sound-speed); no Brinell hardness in the sources (Rockwell M 93)",
)

#: The library by name (the names ``impactlab materials`` lists).
PRESETS: dict[str, Material] = {
    "aisi-201": AISI_201,
    "aisi-1010": AISI_1010,
    "aisi-52100": AISI_52100,
    "aisi-304": AISI_304,
    "al-6061-t6": AL_6061_T6,
    "ti-6al-4v": TI_6AL_4V,
    "brass-c360": BRASS_C360,
    "copper-ofhc": COPPER_OFHC,
    "tungsten-carbide": TUNGSTEN_CARBIDE,
    "alumina-99.5": ALUMINA_995,
    "soda-lime-glass": SODA_LIME_GLASS,
    "pmma": PMMA,
}

#: Other spellings of the library's names.
ALIASES: dict[str, str] = {
    "201": "aisi-201",
    "aisi201": "aisi-201",
    "1010": "aisi-1010",
    "aisi1010": "aisi-1010",
    "52100": "aisi-52100",
    "304": "aisi-304",
    "ss304": "aisi-304",
    "6061-t6": "al-6061-t6",
    "al6061-t6": "al-6061-t6",
    "aluminium-6061-t6": "al-6061-t6",
    "aluminum-6061-t6": "al-6061-t6",
    "ti64": "ti-6al-4v",
    "c360": "brass-c360",
    "c36000": "brass-c360",
    "ofhc": "copper-ofhc",
    "c10200": "copper-ofhc",
    "wc": "tungsten-carbide",
    "alumina": "alumina-99.5",
    "al2o3": "alumina-99.5",
    "glass": "soda-lime-glass",
    "acrylic": "pmma",
    "plexiglas": "pmma",
    "plexiglass": "pmma",
    "perspex": "pmma",
    "lucite": "pmma",
}

#: The library's materials that crack instead of yielding (``Material.brittle``;
#: yield_strength: the compressive strength).
BRITTLE: frozenset[str] = frozenset(key for key, m in PRESETS.items() if m.brittle)
