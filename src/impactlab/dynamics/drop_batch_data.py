"""The columns of ``DropBatchResult`` (``simulate_drops``): their public names, SI units and
meanings, and the batch as a pandas DataFrame or an xarray Dataset (the conventions of
``BatchResult``'s, ``dynamics.export``)."""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab import schema
from impactlab._version import __version__
from impactlab.dynamics.batch_fields import with_units
from impactlab.dynamics.batch_status import INTEGER_FIELDS, integer_series
from impactlab.dynamics.drop_checks import DROP_STATUS_MESSAGES
from impactlab.dynamics.export import flag_attrs, status_attrs
from impactlab.dynamics.flexcore import layout as F

__all__ = [
    "DATASET_OUTPUTS",
    "DROP_BATCH_FIELDS",
    "ENGINE_NAME",
    "PUBLIC_FIELDS",
    "drop_columns",
    "drop_dataframe",
    "drop_dataset",
    "output_unit",
]

#: The outputs of each case, in the columns of ``DropBatchResult.out`` (the engine's names).
DROP_BATCH_FIELDS = F.DROP_OUTPUT_FIELDS
#: The public name of each column, as ``DropResult`` has them (the sequence totals renamed,
#: ``schema.RENAMED_DROP_FIELDS``), and the ratio ``sequence_mean_force``.
PUBLIC_FIELDS = (
    *(schema.RENAMED_DROP_FIELDS.get(n, n) for n in DROP_BATCH_FIELDS),
    "sequence_mean_force",
)
ENGINE_NAME = {new: old for old, new in schema.RENAMED_DROP_FIELDS.items()}
#: The outputs of ``to_pint`` (and, with ``flags`` and the derived ones, of ``to_xarray`` and
#: ``to_dataframe``: :func:`drop_columns`).
DATASET_OUTPUTS = (*PUBLIC_FIELDS, "initial_energy", "max_delta_ratio")
#: The engine's own unit and meaning of each column (``flexcore.layout.DROP_FIELDS``).
_ENGINE_FIELDS = {f.name: f for f in F.DROP_FIELDS}


def output_unit(name: str) -> tuple[str, str]:
    """(SI unit, meaning) of an output of ``DropBatchResult`` (``impactlab.schema``, else the
    engine's column: ``n_jumps``, ``n_dents``, ``t_final``)."""
    try:
        return schema.unit(name), schema.DROP_MEANINGS.get(name) or schema.description(name)
    except KeyError:
        f = _ENGINE_FIELDS[ENGINE_NAME.get(name, name)]
        return f.unit, f.description


def drop_columns() -> tuple[str, ...]:
    """The output columns of ``to_dataframe`` and ``to_xarray``, in the order of
    ``BatchResult``'s (``export.batch_columns``): the outputs (``PUBLIC_FIELDS``,
    ``initial_energy``), ``flags``, the derived ones (``schema.register_output``),
    ``max_delta_ratio``, ``status``."""
    return (
        *PUBLIC_FIELDS, "initial_energy", "flags", *schema.DERIVED_FIELDS, "max_delta_ratio",
        "status",
    )  # fmt: skip


def drop_dataset(drops: Any) -> Any:
    """``DropBatchResult.to_xarray``: the conventions of ``export.batch_dataset``, the columns
    of :func:`drop_dataframe`; the batch's ``setup`` and ``impactlab_version`` in the
    attributes."""
    import xarray as xr  # heavy, needed only here

    status = np.asarray(drops.status)
    failed = status != 0
    variables: dict[str, Any] = {}
    for name, v in drops.inputs.items():
        unit, meaning = output_unit(name)
        variables[name] = ("case", np.array(v), {"units": unit, "long_name": f"input: {meaning}"})
    for name in drop_columns():
        if name == "status":
            variables[name] = ("case", status.astype(np.int32), status_attrs(DROP_STATUS_MESSAGES))
            continue
        unit, meaning = output_unit(name)
        attrs: dict[str, Any] = {"units": unit, "long_name": meaning}
        if name == "flags":
            values = np.where(failed, -1, np.asarray(drops.flags)).astype(np.int64)
            attrs |= flag_attrs() | {"comment": "-1: the case failed (see status)"}
        elif name in INTEGER_FIELDS:  # counts, and next_end (-1: no end lands next)
            attrs["comment"] = "-2: the case failed (see status)"
            values = np.where(failed, -2, np.array(drops[name], dtype=np.float64))
            values = values.astype(np.int64)
        else:
            values = np.array(drops[name], dtype=np.float64)
        variables[name] = ("case", values, attrs)
    attrs = {**drops.setup, "body": drops.body, "law": drops.law, "friction": drops.friction}
    attrs |= {"gravity": drops.gravity, "rtol": drops.rtol}
    attrs |= {"references": [r.key for r in drops.references]}
    attrs |= {"dois": [r.doi for r in drops.references if r.doi]}
    attrs |= {"source": "impactlab.simulate_drops", "impactlab_version": __version__}
    if drops.law_range is not None:
        attrs["law_range"] = drops.law_range
    return xr.Dataset(variables, coords={"case": np.arange(status.shape[0])}, attrs=attrs)


def drop_dataframe(drops: Any) -> Any:
    """``DropBatchResult.to_dataframe``: inputs and the columns of :func:`drop_columns` (those
    of ``to_xarray``, in its order) per case; SI units in ``df.attrs["units"]`` (column ->
    unit, :func:`output_unit`); counts, codes and ``flags`` as nullable integers, ``<NA>``
    where a case failed."""
    import pandas as pd  # heavy, needed only here

    df = pd.DataFrame({k: np.array(v) for k, v in drops.inputs.items()})
    for name in drop_columns():
        if name == "status":
            df[name] = np.array(drops.status)
        elif name == "flags":
            df[name] = integer_series(drops.flags, drops.computed)
        elif name in INTEGER_FIELDS:
            df[name] = integer_series(drops[name], drops.computed)
        else:
            df[name] = np.array(drops[name])
    return with_units(df, lambda name: output_unit(name)[0])
