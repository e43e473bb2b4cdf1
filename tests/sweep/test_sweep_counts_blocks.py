"""A store's status and flag counts (``sweep run``'s summary, ``sweep info``) are read a block
of cases at a time (``summary.COUNT_BLOCK_CASES``), whatever the size of the store, and add up
to the counts of the whole array."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import CrashingEvaluator, FlaggingEvaluator

import impactlab.sweep.summary as summary
from impactlab.sweep import Sample, Study, Uniform, open_sweep, run_sweep, store_info


def _whole(ds, name: str) -> np.ndarray:
    return np.asarray(ds[name].values).ravel()


@pytest.fixture(scope="module")
def flagged_store(tmp_path_factory) -> Path:
    """A store with flagged cases, run once for the module: the tests only read it."""
    study = Study(
        name="counted",
        chunk_size=12,
        grid={"angle": np.radians(np.linspace(5, 85, 9)), "law": ["ghaednia", "hertz"]},
        fixed={"vy": -1.41},
        sample=Sample(size=7, seed=1, inputs={"mu": Uniform(0.0, 0.6)}),
    )
    store = tmp_path_factory.mktemp("counted") / "counted.zarr"
    run_sweep(study, store, evaluator=FlaggingEvaluator(), quiet=True)
    return store


@pytest.mark.parametrize("block", [1, 5, 12, 1000])
def test_block_counts_equal_the_whole_arrays(flagged_store, monkeypatch, block) -> None:
    ds = open_sweep(flagged_store)
    whole_status = summary._counts([_whole(ds, "status")], ds.attrs["status_messages"])
    whole_flags = summary.flag_counts(_whole(ds, "flags"), ds["flags"].attrs)
    assert whole_flags["flagged"] > 0  # the fake flags some cases
    sizes: list[int] = []
    blocks = summary._blocks

    def spy(ds, name):
        for values in blocks(ds, name):
            sizes.append(values.size)
            yield values

    monkeypatch.setattr(summary, "COUNT_BLOCK_CASES", block)
    monkeypatch.setattr(summary, "_blocks", spy)
    assert summary.status_counts(ds) == whole_status
    assert summary.dataset_flag_counts(ds) == whole_flags
    assert max(sizes) <= block and sum(sizes) == 2 * ds["status"].size
    info = store_info(flagged_store)
    assert info["status"] == whole_status
    assert info["flagged"] == summary.flagged_values(whole_flags)


def test_an_incomplete_store_counts_its_undone_cases(tmp_path, monkeypatch) -> None:
    study = Study(
        name="part",
        chunk_size=10,
        sample=Sample(size=97, seed=2, inputs={"mu": Uniform(0.0, 0.6)}),
        fixed={"vy": -1.41, "angle": "30 deg"},
    )
    store = tmp_path / "part.zarr"
    with pytest.raises(RuntimeError, match="simulated crash"):
        run_sweep(study, store, evaluator=CrashingEvaluator(after=3), workers=1, quiet=True)
    monkeypatch.setattr(summary, "COUNT_BLOCK_CASES", 4)
    status = store_info(store)["status"]
    assert sum(status.values()) == 97
    assert (
        status["0: finished"] == 30
        and sum(n for k, n in status.items() if k.startswith("-1:")) == 67
    )
