"""The resolved material values of every case of a study, for its store: E, nu, the yield
strength, the Brinell hardness, the Meyer index (and the body's density) of the body and the
flat, not only a library name.

A property input that the study sets (fixed, on the grid or sampled: a material by values) is
stored as that input already. Every other property of a side is stored here, under the input's
name (``body_E``, ``flat_yield_strength``, ...), from what the case's material resolves to: the
library material's value (a scalar for one material, or an array along the ``<side>_material``
axis of a grid of materials), or, for a material by values (``custom``), the default of an
optional property the study left unset (Brinell hardness: not set, NaN; Meyer index 2.2). So a
store, its xarray Dataset and any table made from it (``ds.to_dataframe().to_csv(...)``) carry
the material values of every case.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from impactlab.materials import Material, get_material
from impactlab.sweep.inputs import INPUTS, MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.study import Study

__all__ = ["ResolvedValues", "resolved_material_values"]

#: One stored array: (name, values (scalar or 1-D), dimension names, attributes).
ResolvedValues = tuple[str, Any, tuple[str, ...], dict[str, Any]]

#: Defaults of the optional properties of a material by values (``Material``'s own).
_DEFAULTS: dict[str, Any] = {
    f.name: f.default for f in dataclasses.fields(Material) if f.default is not dataclasses.MISSING
}


def _value(side: str, name: str, field: str) -> float:
    """The ``field`` of the material ``name`` of ``side`` (a library name or material text;
    :data:`CUSTOM`: the default of an unset optional property)."""
    if name == CUSTOM:
        return float(_DEFAULTS[field])
    return float(getattr(get_material(name, f"{side}_material"), field))


def _attrs(input_name: str, side: str, field: str, source: str) -> dict[str, Any]:
    spec = INPUTS[input_name]
    desc = spec.description.replace(" (overrides the preset)", "")
    d: dict[str, Any] = {"long_name": f"{desc} (resolved: {source})", "resolved_from": source}
    if spec.unit:
        d["units"] = spec.unit
    if field == "brinell_hardness":
        d["note"] = "NaN: not set (Brake's law refuses the case)"
    return d


def resolved_material_values(study: Study) -> list[ResolvedValues]:
    """The arrays that record the material values of ``study``'s cases beside its inputs
    (module docstring): one per property of each side that the study does not set."""
    given = set(study.fixed) | set(study.varying())
    axes = {a.name: a for a in study.axes}
    out: list[ResolvedValues] = []
    for side, fields in MATERIAL_OVERRIDES.items():
        key = f"{side}_material"
        if key in axes:
            names = [str(v) for v in axes[key].values]
            dims: tuple[str, ...] = (key,)
            source = f"the {key} of each case"
        else:
            names = [str(study.value_of(key))]
            dims = ()
            source = names[0] if names[0] != CUSTOM else "default of a material by values"
        for input_name, field in fields.items():
            if input_name in given:
                continue  # stored as the input itself
            if dims and CUSTOM in names:
                continue  # never so: a material by values is refused beside library names
            values = [_value(side, name, field) for name in names]
            data = np.asarray(values, dtype=np.float64)
            out.append((input_name, data if dims else data[0], dims,
                        _attrs(input_name, side, field, source)))  # fmt: skip
    return out
