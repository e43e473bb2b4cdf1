"""The chunk writer (issue 13, wave 5): all arrays of a chunk in one batch on the writer's own
event loop, files written by ``RecordingStore`` with their digests recorded as written. The
store it writes is byte for byte the store of one ``z[block] = v`` per array (the writer before
wave 5), markers included; empty chunks still leave no file and a ``null`` marker entry; resume
after an interrupted chunk still gives the store of an uninterrupted run."""

from __future__ import annotations

import asyncio
import json
import threading
from pathlib import Path

import numpy as np
import pytest
import zarr
from sweep_fakes import FakeEvaluator, store_files

from impactlab.sweep import Normal, Sample, Study, SweepStore, open_sweep, run_sweep
from impactlab.sweep.chunks import compute_chunk
from impactlab.sweep.integrity import chunk_key, file_digest, marker_text
from impactlab.sweep.runner import store_meta
from impactlab.sweep.storebuild import ChunkWriter, RecordingStore


def _grid() -> Study:
    """4 chunks of 6 cases, one per vy; those of vy = -6 and -7 m/s (beyond the fake law's
    validity) hold only NaN outputs: Zarr writes no file for them."""
    return Study(
        name="w5",
        chunk_size=6,
        grid={"vy": [-6.0, -7.0, -1.0, -2.0], "angle": np.radians([10, 30, 50]), "mu": [0.1, 0.4]},
    )


def _sampled() -> Study:
    return Study(
        name="w5mc",
        chunk_size=50,
        fixed={"angle": 0.35},
        sample=Sample(
            size=230, seed=3, inputs={"vy": Normal(-1.41, 0.05), "mu": Normal(0.2, 0.01)}
        ),
    )


