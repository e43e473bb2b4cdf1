"""A store with damaged metadata that the study defines (a result array's ``zarr.json``, the
study record ``.sweep/study.json``): ``open_sweep``, ``info`` and a resume agree. The resume of
the same study rewrites it, keeps every intact chunk and computes only those whose data is gone
(impactlab.sweep.repair); another study is refused as usual."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, store_files

from impactlab.sweep import (
    CorruptStoreError,
    RepairableStoreError,
    Study,
    StudyMismatchError,
    open_sweep,
    run_sweep,
    store_info,
)


def _study(vy: float = -1.41) -> Study:
    return Study(
        name="repair",
        chunk_size=10,
        grid={"angle": np.radians([10.0, 30.0, 50.0, 70.0]), "mu": np.linspace(0.0, 0.6, 5)},
        fixed={"vy": vy},
    )


@pytest.fixture(scope="module")
def finished(tmp_path_factory) -> Path:
    """The finished store of the study, made once: the tests compare with it, never change it."""
    ref = tmp_path_factory.mktemp("repair") / "ref.zarr"
    return run_sweep(_study(), ref, evaluator=FakeEvaluator(), quiet=True).path


@pytest.fixture
def stores(finished, tmp_path) -> tuple[Path, Path]:
    """(a finished store to damage, an identical copy to compare with)."""
    ref = finished
    store = tmp_path / "a.zarr"
    shutil.copytree(ref, store)
    return store, ref


def _same_diagnosis(store: Path, needle: str) -> None:
    """open_sweep and info refuse the store with the same message, advising a resume."""
    with pytest.raises(RepairableStoreError) as opened:
        open_sweep(store)
    with pytest.raises(CorruptStoreError) as info:
        store_info(store)
    message = str(opened.value)
    assert needle in message and str(info.value) == message and "\n" not in message
    assert f"run the same study into it again (impactlab sweep run STUDY.toml --out {store})" in (
        message
    )


@pytest.mark.parametrize("array", ["e", "status"])
def test_a_lost_result_array_is_recreated_and_only_its_chunks_recomputed(stores, array) -> None:
    store, ref = stores
    shutil.rmtree(store / array)
    _same_diagnosis(store, f"result array {array!r} is gone: {array}/zarr.json is missing")
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_repaired == again.stats.chunks_computed == 2
    assert store_files(store) == store_files(ref)


def test_a_lost_array_description_keeps_every_chunk(stores) -> None:
    store, ref = stores
    (store / "e" / "zarr.json").unlink()  # its chunk files are still there
    _same_diagnosis(store, "result array 'e' is gone: e/zarr.json is missing")
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0 and again.stats.chunks_before == 2
    assert store_files(store) == store_files(ref)


def test_a_truncated_study_record_is_detected_and_rewritten(stores) -> None:
    store, ref = stores
    record = store / ".sweep" / "study.json"
    record.write_bytes(record.read_bytes()[:40])
    _same_diagnosis(store, ".sweep/study.json is not valid JSON")
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    assert store_files(store) == store_files(ref)


def test_another_study_is_not_written_into_a_damaged_store(stores) -> None:
    store, _ = stores
    shutil.rmtree(store / "e")
    with pytest.raises(StudyMismatchError, match="holds a different study") as caught:
        run_sweep(_study(vy=-2.0), store, evaluator=FakeEvaluator(), quiet=True)
    assert "restart=True in Python" in str(caught.value)  # the Python spelling too
    with pytest.raises(RepairableStoreError):
        open_sweep(store)


@pytest.mark.parametrize(
    ("damage", "needle"),
    [
        (lambda s: (s / "angle" / "c.0").unlink(), "angle does not hold the study's values"),
        (lambda s: (s / "mu" / "c.0").write_bytes(b"cut short"), "mu cannot be read"),
        (lambda s: shutil.rmtree(s / "vy"), "vy does not hold the study.s values"),
    ],
)
def test_a_damaged_coordinate_is_refused_then_written_again_from_the_study(
    stores, damage, needle
) -> None:
    """A grid coordinate or fixed input is written once, from the study, and no chunk marker
    covers it: gone, it read as NaN coordinates, cut short it made the store unreadable. It is
    refused by name (open_sweep and info alike), and a run of the same study writes it again,
    computing nothing: the store is the same bytes as before."""
    from impactlab.sweep import DamagedStoreError

    store, ref = stores
    damage(store)
    for read in (open_sweep, store_info):
        with pytest.raises(DamagedStoreError, match=needle) as err:
            read(store)
        assert "every computed chunk is kept" in str(err.value) and "\n" not in str(err.value)
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    assert store_files(store) == store_files(ref)
    assert np.array_equal(open_sweep(store)["angle"].values, _study().axes[0].array())


def test_a_deleted_study_record_is_written_again_from_the_root_attributes(stores) -> None:
    """``.sweep/study.json`` gone, the root attributes (written after every array) still name
    the study's hash: a run of the same study writes the record again and keeps every chunk."""
    store, ref = stores
    (store / ".sweep" / "study.json").unlink()
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0
    assert store_files(store) == store_files(ref)


