"""Results as data-science objects: a history as a pandas DataFrame with units and categorical
columns, a batch as an xarray Dataset, and the batch's notebook (HTML) summary.

Units and descriptions come from ``impactlab.schema``; coded columns keep their codes and say
what they mean in CF-style attributes (``flag_values`` / ``flag_masks`` and ``flag_meanings``,
as in a sweep store). ``ImpactResult``/``BatchResult``/``History``
call these functions from one-line methods (``History.to_dataframe``, ``BatchResult.to_xarray``,
``BatchResult._repr_html_``).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab import schema
from impactlab._display import display_unit, format_number
from impactlab._html import grid_html
from impactlab._version import __version__
from impactlab.dynamics.batch_fields import batch_counts
from impactlab.dynamics.kernels.layout import (
    HISTORY_FIELDS,
    OUTPUT_FIELDS,
)
from impactlab.dynamics.kernels.status import REGIME_NAMES, STATUS_MESSAGES
from impactlab.flags import ResultFlag, messages
from impactlab.references import Reference

__all__ = [
    "BATCH_DIAGNOSTICS",
    "HISTORY_CATEGORIES",
    "batch_columns",
    "batch_dataset",
    "batch_html",
    "batch_setup",
    "flag_attrs",
    "history_dataframe",
    "history_units",
    "status_attrs",
]

#: The coded history columns and the names of their codes (0, 1): categorical in a DataFrame.
HISTORY_CATEGORIES: dict[str, tuple[str, str]] = {
    "phase": ("loading", "unloading"),
    "stick": ("slip", "stick"),
}

#: Outputs of a batch stored as integer codes (with their meanings in the attributes).
_CODED = ("regime", "flags", "n_steps")

#: Outputs a batch's notebook summary shows (min, median, max over the ok cases).
_SUMMARY = ("e", "delta_p", "sliding_length", "duration", "mean_force", "max_force")

#: The engine's diagnostic outputs, which ``simulate_batch`` does not compute (a sweep that
#: keeps one does, ``run_arrays(diagnostics=True)``): NaN in every case of a ``BatchResult``,
#: so its ``to_dataframe``, ``to_xarray`` and ``to_pint`` leave them out.
BATCH_DIAGNOSTICS = ("energy_rise", "friction_excess")


def history_units() -> dict[str, str]:
    """SI unit of every history column (``"1"`` for dimensionless), from the schema."""
    return {name: schema.unit(name) for name in HISTORY_FIELDS}


def history_dataframe(data: np.ndarray) -> Any:
    """The history array (rows x ``HISTORY_FIELDS``) as a pandas DataFrame: SI values, units in
    ``df.attrs["units"]`` (column -> unit), ``phase`` and ``stick`` as categoricals
    (``HISTORY_CATEGORIES``)."""
    import pandas as pd  # heavy, needed only here

    df = pd.DataFrame(np.array(data), columns=list(HISTORY_FIELDS))
    for name, labels in HISTORY_CATEGORIES.items():
        codes = np.asarray(df[name].to_numpy(), dtype=np.int64)
        df[name] = pd.Categorical.from_codes(codes, categories=list(labels))
    df.attrs["units"] = history_units()
    return df


def _regime_attrs() -> dict[str, Any]:
    return {
        "flag_values": sorted(REGIME_NAMES),
        "flag_meanings": " ".join(REGIME_NAMES[k] for k in sorted(REGIME_NAMES)),
    }


def flag_attrs() -> dict[str, Any]:
    """The attributes of a ``flags`` variable: the bits, their names and messages (CF
    ``flag_masks``/``flag_meanings``)."""
    bits = [f for f in ResultFlag if f.value]
    return {
        "flag_masks": [int(f) for f in bits],
        "flag_meanings": " ".join(str(f.name).lower() for f in bits),
        "flag_messages": [messages(f)[0] for f in bits],
    }


def status_attrs(texts: Mapping[int, str] = STATUS_MESSAGES) -> dict[str, Any]:
    """The attributes of a ``status`` variable: the codes and their ``texts`` (CF
    ``flag_values``/``flag_meanings``; a drop's name its own rtol range)."""
    codes = sorted(texts)
    return {
        "long_name": "engine status of the case (0: finished, the flags say if ok; "
        "other codes: no result, NaN outputs)",
        "flag_values": codes,
        "flag_meanings": " ".join(f"status_{c}" for c in codes),
        # status 0 reads "finished", as in a sweep store: whether a result is ok is the flags'
        "status_messages": ["finished" if c == 0 else texts[c] for c in codes],
    }


def _output_var(name: str, values: np.ndarray, ok: np.ndarray) -> tuple[Any, ...]:
    attrs: dict[str, Any] = {"units": schema.unit(name), "long_name": schema.description(name)}
    if name not in _CODED:
        return ("case", np.array(values, dtype=np.float64), attrs)
    codes = np.where(ok & np.isfinite(values), values, -1).astype(np.int64)
    if name == "regime":
        attrs.update(_regime_attrs())
    elif name == "flags":
        attrs.update(flag_attrs())
    attrs["comment"] = "-1: the case failed (see status)"
    return ("case", codes, attrs)


def batch_setup(
    body: Any,
    flat: Any,
    *,
    friction: str,
    gravity: Any,
    rtol: float | None,
    constant_angle: bool | None,
    law: Any = None,
    law_params: Mapping[str, Any] | None = None,
    partial_slip_cells: int | None = None,
) -> dict[str, Any]:
    """What a batch simulated besides its per-case inputs, as attributes that netCDF stores
    (strings and numbers, as a sweep store's): ``body`` and ``flat`` (their descriptions),
    ``body_record`` and ``flat_record`` (each as JSON text, the form of a result's ``input``:
    ``impactlab.dynamics.provenance``), ``gravity`` [m/s^2], ``rtol`` (the tolerance used),
    ``constant_angle`` (0 or 1; None, a drop's batch: left out), ``partial_slip_cells`` (the
    cells used, for ``friction="partial_slip"`` when given) and, when given, ``law_params``
    (JSON text, in the units of ``law``'s parameters, as a result's ``input`` records them)."""
    import json

    from impactlab.dynamics.checks import impact_rtol
    from impactlab.dynamics.input_checks import gravity_value
    from impactlab.dynamics.provenance import law_params_record

    if rtol is None:
        rtol = impact_rtol(friction)
    body_text, body_record = _described(body)
    setup: dict[str, Any] = {
        "body": body_text,
        "body_record": body_record,
        "flat": str(flat.name),
        "flat_record": _described(flat)[1],
        "gravity": gravity_value(gravity),
        "rtol": float(rtol),
    }
    if constant_angle is not None:
        setup["constant_angle"] = int(bool(constant_angle))
    if partial_slip_cells is not None and friction == "partial_slip":
        setup["partial_slip_cells"] = int(partial_slip_cells)
    if law_params:
        setup["law_params"] = json.dumps(law_params_record(law, law_params))
    return setup


#: id(a body or a flat) -> (it, its description, its record as JSON text): a batch's setup
#: describes the same few frozen objects call after call (0.3 ms of a 16-impact batch's 0.7).
#: Held by identity, not by value: a Material's ``note`` is recorded but not compared.
_DESCRIBED: dict[int, tuple[Any, str, str]] = {}


def _described(obj: Any) -> tuple[str, str]:
    """(``str(obj)``, ``json.dumps(encode(obj))``) of a frozen body or material, cached."""
    hit = _DESCRIBED.get(id(obj))
    if hit is not None and hit[0] is obj:
        return hit[1], hit[2]
    import json

    from impactlab.dynamics.provenance import encode

    text, record = str(obj), json.dumps(encode(obj))
    if len(_DESCRIBED) >= 64:
        _DESCRIBED.clear()
    _DESCRIBED[id(obj)] = (obj, text, record)
    return text, record


def batch_columns(batch: Any) -> tuple[str, ...]:
    """The output columns of a ``BatchResult``'s ``to_dataframe`` and ``to_xarray``, in order:
    the engine's outputs (``OUTPUT_FIELDS`` but :data:`BATCH_DIAGNOSTICS`), the derived ones
    (``schema.register_output``), ``max_delta_ratio`` (when computed), ``status``."""
    outputs = [n for n in OUTPUT_FIELDS if n not in BATCH_DIAGNOSTICS]
    ratio = () if batch.max_delta_ratio is None else ("max_delta_ratio",)
    return (*outputs, *schema.DERIVED_FIELDS, *ratio, "status")


def batch_dataset(batch: Any) -> Any:
    """A ``BatchResult`` as an ``xarray.Dataset`` over the dimension ``case``: every input and
    output (:func:`batch_columns`, the columns of ``to_dataframe``; SI, ``units`` and
    ``long_name`` attributes), ``max_delta_ratio``, ``status``, and
    ``regime``/``flags`` as integer codes whose meanings are in their attributes (-1 where the
    case failed); the dataset's attributes say what was simulated (law, friction, the batch's
    ``setup``: :func:`batch_setup`), the sources and ``impactlab_version``. Every attribute is
    a number, a string or a list of them: ``ds.to_netcdf(path)`` writes it as it is."""
    import xarray as xr  # heavy, needed only here

    status, out = np.asarray(batch.status), np.asarray(batch.out)
    ok = status == 0
    n = int(status.shape[0])
    variables: dict[str, Any] = {}
    for name, v in batch.inputs.items():
        column = np.broadcast_to(np.asarray(v, dtype=np.float64), (n,))
        variables[name] = (
            "case",
            np.array(column),
            {"units": schema.unit(name), "long_name": f"input: {schema.description(name)}"},
        )
    for name in batch_columns(batch):  # the columns of to_dataframe, in its order
        if name == "status":
            variables[name] = ("case", status.astype(np.int32), status_attrs())
        elif name == "max_delta_ratio":
            variables[name] = (
                "case",
                np.array(batch.max_delta_ratio, dtype=np.float64),
                {"units": "1", "long_name": schema.description("max_delta_ratio")},
            )
        elif name in OUTPUT_FIELDS:
            variables[name] = _output_var(name, out[:, OUTPUT_FIELDS.index(name)], ok)
        else:  # schema.register_output
            variables[name] = _output_var(name, batch[name], ok)
    refs: tuple[Reference, ...] = tuple(batch.references)
    attrs = {
        "law": batch.law,
        "friction": batch.friction,
        "references": [r.key for r in refs],
        "dois": [r.doi for r in refs if r.doi],
        "source": "impactlab.simulate_batch",
        "impactlab_version": __version__,
        **getattr(batch, "setup", {}),
    }
    if batch.law_range is not None:
        attrs["law_range"] = batch.law_range
    return xr.Dataset(variables, coords={"case": np.arange(n)}, attrs=attrs)


def _stats_row(name: str, values: np.ndarray, shown: str) -> tuple[str, str, str, str, str]:
    d = display_unit(name, schema.unit(name))
    v = values[np.isfinite(values)] * d.scale
    unit = "" if d.unit == "-" else d.unit
    if v.size == 0:  # no ok case: no statistics, the unit all the same
        return shown, "-", "-", "-", unit
    lo, mid, hi = (format_number(float(x)) for x in (v.min(), np.median(v), v.max()))
    return shown, lo, mid, hi, unit


def batch_html(
    batch: Any,
    title: str = "BatchResult",
    names: Mapping[str, str] | None = None,
    out: np.ndarray | None = None,
) -> str:
    """The notebook summary of a batch (``BatchResult``, ``DropBatchResult``): the counts of
    its one-line ``repr`` (``batch_fields.batch_counts``: computed, ok, the advisory flags
    marked, not ok), then min / median / max of the main outputs over the ok cases alone
    (``batch.ok``; display units). ``out``: the outputs in ``OUTPUT_FIELDS`` columns (default
    ``batch.out``); ``title`` heads it; ``names`` shows an output under another name (a
    drop's sequence totals)."""
    ok = np.asarray(batch.ok, dtype=bool)
    n_ok = int(np.count_nonzero(ok))
    columns = np.asarray(batch.out if out is None else out)
    shown = names or {}
    rows = [_stats_row(o, columns[ok, OUTPUT_FIELDS.index(o)], shown.get(o, o)) for o in _SUMMARY]
    caption = (
        f"{batch_counts(batch)}; min / median / max over the {n_ok} ok "
        f"case{'s' * (n_ok != 1)}; law {batch.law}, friction {batch.friction}"
        + ("" if batch.law_range is None else f"; law range: {batch.law_range}")
    )
    header = ("output", "min", "median", "max", "unit")
    return grid_html(title, header, rows, caption)
