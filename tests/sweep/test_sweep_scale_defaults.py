"""Sweeps at scale: the default chunk size follows what a case costs (and a store keeps the
chunking it was built with on resume), the too-big refusal estimates the time per kind of case,
the uncertainty report refuses a grid-only store before listing its points, and the run's
throughput is one figure (cases computed / wall time of the run) in text, JSON and HTML."""

from __future__ import annotations

import dataclasses
from types import SimpleNamespace

import pytest
from sweep_fakes import CrashingEvaluator, FakeEvaluator, run_cli, store_files

from impactlab.cli.sweep_summary import run_summary
from impactlab.sweep import (
    Sample,
    Study,
    StudyMismatchError,
    SweepStats,
    SweepStore,
    Uniform,
    limits,
    open_sweep,
    options,
    run_sweep,
    uncertainty_reports,
)
from impactlab.sweep import uncertainty as uncertainty_module
from impactlab.sweep.display import _rows, run_throughput, throughput_text

BASE = {"fixed": {"vy": -1.41, "mu": 0.2}, "grid": {"angle": ["10 deg", "20 deg"]}}


def _study(**fixed) -> Study:
    return Study.from_dict({**BASE, "fixed": {**BASE["fixed"], **fixed}})


# -- the default chunk size ------------------------------------------------------------------


@pytest.mark.parametrize(
    ("fixed", "size"),
    [({}, 65536), ({"friction": "partial_slip"}, 8192), ({"body": "flexible_rod"}, 512)],
)
def test_the_default_chunk_size_follows_the_cost_of_a_case(fixed, size) -> None:
    st = _study(**fixed)
    assert st.chunk_size is None and st.cases_per_chunk == size
    assert st.to_dict()["study"]["chunk_size"] == size  # recorded: the store's chunking
    assert st.hash() == _study(**fixed).hash()
    explicit = Study.from_dict(
        {**BASE, "fixed": {**BASE["fixed"], **fixed}, "study": {"chunk_size": size}}
    )
    assert explicit.hash() == st.hash()  # the same study as one that sets it
    case_s = limits.study_cost(st).chunk_case_s()
    if size < options.DEFAULT_CHUNK_SIZE:  # a chunk: a few seconds of one core
        assert options.CHUNK_TARGET_S / 2 < size * case_s <= options.CHUNK_TARGET_S


def test_a_sample_of_materials_and_a_grid_of_bodies_get_smaller_chunks() -> None:
    materials = Study(
        fixed={"vy": -1.41, "mu": 0.2, "angle": 0.3, "flat_E": 200e9, "flat_nu": 0.3},
        sample=Sample(size=1000, seed=1, inputs={"flat_yield_strength": Uniform(250e6, 350e6)}),
    )
    assert materials.cases_per_chunk == 2048  # a contact model per case, 1.5 ms each
    bodies = Study(
        fixed={"vy": -1.41, "mu": 0.2}, grid={"angle": [0.3], "body": ["rod", "flexible_rod"]}
    )
    assert bodies.cases_per_chunk == 512  # a chunk holds one body: the dearest decides
    assert Study(chunk_size=7, **BASE).cases_per_chunk == 7  # a study's own is kept


def test_a_flexible_study_is_cut_into_chunks_that_show_progress() -> None:
    st = Study.from_dict(
        {
            "fixed": {"body": "flexible_rod"},
            "grid": {
                "angle": {"start": "10 deg", "stop": "80 deg", "num": 60},
                "vy": {"start": -3.5, "stop": -1.0, "num": 10},
                "mu": {"start": 0.05, "stop": 0.5, "num": 10},
            },
        }
    )
    lay = st.layout
    assert lay.n_cases == 6000 and lay.n_chunks >= 12  # was one chunk of 65536
    assert max(lay.block_size(k) for k in range(lay.n_chunks)) <= 512


# -- a store keeps its chunking on resume --------------------------------------------------


def _mc() -> Study:
    return Study(
        name="mc",
        fixed={"angle": 0.35, "vy": -1.41},
        sample=Sample(size=600, seed=3, inputs={"mu": Uniform(0.1, 0.3)}),
    )


def test_a_resume_keeps_the_chunk_size_the_store_was_built_with(tmp_path, monkeypatch) -> None:
    with monkeypatch.context() as m:  # a store built when the default was 100 cases
        m.setattr(options, "DEFAULT_CHUNK_SIZE", 100)
        store = tmp_path / "mc.zarr"
        with pytest.raises(RuntimeError, match="simulated crash"):
            run_sweep(_mc(), store, evaluator=CrashingEvaluator(after=2), quiet=True)
    assert SweepStore(store).done_chunks() == {0, 1}
    assert _mc().cases_per_chunk == 65536  # the default now: one chunk
    again = run_sweep(_mc(), store, evaluator=FakeEvaluator(), quiet=True)  # not refused
    assert again.study.cases_per_chunk == 100 and again.complete
    assert again.stats.chunks_before == 2 and again.stats.chunks_computed == 4
    ref = run_sweep(
        dataclasses.replace(_mc(), chunk_size=100),
        tmp_path / "ref.zarr",
        evaluator=FakeEvaluator(),
        quiet=True,
    )
    assert store_files(store) == store_files(ref.path)  # as if never interrupted
    with pytest.raises(StudyMismatchError):  # a chunk size the study sets is its own
        run_sweep(dataclasses.replace(_mc(), chunk_size=300), store, evaluator=FakeEvaluator())
    fresh = run_sweep(_mc(), store, evaluator=FakeEvaluator(), quiet=True, restart=True)
    assert fresh.study.cases_per_chunk == 65536 and fresh.stats.n_chunks == 1


