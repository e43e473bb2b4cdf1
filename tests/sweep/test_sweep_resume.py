"""Resumption: an interrupted sweep run again completes only the missing chunks and its store is
byte-for-byte the store of an uninterrupted run (kills at chosen moments: test_sweep_kill)."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import numpy as np
import pytest
from sweep_fakes import VY_LIMIT, CrashingEvaluator, FakeEvaluator, store_files

from impactlab.sweep import (
    Normal,
    Sample,
    Study,
    StudyMismatchError,
    SweepStore,
    Uniform,
    open_sweep,
    run_sweep,
)

HERE = Path(__file__).resolve().parent


def grid_study(**kw) -> Study:
    base = dict(
        name="grid",
        chunk_size=12,
        grid={
            "angle": np.radians(np.linspace(5, 85, 9)),
            "mu": np.linspace(0, 0.6, 7),
            "law": ["ghaednia", "hertz"],
        },
        fixed={"vy": -1.41},
    )
    base.update(kw)
    return Study(**base)


def sample_study(size: int = 2000, chunk: int = 100) -> Study:
    return Study(
        name="mc",
        chunk_size=chunk,
        fixed={"angle": 0.35},
        sample=Sample(
            size=size, seed=11, inputs={"vy": Normal(-1.41, 0.05), "mu": Uniform(0.1, 0.3)}
        ),
    )


@pytest.fixture(scope="module")
def grid_ref(tmp_path_factory):
    """``run_sweep``'s result of ``grid_study()``, uninterrupted, run once for the module: the
    tests only read its store (or copy it)."""
    path = tmp_path_factory.mktemp("grid") / "ref.zarr"
    return run_sweep(grid_study(), path, evaluator=FakeEvaluator(), quiet=True)


def test_grid_results_match_the_closed_form(grid_ref) -> None:
    res = grid_ref
    assert res.complete and res.stats.chunks_computed == res.stats.n_chunks
    ds = res.dataset
    assert ds["e"].dims == ("angle", "mu", "law")
    th = ds["angle"].values[:, None]
    mu = ds["mu"].values[None, :]
    np.testing.assert_allclose(
        ds["e"].sel(law="hertz").values, 0.5 + 0.1 * np.sin(th) - 0.2 * mu + 0.01, rtol=1e-15
    )
    assert ds["angle"].attrs["units"] == "rad" and ds["duration"].attrs["units"] == "s"
    assert str(ds["vy"].values) == "-1.41" and ds["vy"].attrs["units"] == "m/s"
    assert str(ds["friction"].values) == "coulomb"  # defaults are recorded too
    assert set(np.unique(ds["regime"].values)) <= {0, 1}
    assert ds["regime"].dtype == np.int8 and ds["status"].dtype == np.int32


def test_crash_mid_sweep_then_resume_gives_identical_store(tmp_path, grid_ref) -> None:
    ref = grid_ref
    store = tmp_path / "b.zarr"
    with pytest.raises(RuntimeError, match="simulated crash"):
        run_sweep(grid_study(), store, evaluator=CrashingEvaluator(after=4), quiet=True)
    assert SweepStore(store).done_chunks() == {0, 1, 2, 3}
    ds = open_sweep(store)
    assert (ds["status"].values == -1).any()  # missing chunks read as "not computed"
    again = run_sweep(grid_study(), store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == 4
    assert again.stats.chunks_computed == ref.stats.n_chunks - 4
    assert store_files(store) == store_files(ref.path)
    # a finished store is left alone
    third = run_sweep(grid_study(), store, evaluator=CrashingEvaluator(after=0), quiet=True)
    assert third.stats.chunks_computed == 0


def test_changed_study_is_refused_or_restarted_explicitly(tmp_path, fake, grid_ref) -> None:
    store = shutil.copytree(grid_ref.path, tmp_path / "s.zarr")  # the store of grid_study()
    changed = grid_study(fixed={"vy": -2.0})
    with pytest.raises(StudyMismatchError, match="--restart"):
        run_sweep(changed, store, evaluator=fake, quiet=True)
    assert not (store / ".sweep" / "lock").exists()
    fresh = run_sweep(changed, store, evaluator=fake, quiet=True, restart=True)
    ref = run_sweep(changed, tmp_path / "ref.zarr", evaluator=fake, quiet=True)
    assert fresh.stats.chunks_computed == fresh.stats.n_chunks
    assert store_files(store) == store_files(ref.path)
    # a non-store directory is never overwritten
    other = tmp_path / "other"
    other.mkdir()
    (other / "notes.txt").write_text("keep me")
    with pytest.raises(ValueError, match="not a sweep store"):
        run_sweep(changed, other, evaluator=fake, quiet=True, restart=True)
    assert (other / "notes.txt").read_text() == "keep me"


def test_store_begun_by_other_code_is_refused_with_the_reason(tmp_path, fake, monkeypatch) -> None:
    store = tmp_path / "s.zarr"
    with pytest.raises(RuntimeError):
        run_sweep(grid_study(), store, evaluator=CrashingEvaluator(after=2), quiet=True)
    engine = open_sweep(store).attrs["engine"]
    assert engine.startswith(f"{fake.identity}|impactlab ") and "|code " in engine
    # the same study, resumed after the code that computes results changed
    monkeypatch.setattr("impactlab.sweep.study_meta.results_code_hash", lambda: "0" * 16)
    with pytest.raises(StudyMismatchError, match="computed by other impactlab code") as info:
        run_sweep(grid_study(), store, evaluator=fake, quiet=True)
    assert engine in str(info.value) and "0" * 16 in str(info.value)
    assert "--restart" in str(info.value)
    # another study is still named as such
    with pytest.raises(StudyMismatchError, match="holds a different study"):
        run_sweep(grid_study(fixed={"vy": -2.0}), store, evaluator=fake, quiet=True)
    fresh = run_sweep(grid_study(), store, evaluator=fake, quiet=True, restart=True)
    assert fresh.stats.chunks_computed == fresh.stats.n_chunks
    assert "0" * 16 in open_sweep(store).attrs["engine"]


def test_process_pool_equals_in_process_run(tmp_path, fake) -> None:
    a = run_sweep(
        sample_study(size=600, chunk=100), tmp_path / "a.zarr", evaluator=fake, quiet=True
    )
    b = run_sweep(
        sample_study(size=600, chunk=100),
        tmp_path / "b.zarr",
        evaluator=fake,
        quiet=True,
        backend="processes",
        workers=2,
    )
    assert b.stats.chunks_computed == a.stats.n_chunks
    assert store_files(a.path) == store_files(b.path)


def test_invalid_cases_are_recorded_not_raised(tmp_path, fake) -> None:
    st = grid_study(
        grid={"angle": np.radians([20.0, 45.0]), "vy": [-1.0, -6.0, -7.0]}, fixed={"mu": 0.2}
    )
    ds = run_sweep(st, tmp_path / "inv.zarr", evaluator=fake, quiet=True).dataset
    status = ds["status"].values
    bad = ds["vy"].values[None, :] < VY_LIMIT
    np.testing.assert_array_equal(status, np.where(bad, 1, 0) * np.ones((2, 1), dtype=int))
    assert np.isnan(ds["e"].values[status != 0]).all()
    assert np.isfinite(ds["e"].values[status == 0]).all()
    msgs = ds.attrs["status_messages"]
    assert msgs["1"] == "fake: vy outside the validity range"
    assert "not computed" in msgs["-1"] and ds["status"].attrs["messages"] == msgs


def test_progress_bar_and_quiet(tmp_path, fake, capsys) -> None:
    run_sweep(grid_study(), tmp_path / "p.zarr", evaluator=fake, progress=True)
    err = capsys.readouterr().err
    assert "126/126" in err and "impacts" in err and "ETA" in err
    run_sweep(grid_study(), tmp_path / "q.zarr", evaluator=fake, quiet=True)
    run_sweep(grid_study(), tmp_path / "r.zarr", evaluator=fake)  # stderr is not a terminal
    assert capsys.readouterr().err == ""


def test_one_writer_per_store(tmp_path, fake) -> None:
    store = tmp_path / "l.zarr"
    with pytest.raises(RuntimeError):
        run_sweep(grid_study(), store, evaluator=CrashingEvaluator(after=2), quiet=True)
    assert not (store / ".sweep" / "lock").exists()  # released on the way out
    # a live writer (here: this test's parent process id) blocks a second one
    (store / ".sweep" / "lock").write_text(f"{os.uname().nodename} {os.getppid()}")
    with pytest.raises(ValueError, match="is being written by process"):
        run_sweep(grid_study(), store, evaluator=fake, quiet=True)
    # a lock left by a dead process is taken over
    (store / ".sweep" / "lock").write_text(f"{os.uname().nodename} 999999999")
    res = run_sweep(grid_study(), store, evaluator=fake, quiet=True)
    assert res.complete and not (store / ".sweep" / "lock").exists()


def test_netcdf_export_round_trip(tmp_path, grid_ref) -> None:
    import xarray as xr

    from impactlab.sweep import export_netcdf

    ds = open_sweep(grid_ref.path)
    export_netcdf(ds, tmp_path / "n.nc")
    back = xr.open_dataset(tmp_path / "n.nc")
    np.testing.assert_array_equal(back["e"].values, ds["e"].values)
    assert list(back["law"].values) == ["ghaednia", "hertz"]
    assert back["angle"].attrs["units"] == "rad"
    assert "not computed" in back.attrs["status_messages"]
    back.close()


def test_store_cut_short_by_an_older_impactlab_is_recovered(tmp_path, fake, grid_ref) -> None:
    # an older impactlab built the store in place: a kill during its creation left sweep
    # metadata without the study record, which could then never be resumed
    ref = grid_ref
    half = tmp_path / "half.zarr"
    (half / ".sweep" / "done").mkdir(parents=True)
    (half / "e").mkdir()
    res = run_sweep(grid_study(), half, evaluator=fake, quiet=True)  # nothing computed: anew
    assert res.stats.chunks_computed == res.stats.n_chunks
    assert store_files(half) == store_files(ref.path)
    # with chunks but no study record: refused, and --restart always works
    partial = tmp_path / "partial.zarr"
    (partial / ".sweep" / "done").mkdir(parents=True)
    (partial / ".sweep" / "done" / "3").write_text("3\n")
    (partial / "zarr.json").write_text('{"attributes": {"sweep_format": "impactlab-sweep/1"}}')
    with pytest.raises(ValueError, match=r"lacks its study record.*--restart"):
        run_sweep(grid_study(), partial, evaluator=fake, quiet=True)
    run_sweep(grid_study(), partial, evaluator=fake, quiet=True, restart=True)
    assert store_files(partial) == store_files(ref.path)
    # killed before it wrote its attributes: a Zarr group of sweep arrays only (--restart)
    bare = tmp_path / "bare.zarr"
    (bare / "e").mkdir(parents=True)
    (bare / "zarr.json").write_text('{"zarr_format": 3, "node_type": "group", "attributes": {}}')
    with pytest.raises(ValueError, match=r"creation was cut short; run with --restart"):
        run_sweep(grid_study(), bare, evaluator=fake, quiet=True)
    run_sweep(grid_study(), bare, evaluator=fake, quiet=True, restart=True)
    assert store_files(bare) == store_files(ref.path)
    # a Zarr group holding anything else is not ours: never deleted, not even on --restart
    (tmp_path / "other.zarr" / "mine").mkdir(parents=True)
    (tmp_path / "other.zarr" / "zarr.json").write_text('{"node_type": "group"}')
    with pytest.raises(ValueError, match="not a sweep store"):
        run_sweep(grid_study(), tmp_path / "other.zarr", evaluator=fake, quiet=True, restart=True)
    assert (tmp_path / "other.zarr" / "mine").is_dir()
    names = ["bare.zarr", "half.zarr", "other.zarr", "partial.zarr"]
    assert sorted(p.name for p in tmp_path.iterdir()) == names


def test_a_resume_records_the_edited_description(tmp_path) -> None:
    """The description (and max_cases) is no part of the study's hash: a resume with another
    writes it, and the store is the one an uninterrupted run of the edited study makes."""
    edited = grid_study(description="changed words", max_cases=10_000)
    ref = run_sweep(edited, tmp_path / "ref.zarr", evaluator=FakeEvaluator(), quiet=True)
    store = tmp_path / "b.zarr"
    with pytest.raises(RuntimeError, match="simulated crash"):
        run_sweep(grid_study(), store, evaluator=CrashingEvaluator(after=4), quiet=True)
    again = run_sweep(edited, store, evaluator=FakeEvaluator(), quiet=True)
    assert again.stats.chunks_before == 4
    assert open_sweep(store).attrs["description"] == "changed words"
    assert store_files(store) == store_files(ref.path)
    # a finished store resumed with another description records it too, and nothing else
    done = run_sweep(grid_study(description="third"), store, evaluator=FakeEvaluator(),
                     quiet=True)  # fmt: skip
    assert done.stats.chunks_computed == 0
    assert store_files(store) == store_files(
        run_sweep(grid_study(description="third"), tmp_path / "r3.zarr",
                  evaluator=FakeEvaluator(), quiet=True).path
    )  # fmt: skip
