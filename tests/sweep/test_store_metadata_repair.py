"""Array metadata follows from the study: a ``zarr.json`` of a result array, a coordinate, a
fixed or sampled input or the ``.sweep`` group that is cut short, junk or gone is refused by
name (a resume repairs it), and a run of the same study writes it again, keeping every chunk:
the store is then the same bytes as one never damaged."""

from __future__ import annotations

import shutil
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, store_files

from impactlab.sweep import (
    CorruptStoreError,
    RepairableStoreError,
    Study,
    open_sweep,
    run_sweep,
    store_info,
)
from impactlab.sweep.dimensions import Sample
from impactlab.sweep.distributions import Uniform


def _study() -> Study:
    return Study(
        name="meta",
        chunk_size=10,
        grid={"angle": np.radians([10.0, 30.0, 50.0, 70.0])},
        sample=Sample(size=5, seed=3, inputs={"mu": Uniform(0.0, 0.6)}),
        fixed={"vy": -1.41},
    )


def _cut(f: Path) -> None:
    f.write_bytes(f.read_bytes()[:-1])


def _junk(f: Path) -> None:
    f.write_bytes(b"\x00\xff junk")


def _not_zarr(f: Path) -> None:
    f.write_text('{"a": 1}')


DAMAGE: dict[str, Callable[[Path], None]] = {
    "cut short": _cut,
    "junk": _junk,
    "not Zarr's": _not_zarr,
    "gone": Path.unlink,
}


@pytest.fixture(scope="module")
def reference(tmp_path_factory) -> Path:
    path = tmp_path_factory.mktemp("ref") / "ref.zarr"
    return run_sweep(_study(), path, evaluator=FakeEvaluator(), quiet=True).path


@pytest.mark.parametrize("damage", sorted(DAMAGE))
@pytest.mark.parametrize(
    "node",
    ["e", "status", "angle", "mu", "vy", "body_E", "law", ".sweep"],
    ids=[
        "result",
        "status",
        "coordinate",
        "sampled",
        "fixed",
        "material value",
        "category",
        "bookkeeping",
    ],
)
def test_damaged_metadata_is_repaired_with_every_chunk_kept(
    tmp_path, reference, node, damage
) -> None:
    store = tmp_path / "a.zarr"
    shutil.copytree(reference, store)
    DAMAGE[damage](store / node / "zarr.json")
    with pytest.raises(RepairableStoreError) as opened:
        open_sweep(store)
    message = str(opened.value)
    assert f"{node}/zarr.json" in message and "\n" not in message
    assert "run the same study into it again" in message and "--restart would discard" in message
    with pytest.raises(CorruptStoreError) as info:
        store_info(store)
    assert str(info.value) == message
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0 and again.stats.chunks_before == again.stats.n_chunks
    assert store_files(store) == store_files(reference)


def test_a_folder_that_is_not_the_studys_still_needs_a_restart(tmp_path, reference) -> None:
    store = tmp_path / "a.zarr"
    shutil.copytree(reference, store)
    (store / "stray").mkdir()
    (store / "stray" / "zarr.json").write_bytes(b"{")
    with pytest.raises(CorruptStoreError, match=r"stray/zarr\.json is not valid JSON.*--restart"):
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
