"""What is put into a store by hand: a folder that is none of its nodes (Jupyter's
``.ipynb_checkpoints``, a ``plots/`` folder) is ignored, as a plain file is; a folder where a
chunk's file belongs damages that chunk only, which a resume computes again; an exported file
given to ``sweep uncertainty`` is named as a file, not a store."""

from __future__ import annotations

import shutil
import warnings

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, run_cli, store_files

from impactlab.sweep import (
    CorruptStoreError,
    DamagedStoreError,
    Study,
    open_sweep,
    run_sweep,
    store_info,
)
from impactlab.sweep.limits import SweepSizeWarning


def _study() -> Study:
    angles = np.radians([10.0, 20.0, 30.0])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SweepSizeWarning)  # 3 chunks of 1 case, on purpose
        return Study(name="f", grid={"angle": angles}, fixed={"vy": -1.41, "mu": 0.2}, chunk_size=1)


@pytest.fixture(scope="module")
def finished(tmp_path_factory):
    """The study's finished store, run once for the module."""
    path = tmp_path_factory.mktemp("f") / "f.zarr"
    return run_sweep(_study(), path, evaluator=FakeEvaluator(), quiet=True).path


@pytest.fixture
def store(finished, tmp_path):
    """A copy of the finished store, the test's own to put folders into."""
    return shutil.copytree(finished, tmp_path / "f.zarr")


@pytest.mark.parametrize("folder", [".ipynb_checkpoints", "plots"])
def test_a_folder_that_is_not_the_stores_is_ignored(store, folder, monkeypatch, capsys) -> None:
    before = open_sweep(store)["e"].values
    (store / folder).mkdir()
    (store / folder / "notes.txt").write_text("mine")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # not Zarr's warning of a folder it does not know
        np.testing.assert_array_equal(open_sweep(store)["e"].values, before)
        assert store_info(store)["chunks_done"] == 3
        again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store))
    assert code == 0 and err == ""
    assert (store / folder / "notes.txt").read_text() == "mine"


def test_a_folder_with_unreadable_zarr_metadata_still_needs_a_restart(store) -> None:
    (store / "plots").mkdir()
    (store / "plots" / "zarr.json").write_text("junk")
    with pytest.raises(CorruptStoreError, match=r"plots/zarr\.json is not valid JSON.*--restart"):
        open_sweep(store)


def test_a_folder_in_place_of_a_chunk_file_damages_that_chunk(store, tmp_path) -> None:
    reference = tmp_path / "ref"
    reference.mkdir()
    ref = run_sweep(_study(), reference / "f.zarr", evaluator=FakeEvaluator(), quiet=True).path
    (store / "e" / "c.1").unlink()
    (store / "e" / "c.1").mkdir()
    with pytest.raises(DamagedStoreError, match=r"chunk 1 \(e/c\.1: a folder, not a file\)"):
        open_sweep(store)
    assert "chunk 1 (e/c.1: a folder, not a file)" in store_info(store)["damaged"]
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_repaired == 1 and again.stats.chunks_computed == 1
    assert store_files(store) == store_files(ref)


@pytest.mark.parametrize("name", ["out.nc", "out.csv"])
def test_uncertainty_of_an_exported_file(store, tmp_path, name, monkeypatch, capsys) -> None:
    target = tmp_path / name
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 0, err
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(target))
    assert code == 2 and out == ""
    assert f"error: {str(target)!r} is a file, not a sweep store (a folder written by " in err
    assert "give a Monte Carlo study file (TOML) or the Zarr store it ran into" in err
