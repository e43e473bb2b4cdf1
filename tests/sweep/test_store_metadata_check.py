"""The store's metadata check (every array's ``zarr.json`` opened, ~45 ms for a sweep) runs
once per run: not on a store the run has just built, once on a store it reopens, and a damaged
store is still found."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator

import impactlab.sweep.store as store_module
from impactlab.sweep import CorruptStoreError, Study, open_sweep, run_sweep


def _study() -> Study:
    grid = {"vy": [-1.0, -2.0], "angle": np.radians([10, 30]), "mu": [0.2]}
    return Study(name="meta", chunk_size=4, grid=grid)


@pytest.fixture
def checks(monkeypatch: pytest.MonkeyPatch) -> list[Path]:
    calls: list[Path] = []
    real = store_module.check_metadata

    def counting(path: str | Path) -> None:
        calls.append(Path(path))
        real(path)

    monkeypatch.setattr(store_module, "check_metadata", counting)
    return calls


def test_a_new_store_is_not_checked_again(tmp_path: Path, fake: FakeEvaluator, checks) -> None:  # type: ignore[no-untyped-def]
    run_sweep(_study(), tmp_path / "s.zarr", evaluator=fake, quiet=True)
    assert checks == []


def test_a_reopened_store_is_checked_once(tmp_path: Path, fake: FakeEvaluator, checks) -> None:  # type: ignore[no-untyped-def]
    path = tmp_path / "s.zarr"
    run_sweep(_study(), path, evaluator=fake, quiet=True)
    run_sweep(_study(), path, evaluator=fake, quiet=True)
    assert checks == [path]


def test_a_damaged_store_is_still_found(tmp_path: Path, fake: FakeEvaluator, checks) -> None:  # type: ignore[no-untyped-def]
    """Found by the one check of the run that reopens it, and repaired (an array's metadata
    follows from the study); opened without a run, it is refused."""
    path = tmp_path / "s.zarr"
    run_sweep(_study(), path, evaluator=fake, quiet=True)
    (path / "e" / "zarr.json").write_text("{ not json")
    with pytest.raises(CorruptStoreError, match=r"e/zarr\.json is not valid JSON"):
        open_sweep(path)
    again = run_sweep(_study(), path, evaluator=fake, quiet=True)
    assert checks[0] == path and again.stats.chunks_computed == 0
    assert open_sweep(path)["e"].shape == (2, 2, 1)