def _old_write(store: SweepStore, arrays, study: Study, index: int, outputs, status) -> None:
    """``SweepStore.write_chunk`` before wave 5: one synchronous ``z[block] = v`` per array,
    then the marker from the files read back."""
    lay = study.layout
    block = lay.block(index)
    bshape = tuple(s.stop - s.start for s in block)
    coords = tuple(s.start // c for s, c in zip(block, lay.chunks, strict=True))
    keys = [chunk_key(name, coords) for name in [*outputs, "status"]]
    for name, values in outputs.items():
        z = arrays[name]
        v = np.asarray(values).reshape(bshape)
        if np.dtype(z.dtype).kind == "i" and v.dtype.kind == "f":
            v = np.where(np.isfinite(v), v, z.fill_value)
        z[block] = v.astype(z.dtype, copy=False)
    arrays["status"][block] = np.asarray(status, dtype=np.int32).reshape(bshape)
    if study.sample is not None and all(s.start == 0 for s in block[:-1]):
        sl = block[-1]
        for name in study.sample.inputs:
            arrays[name][sl] = study.sample.draw(name, sl.start, sl.stop)
            keys.append(chunk_key(name, coords[-1:]))
    store.mark_done(index, marker_text(index, store.path, keys))


def _old_store(study: Study, path: Path) -> Path:
    ev = FakeEvaluator()
    meta = store_meta(study, ev)
    store = SweepStore(path)
    store.prepare(study, meta)
    names = [*meta.outputs, "status", *(study.sample.inputs if study.sample else ())]
    group = zarr.open_group(str(path), mode="r+")
    arrays = {n: group[n] for n in names}
    for k in range(study.layout.n_chunks):
        res = compute_chunk(study, k, ev, meta.outputs)
        _old_write(store, arrays, study, k, res.outputs, res.status)
    store.release()
    return path


def _markers(path: Path) -> dict[int, dict]:
    done = path / ".sweep" / "done"
    return {int(p.name): json.loads(p.read_text()) for p in done.iterdir() if p.name.isdigit()}


@pytest.mark.parametrize("make", [_grid, _sampled], ids=["grid", "sample"])
def test_store_is_byte_identical_to_the_per_array_writes(tmp_path, make) -> None:
    study = make()
    new = run_sweep(study, tmp_path / "new.zarr", evaluator=FakeEvaluator(), quiet=True).path
    old = _old_store(study, tmp_path / "old.zarr")
    assert store_files(new) == store_files(old)  # data files and completion markers alike
    assert SweepStore(new).verify() == {}
    ds = open_sweep(new)
    assert int((ds["status"] >= 0).sum()) == study.layout.n_cases


def test_markers_hold_the_digests_of_the_files_and_null_for_empty_chunks(tmp_path) -> None:
    study = _grid()
    path = run_sweep(study, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).path
    markers = _markers(path)
    assert sorted(markers) == list(range(study.layout.n_chunks))
    nulls = 0
    for k, record in markers.items():
        assert set(record) == {"chunk", "files"} and record["chunk"] == k
        text = (path / ".sweep" / "done" / str(k)).read_text()
        assert text == json.dumps(record, sort_keys=True) + "\n"
        for key, want in record["files"].items():
            assert want == file_digest(path / key)  # recorded as written == read back
            nulls += want is None
    # vy = -6 and -7 m/s: 2 chunks whose 6 outputs are all NaN (status is not: it has a file)
    assert nulls == 2 * 6
    assert not (path / "e" / "c" / "0").exists() and (path / "status" / "c" / "0").exists()
    ds = open_sweep(path)
    assert np.isnan(ds["e"].sel(vy=[-6.0, -7.0]).values).all()
    assert (ds["status"].sel(vy=[-6.0, -7.0]).values == 1).all()


def test_resume_after_an_interrupted_chunk_gives_the_uninterrupted_store(tmp_path) -> None:
    study = _grid()
    ref = run_sweep(study, tmp_path / "ref.zarr", evaluator=FakeEvaluator(), quiet=True).path
    path = run_sweep(study, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).path
    store = SweepStore(path)
    # a writer killed inside chunks 0 and 3: markers gone, files half written or stale
    store.discard([0, 3])
    (path / "e" / "c" / "0" / "0").mkdir(parents=True)
    (path / "e" / "c" / "0" / "0" / "0").write_bytes(b"stale: must be removed (empty chunk)")
    (path / "e" / "c" / "3" / "0" / "0").write_bytes(b"garbage")
    (path / "status" / "c" / "3" / "0" / "0.123.partial").write_bytes(b"cut short")
    again = run_sweep(study, path, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == study.layout.n_chunks - 2
    assert again.stats.chunks_computed == 2
    assert store_files(path) == store_files(ref)
    assert store.verify() == {}


def _one_chunk(tmp_path: Path) -> tuple[SweepStore, Study, list[str], object]:
    study = _grid()
    ev = FakeEvaluator()
    meta = store_meta(study, ev)
    store = SweepStore(tmp_path / "s.zarr")
    store.prepare(study, meta)
    res = compute_chunk(study, 1, ev, meta.outputs)
    return store, study, [*meta.outputs, "status"], res


def test_all_of_a_chunk_is_written_by_the_calling_thread(tmp_path) -> None:
    store, study, names, res = _one_chunk(tmp_path)
    writer = store.writer(names)
    try:
        before = set(threading.enumerate())
        for _ in range(3):
            store.write_chunk(writer, study, 1, res.outputs, res.status)
        # no thread started by the writes (a thread of an earlier test may end meanwhile)
        assert set(threading.enumerate()) - before == set()
    finally:
        writer.close()
        store.release()
    assert store.verify() == {}


def test_writer_works_where_an_event_loop_runs(tmp_path) -> None:
    """A notebook runs an event loop in its main thread: Zarr's own loop thread writes."""
    store, study, names, res = _one_chunk(tmp_path)
    writer = store.writer(names)

    async def inside_a_loop() -> None:
        store.write_chunk(writer, study, 1, res.outputs, res.status)

    try:
        asyncio.run(inside_a_loop())
    finally:
        writer.close()
        store.release()
    assert store.verify() == {} and store.done_chunks() == {1}
    record = _markers(store.path)[1]["files"]
    assert all(v == file_digest(store.path / k) for k, v in record.items())


def test_a_failed_write_raises_and_the_writer_goes_on(tmp_path) -> None:
    store, study, names, res = _one_chunk(tmp_path)
    writer = ChunkWriter(store.path, names)
    block = study.layout.block(1)
    try:
        with pytest.raises((ValueError, IndexError)):  # wrong shape (Zarr's error)
            writer.write([("e", block, np.zeros(5)), ("mean_force", block, np.zeros(6))])
        store.write_chunk(writer, study, 1, res.outputs, res.status)
    finally:
        writer.close()
        writer.close()  # twice: nothing left to close
        store.release()
    assert store.verify() == {} and store.done_chunks() == {1}


def test_recording_store_records_writes_and_removals(tmp_path) -> None:
    rec = RecordingStore(tmp_path)
    g = zarr.open_group(store=rec, mode="w")
    z = g.create_array("x", shape=(4,), chunks=(2,), dtype="float64", fill_value=np.nan)
    rec.take()
    z[:2] = [1.0, 2.0]
    got = rec.take()
    assert got == {"x/c/0": file_digest(tmp_path / "x" / "c" / "0")}
    z[:2] = np.nan  # all fill value: Zarr removes the file
    assert rec.take() == {"x/c/0": None} and not (tmp_path / "x" / "c" / "0").exists()
    assert not list(tmp_path.rglob("*.partial"))
