"""Materials, contact pairs and the material library (SI units throughout).

- :class:`Material` (``impactlab.materials.core``), :class:`ContactPair`
  (``impactlab.materials.pair``, with the rule of which body yields first,
  :func:`body_yields_first`), the reduced moduli;
- the library of common impact materials with cited properties (``impactlab.materials.library``):
  :data:`PRESETS` by name, the paper's :data:`AISI_201` and :data:`AISI_1010` and the others;
- :func:`get_material`: a material from a library name, a definition by values
  (``"E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"``) or a TOML file
  (``impactlab.materials.inputs``), the one reader of every command and study file.
"""

from __future__ import annotations

from impactlab.materials.core import (
    G0,
    Material,
    brinell_to_pa,
    reduced_modulus,
    reduced_shear_modulus,
    summary_line,
)
from impactlab.materials.inputs import get_material, library_key
from impactlab.materials.library import (
    AISI_201,
    AISI_304,
    AISI_1010,
    AISI_52100,
    AL_6061_T6,
    ALIASES,
    ALUMINA_995,
    BRASS_C360,
    BRITTLE,
    COPPER_OFHC,
    PMMA,
    PRESETS,
    SODA_LIME_GLASS,
    TI_6AL_4V,
    TUNGSTEN_CARBIDE,
    dynamic_poisson_ratio,
)
from impactlab.materials.pair import ContactPair, body_yields_first, first_yield_factor

__all__ = [
    "AISI_201",
    "AISI_304",
    "AISI_1010",
    "AISI_52100",
    "ALIASES",
    "ALUMINA_995",
    "AL_6061_T6",
    "BRASS_C360",
    "BRITTLE",
    "COPPER_OFHC",
    "G0",
    "PMMA",
    "PRESETS",
    "SODA_LIME_GLASS",
    "TI_6AL_4V",
    "TUNGSTEN_CARBIDE",
    "ContactPair",
    "Material",
    "body_yields_first",
    "brinell_to_pa",
    "dynamic_poisson_ratio",
    "first_yield_factor",
    "get_material",
    "library_key",
    "reduced_modulus",
    "reduced_shear_modulus",
    "summary_line",
]
