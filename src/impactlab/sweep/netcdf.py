"""A sweep's Dataset as a file: NetCDF-4 (``.nc``, ``.nc4``: every variable and attribute) or a
CSV table (``.csv``: one row per case, every input and output a column, its unit in the
header, ``e_energy``, ``delta_p [m]``, ``angle [rad]``, in a fixed order). ``export_file``
chooses by the suffix and refuses any other."""

from __future__ import annotations

import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

from impactlab.sweep.inputs import INPUTS

__all__ = ["EXPORT_SUFFIXES", "export_csv", "export_file", "export_netcdf"]

#: The suffixes of the files a sweep exports to, and their format.
EXPORT_SUFFIXES = {".csv": "CSV", ".nc": "NetCDF-4", ".nc4": "NetCDF-4"}


def check_suffix(
    path: str | Path, name: str, formats: tuple[str, ...] = ("CSV", "NetCDF-4")
) -> str:
    """The format of ``path`` by its suffix (:data:`EXPORT_SUFFIXES`, among ``formats``);
    ValueError naming ``name`` (how the user gave the path) and the suffixes allowed."""
    p = Path(path)
    if p.name.lower() in EXPORT_SUFFIXES:  # ".csv": a suffix only, which Path reads as a name
        raise ValueError(
            f"{name} {str(p)!r} needs a name before its suffix, e.g. "
            f"{str(p.with_name('out' + p.name))!r}"
        )
    kind = EXPORT_SUFFIXES.get(p.suffix.lower())
    if kind not in formats:
        allowed = ", ".join(
            " or ".join(s for s, k in EXPORT_SUFFIXES.items() if k == f) + f" ({f})"
            for f in formats
        )
        raise ValueError(f"{name} {str(p)!r} must end in {allowed}")
    return str(kind)


def export_file(ds: xr.Dataset, path: str | Path) -> Path:
    """Write the Dataset to ``path``: a CSV table for ``.csv``, NetCDF-4 for ``.nc``/``.nc4``
    (ValueError for any other suffix)."""
    if check_suffix(path, "export file") == "CSV":
        return export_csv(ds, path)
    return export_netcdf(ds, path)


def export_netcdf(ds: xr.Dataset, path: str | Path) -> Path:
    """Write the Dataset to NetCDF-4 (strings kept; dictionary attributes become JSON text);
    ``path`` ends in ``.nc`` or ``.nc4``."""
    check_suffix(path, "NetCDF file", ("NetCDF-4",))
    out = Path(path)

    def attrs(a: Mapping[str, Any]) -> dict[str, Any]:
        return {k: json.dumps(v) if isinstance(v, dict) else v for k, v in a.items()}

    def plain(var: xr.Variable) -> xr.Variable:
        values = var.values
        if values.dtype.kind == "T":  # numpy StringDType -> fixed-width unicode
            values = np.array(values.tolist(), dtype=str)
        return xr.Variable(var.dims, values, attrs(var.attrs))

    loaded = ds.load()
    coords = {str(k): plain(v.variable) for k, v in loaded.coords.items()}
    data = {str(k): plain(v.variable) for k, v in loaded.data_vars.items()}
    xr.Dataset(data, coords=coords, attrs=attrs(loaded.attrs)).to_netcdf(out, engine="netcdf4")
    return out


def export_csv(ds: xr.Dataset, path: str | Path) -> Path:
    """Write the Dataset as a CSV table (``ds.to_dataframe()``): one row per case, a column per
    dimension, input and output, headed ``name [unit]`` (the variable's ``units``: SI but the
    Brinell hardness in kgf/mm^2; a dimensionless one by its name alone), in the order of
    :func:`_columns`. Written whole or not at all; ``path`` ends in ``.csv``."""
    check_suffix(path, "CSV file", ("CSV",))
    out = Path(path)
    dims = [str(d) for d in (ds["status"].dims if "status" in ds else ds.dims)]
    table = ds.to_dataframe(dim_order=dims).reset_index()
    table = table[_columns(dims, ds.attrs.get("outputs", []), [str(c) for c in table.columns])]
    table.columns = [_header(str(c), ds[c].attrs.get("units")) for c in table.columns]
    tmp = out.with_name(f".{out.name}.{os.getpid()}.partial")
    try:
        table.to_csv(tmp, index=False)
        os.replace(tmp, out)
    except BaseException:
        tmp.unlink(missing_ok=True)
        raise
    return out


def _columns(dims: list[str], outputs: Any, present: list[str]) -> list[str]:
    """The columns of a CSV table in a fixed order, whatever order the store's variables come
    in: dimensions, outputs (the study's order), ``flags``, ``status``, then the inputs
    (``INPUTS`` order; any other name after them, sorted)."""
    head = [
        c for c in dict.fromkeys([*dims, *map(str, outputs), "flags", "status"]) if c in present
    ]
    rank = {name: i for i, name in enumerate(INPUTS)}
    rest = sorted(set(present) - set(head), key=lambda c: (rank.get(c, len(rank)), c))
    return [*head, *rest]


def _header(name: str, unit: Any) -> str:
    return name if unit in (None, "", "1", "-") else f"{name} [{unit}]"
