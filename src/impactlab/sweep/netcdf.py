"""A sweep's Dataset as a NetCDF-4 file."""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr

__all__ = ["export_netcdf"]


def export_netcdf(ds: xr.Dataset, path: str | Path) -> Path:
    """Write the Dataset to NetCDF-4 (strings kept; dictionary attributes become JSON text)."""
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
