"""``export_csv``, ``export_netcdf`` and ``export_file`` take a store's path, as ``impactlab
sweep export STORE OUT`` does (opened with ``open_sweep``), and refuse anything that is neither a
Dataset nor a path in one line (formerly ``'str' object has no attribute 'dims'``)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pandas as pd
import pytest
import xarray as xr
from sweep_fakes import FakeEvaluator

from impactlab.sweep import Study, export_csv, export_file, export_netcdf, open_sweep, run_sweep


@pytest.fixture
def store(tmp_path: Path) -> Path:
    study = Study(
        name="exp",
        grid={"angle": ["20 deg", "40 deg"], "mu": [0.1, 0.3]},
        fixed={"vy": -1.41, "law": "hertz"},
        outputs=["e", "delta_p", "regime"],
    )
    return run_sweep(study, tmp_path / "exp.zarr", evaluator=FakeEvaluator(), quiet=True).path


@pytest.mark.parametrize("as_text", [True, False])
def test_a_store_path_exports_as_its_dataset_does(
    store: Path, tmp_path: Path, as_text: bool
) -> None:
    given: Any = str(store) if as_text else store
    from_path = export_csv(given, tmp_path / "a.csv")
    from_ds = export_csv(open_sweep(store), tmp_path / "b.csv")
    assert from_path.read_text() == from_ds.read_text()
    assert len(pd.read_csv(from_path)) == 4
    nc = export_netcdf(given, tmp_path / "a.nc")
    with xr.open_dataset(nc) as got, xr.open_dataset(export_file(store, tmp_path / "b.nc")) as ref:
        xr.testing.assert_identical(got, ref)
    assert export_file(given, tmp_path / "c.csv").read_text() == from_ds.read_text()


def test_run_sweeps_result_exports(tmp_path: Path) -> None:
    study = Study(name="exp2", grid={"mu": [0.1, 0.3]}, fixed={"vy": -1.41, "angle": "20 deg"})
    result = run_sweep(study, tmp_path / "r.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert len(pd.read_csv(export_csv(result, tmp_path / "r.csv"))) == 2


@pytest.mark.parametrize("export", [export_csv, export_netcdf, export_file])
@pytest.mark.parametrize(("bad", "shown"), [(5, "the int 5"), (None, "the NoneType None")])
def test_anything_else_is_refused_in_one_line(
    export: Any, bad: Any, shown: str, tmp_path: Path
) -> None:
    suffix = ".nc" if export is export_netcdf else ".csv"
    with pytest.raises(ValueError, match=(
        r"^ds must be an xarray.Dataset \(open a store with open_sweep\(path\)\) or a sweep "
        rf"store's path, got {shown}$"
    )):  # fmt: skip
        export(bad, tmp_path / f"out{suffix}")
    assert not (tmp_path / f"out{suffix}").exists()


def test_a_path_that_is_no_store_says_so(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="is not a sweep store"):
        export_csv(tmp_path / "missing.zarr", tmp_path / "out.csv")
