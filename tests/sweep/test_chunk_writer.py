"""The chunk writer (``impactlab.sweep.chunkfiles``): each chunk of each array encoded with the
array's own Zarr codecs through Zarr's synchronous codec protocol and written as one file, its
digest recorded as written. The store it writes is byte for byte the store that Zarr's own
``z[block] = v`` writes, markers included, for grids, samples, edge chunks and integer arrays;
empty chunks leave no file and a ``null`` marker entry; stores made with the "/" chunk-key
separator are resumed in their own layout; resume after an interrupted chunk
gives the store of an uninterrupted run."""

from __future__ import annotations

import asyncio
import json
import tempfile
import threading
from pathlib import Path

import numpy as np
import pytest
import zarr
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra import numpy as hnp
from sweep_fakes import FakeEvaluator, store_files

from impactlab.sweep import Normal, Sample, Study, SweepStore, open_sweep, run_sweep, storebuild
from impactlab.sweep.chunkfiles import ChunkWriter
from impactlab.sweep.chunks import compute_chunk
from impactlab.sweep.integrity import file_digest, marker_text
from impactlab.sweep.study_meta import store_meta


def _grid() -> Study:
    """4 chunks of 6 cases, one per vy; those of vy = -6 and -7 m/s (beyond the fake law's
    validity) hold only NaN outputs: no file is written for them."""
    return Study(
        name="w5",
        chunk_size=6,
        grid={"vy": [-6.0, -7.0, -1.0, -2.0], "angle": np.radians([10, 30, 50]), "mu": [0.1, 0.4]},
    )