@pytest.mark.parametrize(
    ("damage", "needle"),
    [
        (lambda f: f.write_bytes(f.read_bytes()[:50]), "zarr.json is not valid JSON"),
        (lambda f: f.write_bytes(b"\x00\xff junk"), "zarr.json is not text"),
        (lambda f: f.unlink(), "zarr.json is missing"),
    ],
)
def test_a_damaged_root_is_rewritten_from_the_study_record(stores, damage, needle) -> None:
    """The root ``zarr.json`` holds the study's attributes: cut short, junk or gone, it is
    written again from ``.sweep/study.json`` and the engine identity kept beside it, by a run
    of the same study; every chunk is kept and the store reads as before."""
    store, ref = stores
    damage(store / "zarr.json")
    _same_diagnosis(store, needle)
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 0 and again.stats.chunks_before == 2
    assert open_sweep(store).attrs == open_sweep(ref).attrs
    np.testing.assert_array_equal(open_sweep(store)["e"].values, open_sweep(ref)["e"].values)


def test_a_damaged_root_is_not_rewritten_for_another_study_or_other_code(
    stores, monkeypatch
) -> None:
    store, _ = stores
    (store / "zarr.json").write_bytes(b"{")
    with pytest.raises(StudyMismatchError, match="holds a different study"):
        run_sweep(_study(vy=-2.0), store, evaluator=FakeEvaluator(), quiet=True)
    monkeypatch.setattr("impactlab.sweep.study_meta.results_code_hash", lambda: "0" * 16)
    with pytest.raises(StudyMismatchError, match="computed by other impactlab code"):
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert (store / "zarr.json").read_bytes() == b"{"  # nothing rewritten
    assert not (store / ".sweep" / "lock").exists()
    fresh = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True, restart=True)
    assert fresh.stats.chunks_computed == fresh.stats.n_chunks


def test_a_damaged_root_and_record_still_needs_a_restart(stores) -> None:
    store, _ = stores
    (store / "zarr.json").write_bytes(b"{")
    (store / ".sweep" / "study.json").write_bytes(b"{")
    with pytest.raises(CorruptStoreError, match="--restart"):
        run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)


def test_a_deleted_markers_folder_is_made_again_and_its_chunks_recomputed(stores) -> None:
    """``rm -rf STORE/.sweep/done``: no chunk counts as done, the resume computes them all and
    writes their markers into a new folder."""
    store, ref = stores
    shutil.rmtree(store / ".sweep" / "done")
    info = store_info(store)
    assert (info["chunks_done"], info["chunks_total"]) == (0, 2)
    again = run_sweep(_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.complete and again.stats.chunks_computed == 2
    assert store_files(store) == store_files(ref)
