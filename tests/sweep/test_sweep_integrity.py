"""A tampered store: chunks whose files no longer match the checksums in their completion
markers are reported by ``info``, refused by ``export``/``plot`` and ``open_sweep``, and
computed again (only they) on resume."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import CrashingEvaluator, FakeEvaluator, run_cli, store_files

from impactlab.sweep import DamagedStoreError, Study, open_sweep, run_sweep, store_info


def _study() -> Study:
    return Study(
        name="tamper",
        chunk_size=10,
        grid={"angle": np.radians(np.linspace(10, 80, 8)), "mu": np.linspace(0.0, 0.6, 10)},
        fixed={"vy": -1.41},
    )


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    """The finished store of the study, made once; no test changes it."""
    ref = tmp_path_factory.mktemp("tamper") / "ref.zarr"
    return run_sweep(_study(), ref, evaluator=FakeEvaluator(), quiet=True).path


@pytest.fixture
def stores(reference, tmp_path) -> tuple[Path, Path]:
    """(a finished store to tamper with, an identical reference)."""
    return shutil.copytree(reference, tmp_path / "a.zarr"), reference


def _chunk_file(store: Path, index: int, array: str) -> Path:
    """The file of ``array`` in chunk ``index``, read from the chunk's completion marker."""
    files = json.loads((store / ".sweep" / "done" / str(index)).read_text())["files"]
    return store / next(k for k in files if k.startswith(f"{array}/"))


def test_deleted_chunk_data_is_reported_refused_and_recomputed(stores, tmp_path) -> None:
    store, ref = stores
    _chunk_file(store, 3, "e").unlink()  # data gone, completion marker kept
    info = store_info(store)
    assert (info["chunks_done"], info["chunks_total"]) == (7, 8)
    assert "chunk 3 (e/c.3.0: missing)" in info["damaged"]
    assert sum(info["status"].values()) == 70  # the damaged chunk's 10 cases are left out
    with pytest.raises(DamagedStoreError, match=r"1 damaged chunk\(s\): chunk 3 .*run the sweep"):
        open_sweep(store)
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_repaired == 1 and again.stats.chunks_computed == 1
    assert store_files(store) == store_files(ref)


def test_truncated_chunk_file_is_refused_in_one_line(stores, monkeypatch, capsys) -> None:
    store, ref = stores
    f = _chunk_file(store, 5, "status")
    f.write_bytes(f.read_bytes()[:7])
    info = store_info(store)  # no blosc traceback: the damaged chunk is not read
    assert "chunk 5 (status/c.5.0: changed (size or checksum))" in info["damaged"]
    for args in (
        ["export", str(store), str(store.parent / "x.nc")],
        ["plot", str(store), "-o", str(store.parent / "p")],
    ):
        code, _, err = run_cli(monkeypatch, capsys, "sweep", *args)
        assert code == 2 and err.count("\n") == 1, err
        assert err.startswith("error: ") and "chunk 5" in err and "run the sweep again" in err
    assert not (store.parent / "x.nc").exists()
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0, err
    # a resume recomputes the damaged chunk only; an evaluator that fails on a second call
    # proves that nothing intact is computed again
    again = run_sweep(_study(), store, evaluator=CrashingEvaluator(after=1), quiet=True)
    assert again.stats.chunks_computed == 1 and again.stats.chunks_before == 7
    assert store_files(store) == store_files(ref)


def test_a_chunk_of_fill_values_only_has_no_file_and_is_intact(tmp_path) -> None:
    # every case rejected: all outputs NaN (the fill value), so Zarr writes no output files
    st = Study(
        name="void", chunk_size=4, grid={"vy": [-6.0, -7.0]}, fixed={"mu": 0.1, "angle": 0.3}
    )
    store = run_sweep(st, tmp_path / "v.zarr", evaluator=FakeEvaluator(), quiet=True).path
    assert not (store / "e" / "c.0").exists()
    assert "damaged" not in store_info(store)
    assert int(open_sweep(store)["status"].sum()) == 2
    (store / "e" / "c.0").write_bytes(b"junk")
    assert "e/c.0: changed (unexpected file)" in store_info(store)["damaged"]
