"""A chunk without its completion marker (a run killed between its data and its marker) reads
as not computed in every variable: status -1, its outputs NaN and its integer outputs -1,
whatever its files hold; a marker of no chunk of the store counts for nothing."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pandas as pd
import pytest
from sweep_fakes import run_cli

from impactlab.sweep import Study, open_sweep, run_sweep, store_info

INTEGERS = ("regime", "n_steps", "flags")


@pytest.fixture(scope="module")
def unmarked(tmp_path_factory, engine):
    """A finished store of 3 chunks of 2 cases, computed by the engine, and chunk 1's
    marker removed: its files hold results that no marker vouches for."""
    study = Study(
        name="tiny",
        grid={"angle": np.radians([10.0, 20.0, 30.0]), "mu": [0.1, 0.2]},
        fixed={"vy": -1.41},
        chunk_size=2,
    )
    path = run_sweep(study, tmp_path_factory.mktemp("unmarked") / "k.zarr", quiet=True).path
    assert (open_sweep(path)["flags"].values > 0).all()  # law extrapolated: flagged
    (path / ".sweep" / "done" / "1").unlink()
    return path


@pytest.fixture
def store(unmarked, tmp_path):
    """A copy of that store, the test's own."""
    return shutil.copytree(unmarked, tmp_path / "k.zarr")


def test_every_variable_of_an_unmarked_chunk_reads_no_result(store) -> None:
    ds = open_sweep(store)
    undone = np.zeros((3, 2), dtype=bool)
    undone[1] = True
    np.testing.assert_array_equal(ds["status"].values == -1, undone)
    for name in ds.attrs["outputs"]:
        values = ds[name].values
        if name in INTEGERS:
            assert (values[undone] == -1).all(), name
            assert (values[~undone] >= 0).all() or name == "regime", name
        else:
            assert np.isnan(values[undone]).all(), name
    assert np.isfinite(ds["e"].values[~undone]).all()
    assert (ds["flags"].values[undone] == -1).all()


def test_info_and_export_count_only_marked_cases(store, tmp_path, monkeypatch, capsys) -> None:
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0, err
    info = json.loads(out)
    assert (info["chunks_done"], info["chunks_total"]) == (2, 3)
    assert info["flagged"]["total"] == 4 and info["flagged"]["law_extrapolated"] == 4
    target = tmp_path / "k.csv"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 0, err
    table = pd.read_csv(target)
    undone = table["status"] == -1
    assert undone.sum() == 2
    assert table.loc[undone, "e"].isna().all() and (table.loc[undone, "flags"] == -1).all()


def test_a_marker_of_no_chunk_is_ignored(store) -> None:
    shutil.copy(store / ".sweep" / "done" / "0", store / ".sweep" / "done" / "99")
    assert (store_info(store)["chunks_done"], store_info(store)["chunks_total"]) == (2, 3)
    ds = open_sweep(store)
    assert (ds["status"].values[1] == -1).all() and np.isnan(ds["e"].values[1]).all()