def _edge() -> Study:
    """Chunks of (2, 3, 2) over 5 vy: the last chunk is cut by the grid's edge."""
    return Study(
        name="edge",
        chunk_size=12,
        grid={
            "vy": [-1.0, -2.0, -3.0, -4.0, -5.0],
            "angle": np.radians([10, 30, 50]),
            "mu": [0.1, 0.4],
        },
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


def _zarr_write(store: SweepStore, arrays, study: Study, index: int, outputs, status) -> None:
    """Chunk ``index`` written by Zarr itself (``z[block] = v`` per array), then its marker from
    the files read back."""
    lay = study.layout
    block = lay.block(index)
    bshape = tuple(s.stop - s.start for s in block)
    coords = tuple(s.start // c for s, c in zip(block, lay.chunks, strict=True))
    keys = []
    for name, values in [*outputs.items(), ("status", status)]:
        z = arrays[name]
        v = np.asarray(values).reshape(bshape)
        if np.dtype(z.dtype).kind == "i" and v.dtype.kind == "f":
            v = np.where(np.isfinite(v), v, z.fill_value)
        z[block] = v.astype(z.dtype, copy=False)
        keys.append(f"{name}/{z.metadata.encode_chunk_key(coords)}")
    if study.sample is not None and all(s.start == 0 for s in block[:-1]):
        sl = block[-1]
        for name in study.sample.inputs:
            arrays[name][sl] = study.sample.draw(name, sl.start, sl.stop)
            keys.append(f"{name}/{arrays[name].metadata.encode_chunk_key(coords[-1:])}")
    store.mark_done(index, marker_text(index, store.path, keys))


def _zarr_store(study: Study, path: Path) -> Path:
    ev = FakeEvaluator()
    meta = store_meta(study, ev)
    store = SweepStore(path)
    store.prepare(study, meta)
    names = [*meta.outputs, "status", *(study.sample.inputs if study.sample else ())]
    group = zarr.open_group(str(path), mode="r+")
    arrays = {n: group[n] for n in names}
    for k in range(study.layout.n_chunks):
        res = compute_chunk(study, k, ev, meta.outputs)
        _zarr_write(store, arrays, study, k, res.outputs, res.status)
    store.release()
    return path


def _markers(path: Path) -> dict[int, dict]:
    done = path / ".sweep" / "done"
    return {int(p.name): json.loads(p.read_text()) for p in done.iterdir() if p.name.isdigit()}


@pytest.mark.parametrize("make", [_grid, _edge, _sampled], ids=["grid", "edge", "sample"])
def test_store_is_byte_identical_to_zarrs_own_writes(tmp_path, make) -> None:
    study = make()
    new = run_sweep(study, tmp_path / "new.zarr", evaluator=FakeEvaluator(), quiet=True).path
    ref = _zarr_store(study, tmp_path / "ref.zarr")
    assert store_files(new) == store_files(ref)  # data files and completion markers alike
    assert SweepStore(new).verify() == {}
    ds = open_sweep(new)
    assert int((ds["status"] >= 0).sum()) == study.layout.n_cases


def test_chunk_files_lie_in_one_folder_per_array(tmp_path) -> None:
    study = _grid()
    path = run_sweep(study, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).path
    assert sorted(p.name for p in (path / "status").iterdir()) == [
        "c.0.0.0",
        "c.1.0.0",
        "c.2.0.0",
        "c.3.0.0",
        "zarr.json",
    ]
    folders = {p.relative_to(path).as_posix() for p in path.rglob("*") if p.is_dir()}
    assert {f for f in folders if "/" in f} == {".sweep/done"}  # no folder inside an array


def test_a_store_with_the_slash_separator_is_written_and_resumed_in_its_layout(
    tmp_path, monkeypatch
) -> None:
    study = _grid()
    with monkeypatch.context() as m:  # the layout of stores made with the "/" separator
        m.setattr(storebuild, "CHUNK_KEYS", {})
        path = run_sweep(study, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).path
        ref = _zarr_store(study, tmp_path / "ref.zarr")
    assert (path / "status" / "c" / "2" / "0" / "0").is_file()
    assert store_files(path) == store_files(ref)
    SweepStore(path).discard([2])
    again = run_sweep(study, path, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_computed == 1
    assert store_files(path) == store_files(ref)


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
    assert not (path / "e" / "c.0.0.0").exists() and (path / "status" / "c.0.0.0").exists()
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
    (path / "e" / "c.0.0.0").write_bytes(b"stale: must be removed (empty chunk)")
    (path / "e" / "c.3.0.0").write_bytes(b"garbage")
    (path / "status" / "c.3.0.0.123.partial").write_bytes(b"cut short")
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
    """A notebook runs an event loop in its main thread: the writer needs none."""
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
        with pytest.raises(ValueError, match=r"array 'e': values of shape \(5,\) for a chunk"):
            writer.write([("e", block, np.zeros(5)), ("mean_force", block, np.zeros(6))])
        shifted = (block[0], slice(1, 3), block[2])  # chunks of 3 along the second axis
        with pytest.raises(ValueError, match=r"array 'e': block .* not start on a chunk bound"):
            writer.write([("e", shifted, np.zeros((1, 2, 2)))])
        store.write_chunk(writer, study, 1, res.outputs, res.status)
    finally:
        writer.close()
        store.release()
    assert store.verify() == {} and store.done_chunks() == {1}


def _twin_arrays(root: Path, dtype: str, shape, chunks, fill) -> tuple[zarr.Array, zarr.Array]:
    g = zarr.open_group(str(root), mode="w", zarr_format=3)
    kw = {
        "shape": shape,
        "chunks": chunks,
        "dtype": dtype,
        "fill_value": fill,
        "compressors": storebuild.compressors(),
        **storebuild.CHUNK_KEYS,
    }
    return g.create_array("a", **kw), g.create_array("b", **kw)


@settings(max_examples=40, deadline=None)
@given(
    data=st.data(),
    dtype=st.sampled_from(["float64", "int32"]),
    chunks=st.tuples(st.integers(1, 5), st.integers(1, 7)),
    extra=st.tuples(st.integers(0, 4), st.integers(0, 6)),
)
def test_a_chunk_file_is_zarrs_for_any_values(data, dtype, chunks, extra) -> None:
    """Any values, NaN and infinities included, edge chunks and all-fill chunks: the file the
    writer makes is the one Zarr makes (or, like Zarr, none)."""
    shape = (chunks[0] + extra[0], chunks[1] + extra[1])
    fill = np.nan if dtype == "float64" else -1
    elements = (
        st.floats(allow_nan=True, allow_infinity=True, width=64)
        if dtype == "float64"
        else st.integers(-3, 3)
    )
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        a, b = _twin_arrays(root, dtype, shape, chunks, fill)
        writer = ChunkWriter(root, ["a"])
        for i in range(0, shape[0], chunks[0]):
            for j in range(0, shape[1], chunks[1]):
                part = (min(chunks[0], shape[0] - i), min(chunks[1], shape[1] - j))
                sel = (slice(i, i + part[0]), slice(j, j + part[1]))
                if data.draw(st.booleans()):
                    v = np.full(part, fill, dtype=dtype)  # a chunk of fill values only
                else:
                    v = data.draw(hnp.arrays(dtype, part, elements=elements))
                digests = writer.write([("a", sel, v)])
                b[sel] = v
                key = f"c.{i // chunks[0]}.{j // chunks[1]}"
                assert digests == {f"a/{key}": file_digest(root / "a" / key)}
                assert file_digest(root / "a" / key) == file_digest(root / "b" / key)
        np.testing.assert_array_equal(a[...], b[...])


def test_a_chunk_past_the_first_of_its_sample_block_holds_its_sampled_inputs(tmp_path) -> None:
    """Only a sample block's first chunk wrote its sampled inputs: a processes or Dask run
    interrupted with a later chunk stored gave cases with results and NaN inputs."""
    study = Study(
        name="gs",
        grid={"law": ["ghaednia", "hertz"]},
        sample=Sample(size=8, seed=1, inputs={"mu": Normal(0.3, 0.05, low=0.0)}),
        fixed={"vy": -1.41, "angle": 0.35},
        chunk_size=4,
    )
    ev = FakeEvaluator()
    meta = store_meta(study, ev)
    store = SweepStore(tmp_path / "s.zarr")
    store.prepare(study, meta)
    lay = study.layout
    later = next(k for k in range(lay.n_chunks) if lay.block(k)[0].start > 0)
    res = compute_chunk(study, later, ev, meta.outputs)
    writer = store.writer([*meta.outputs, "status", "mu"])
    try:
        store.write_chunk(writer, study, later, res.outputs, res.status)
    finally:
        writer.close()
        store.release()
    assert store.verify() == {} and store.done_chunks() == {later}
    sl = lay.block(later)[-1]
    stored = open_sweep(store.path)["mu"].values[sl]
    np.testing.assert_array_equal(stored, study.sample.draw("mu", sl.start, sl.stop))
