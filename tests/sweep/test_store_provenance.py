"""A sweep store says what was swept and with which impactlab, and opens in plain xarray
without a warning."""

from __future__ import annotations

import json
import warnings

import xarray as xr

import impactlab
from impactlab.sweep import Study, open_sweep, run_sweep


def test_store_opens_without_warnings_and_names_its_version(tmp_path, fake) -> None:
    st = Study(name="p", fixed={"angle": 0.5, "mu": 0.2}, grid={"vy": [-1.0, -2.0]})
    path = tmp_path / "p.zarr"
    run_sweep(st, path, evaluator=fake, quiet=True)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ds = xr.open_zarr(path)
        assert set(ds.data_vars) >= {"e", "status"}
    assert ds.attrs["impactlab_version"] == impactlab.__version__
    assert json.loads(ds.attrs["study"])["grid"]
    assert float(open_sweep(path)["e"].sum()) == float(ds["e"].sum())  # the same data