def test_the_recorded_chunk_size_is_read_from_the_root_attributes_too(tmp_path, fake) -> None:
    study = dataclasses.replace(_mc(), chunk_size=250)
    res = run_sweep(study, tmp_path / "r.zarr", evaluator=fake, quiet=True)
    assert options.recorded_chunk_size(res.path) == 250
    (res.path / ".sweep" / "study.json").unlink()
    assert options.recorded_chunk_size(res.path) == 250
    assert options.recorded_chunk_size(tmp_path / "none.zarr") is None


# -- the too-big refusal's estimate ------------------------------------------------------------


def _refusal(monkeypatch, fixed: dict, num: int = 1000) -> str:
    monkeypatch.setattr(limits, "usable_cores", lambda: 2)
    grid = {
        "angle": {"start": "10 deg", "stop": "80 deg", "num": num},
        "vy": {"start": -3.5, "stop": -1.0, "num": 1000},
        "mu": {"start": 0.05, "stop": 0.5, "num": 101},
    }
    with pytest.raises(ValueError, match="more than max_cases") as err:
        Study.from_dict({"fixed": fixed, "grid": grid, "outputs": {"keep": ["e"]}})
    return str(err.value)


def test_the_refusal_estimates_the_time_by_body_and_friction(monkeypatch) -> None:
    flexible = _refusal(monkeypatch, {"body": "flexible_rod"})
    days = 101_000_000 * limits.FLEXIBLE_DROP_S / 2 / 86400  # 2.9 days, not 21.6 min
    assert f"about {days:,.1f} days on this machine's 2 core(s)" in flexible
    assert "(an estimate at about 201 drops/s per core" in flexible
    slip = _refusal(monkeypatch, {"friction": "partial_slip"})
    hours = 101_000_000 * limits.PARTIAL_SLIP_CASE_S / 2 / 3600
    assert f"about {hours:,.1f} h on this machine's 2 core(s)" in slip and "4,000 impacts/s" in slip
    rigid = _refusal(monkeypatch, {})
    assert "at about 112,000 impacts/s per core" in rigid  # the sweep benchmark, 224 000/s on 2
    assert f"about {101_000_000 / 224_000 / 60:.1f} min" in rigid


def test_a_sample_of_materials_counts_its_contact_models(monkeypatch) -> None:
    monkeypatch.setattr(limits, "usable_cores", lambda: 2)
    with pytest.raises(ValueError, match="contact models built on one core") as err:
        Study(
            fixed={"vy": -1.41, "mu": 0.2, "angle": 0.3, "flat_E": 200e9, "flat_nu": 0.3},
            sample=Sample(
                size=10**9, seed=1, inputs={"flat_yield_strength": Uniform(2.5e8, 3.5e8)}
            ),
        )
    seconds = 1e9 * (limits.RIGID_CASE_S / 2 + limits.CONTACT_MODEL_S)
    assert f"about {seconds / 86400:,.1f} days" in str(err.value)


# -- the uncertainty report of a store without a sample --------------------------------------


def test_a_grid_store_is_refused_before_its_points_are_listed(
    tmp_path, fake, monkeypatch, capsys
) -> None:
    res = run_sweep(Study(name="g", **BASE), tmp_path / "g.zarr", evaluator=fake, quiet=True)

    def listed(*args):  # the grid points of a large store took minutes to list
        raise AssertionError("grid points listed before the sample was checked")

    monkeypatch.setattr(uncertainty_module, "_point_titles", listed)
    with pytest.raises(ValueError, match="needs a Monte Carlo sweep"):
        uncertainty_reports(open_sweep(res.path))
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(res.path))
    assert code == 2 and "needs a Monte Carlo sweep (a 'sample' dimension)" in err


# -- the throughput of a run ---------------------------------------------------------------


def test_the_throughput_is_this_runs_cases_over_its_wall_time(tmp_path, fake) -> None:
    res = run_sweep(Study(name="t", **BASE), tmp_path / "t.zarr", evaluator=fake, quiet=True)
    assert res.stats.n_chunks == 1  # a single chunk has a throughput too
    one = run_summary(res, res.dataset, None, [], as_json=True)
    assert one["throughput"] == pytest.approx(2 / res.stats.wall_s) and one["cases_computed"] == 2
    # a resume that computed 640 000 of 1 000 000 cases in 10.7 s, its first chunk included
    res.stats.cases_computed, res.stats.wall_s = 640_000, 10.7
    res.stats.first_task_s, res.stats.first_task_cases = {"w": 1.9}, {"w": 65_536}
    assert run_throughput(res.stats) == pytest.approx(640_000 / 10.7)
    text = "59813 impacts/s (cases computed / wall time)"
    assert throughput_text(res.stats) == text
    assert run_summary(res, res.dataset, None, [], as_json=False)["throughput"] == text
    assert dict(_rows(res))["throughput"] == text  # the notebook's table
    data = run_summary(res, res.dataset, None, [], as_json=True)
    assert data["throughput"] == pytest.approx(640_000 / 10.7)
    nothing = SweepStats(cases_computed=0, wall_s=0.0)
    assert run_throughput(nothing) is None
    assert throughput_text(nothing) == "- (nothing computed)"
    assert dict(_rows(SimpleNamespace(stats=nothing, path="x.zarr")))["throughput"] == (
        "- (nothing computed)"
    )
