"""Results as data-science objects: ``BatchResult.to_xarray()``, a batch's notebook
summary, and a history DataFrame with units and categorical phase/stick columns."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd
import pytest
import xarray as xr

from impactlab import ImplausibleInputWarning, schema
from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import simulate, simulate_batch
from impactlab.dynamics.batch_result import BatchResult
from impactlab.dynamics.kernels.status import REGIME_NAMES, ST_BAD_ANGLE


@pytest.fixture(scope="module")
def batch() -> BatchResult:
    with pytest.warns(ImplausibleInputWarning, match="every refused angle"):  # 4.0: degrees?
        return simulate_batch(
            PAPER_ROD,
            law="ghaednia",
            friction="coulomb",
            mu=[0.1, 0.2, 1.0, 0.2],
            angle=[math.radians(20), math.radians(20), math.radians(20), 4.0],
            vy=-1.41,
        )


def test_to_xarray(batch: BatchResult) -> None:
    ds = batch.to_xarray()
    assert dict(ds.sizes) == {"case": 4}
    for name in ("e", "delta_p", "duration", "mu", "angle", "vy"):
        assert ds[name].attrs["units"] == schema.unit(name)
        assert ds[name].attrs["long_name"]
    np.testing.assert_array_equal(ds["e"].values, batch.e)
    np.testing.assert_array_equal(ds["mu"].values, batch.mu)
    assert ds["status"].values.tolist() == [0, 0, 0, ST_BAD_ANGLE]
    st = ds["status"].attrs
    assert st["status_messages"][st["flag_values"].index(ST_BAD_ANGLE)].startswith("angle")
    assert st["status_messages"][st["flag_values"].index(0)] == "finished"  # as a sweep store's
    reg = ds["regime"]
    assert reg.dtype.kind == "i" and reg.values.tolist() == [1, 1, 2, -1]
    names = dict(zip(reg.attrs["flag_values"], reg.attrs["flag_meanings"].split(), strict=True))
    assert names == REGIME_NAMES
    flags = ds["flags"]
    assert flags.dtype.kind == "i" and flags.values[3] == -1
    np.testing.assert_array_equal(flags.values[:3], batch.flags[:3])
    assert "energy_gain" in flags.attrs["flag_meanings"].split()
    assert ds.attrs["law"] == "ghaednia" and ds.attrs["friction"] == "coulomb"
    assert "10.1007/s00419-015-1108-2" in ds.attrs["dois"]


def test_to_xarray_writes_netcdf(batch: BatchResult, tmp_path) -> None:
    ds = batch.to_xarray()
    ds.to_netcdf(tmp_path / "b.nc")
    back = xr.load_dataset(tmp_path / "b.nc")
    np.testing.assert_array_equal(back["regime"].values, ds["regime"].values)
    assert back["e"].attrs["units"] == "1" and back.attrs["law"] == "ghaednia"


def test_batch_html(batch: BatchResult) -> None:
    html = batch._repr_html_()
    assert repr(batch).startswith("BatchResult(4 cases, 3 computed, 3 ok")
    assert "<p>4 cases, 3 computed, 3 ok" in html and "over the 3 ok cases" in html
    assert "<td>delta_p</td>" in html and "<td>um</td>" in html


def test_history_dataframe_units_and_categories() -> None:
    r = simulate(PAPER_ROD, mu=0.2, angle="20 deg", velocity=(0.0, -1.41))
    h = r.history
    assert h is not None
    assert h.units["normal_force"] == "N" and h.units["t"] == "s" and h.units["phase"] == "1"
    df = h.to_dataframe()
    assert df.attrs["units"] == h.units and df.attrs["units"]["penetration"] == "m"
    assert isinstance(df["phase"].dtype, pd.CategoricalDtype)
    assert list(df["phase"].cat.categories) == ["loading", "unloading"]
    assert list(df["stick"].cat.categories) == ["slip", "stick"]
    np.testing.assert_array_equal(df["phase"].cat.codes.to_numpy(), h.phase.astype(int))
    assert df["phase"].iloc[0] == "loading" and df["phase"].iloc[-1] == "unloading"
