"""The uncertainty report: spread of the outputs, and the ranking finds the dominant input."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.sweep import (
    Normal,
    Sample,
    Study,
    UncertaintySpec,
    Uniform,
    run_sweep,
    status_counts,
    store_info,
    uncertainty_report,
    uncertainty_reports,
)
from impactlab.sweep.uncertainty import format_report


def _mc(tmp_path, fake, grid=None):
    # fake engine: e = 0.5 + 0.1 sin(angle) - 0.2 mu; delta_p = 1e-5 |vy| 200e9/flat_E;
    # F = 1000 |vy|. mu (std 0.058) dominates e, flat_E (10 %) dominates delta_p over vy (2 %).
    st = Study(
        name="mc",
        chunk_size=1000,
        grid=grid or {},
        fixed={"flat_nu": 0.3, "flat_yield_strength": 305e6},  # the flat whole, E sampled
        sample=Sample(
            size=4000,
            seed=5,
            inputs={
                "angle": Normal(0.35, 0.01),
                "vy": Normal(-1.41, 0.03),
                "mu": Uniform(0.1, 0.3),
                "flat_E": Normal(200e9, 20e9, low=100e9),
            },
        ),
    )
    return run_sweep(st, tmp_path / "mc.zarr", evaluator=fake, quiet=True).dataset


def test_ranking_finds_the_dominant_input(tmp_path, fake) -> None:
    ds = _mc(tmp_path, fake)
    rep = uncertainty_report(ds, outputs=["e", "delta_p", "F", "T"])
    assert rep.dominant("e") == "mu"
    assert rep.dominant("delta_p") == "flat_E"
    assert rep.ranking("delta_p")[1] == "vy"
    assert rep.dominant("mean_force") == "vy"
    sens = rep.sensitivity.set_index(["output", "input"])
    # F depends on vy alone and linearly: rho^2 = SRC^2 = R^2 = 1
    assert sens.loc[("mean_force", "vy"), "rank_corr2"] == pytest.approx(1.0)
    assert sens.loc[("mean_force", "vy"), "src2"] == pytest.approx(1.0)
    assert sens.loc[("mean_force", "mu"), "rank_corr2"] < 0.01
    # e is linear in mu and nearly so in angle: SRC^2 add up to R^2 ~ 1
    e = rep.sensitivity[rep.sensitivity.output == "e"]
    assert e["r2"].iloc[0] == pytest.approx(1.0, abs=1e-6)
    assert e["src2"].sum() == pytest.approx(1.0, abs=0.02)
    # a constant output (T) has no sensitivity
    assert (rep.sensitivity[rep.sensitivity.output == "duration"]["rank_corr2"] == 0).all()
    s = rep.summary
    assert s.loc["mean_force", "mean"] == pytest.approx(1410.0, rel=2e-3)
    assert s.loc["mean_force", "std"] == pytest.approx(30.0, rel=0.05)
    assert s.loc["mean_force", "p2.5"] == pytest.approx(1410 - 1.96 * 30, rel=3e-3)
    assert s.loc["e", "n"] == 4000 and rep.n_invalid == 0
    text = format_report(rep)
    assert "mean_force: vy 1.000" in text


def test_report_needs_a_sample_and_one_grid_point(tmp_path, fake) -> None:
    ds = _mc(tmp_path, fake, grid={"law": ["ghaednia", "hertz"]})
    with pytest.raises(ValueError, match="select one grid point"):
        uncertainty_report(ds)
    rep = uncertainty_report(ds.isel(law=1), outputs=["e"])
    assert rep.dominant("e") == "mu"
    with pytest.raises(ValueError, match="not in the sweep"):
        uncertainty_report(ds.isel(law=0), outputs=["bogus"])
    with pytest.raises(ValueError, match="needs a Monte Carlo"):
        uncertainty_report(ds.isel(sample=0))
    assert np.isfinite(rep.summary.loc["e", "std"])


def test_one_report_per_grid_point_with_the_study_defaults(tmp_path, fake) -> None:
    st = Study(
        name="mcg",
        chunk_size=1000,
        grid={"law": ["ghaednia", "hertz"]},
        sample=Sample(
            size=500, seed=3, inputs={"vy": Normal(-1.41, 0.03), "mu": Uniform(0.1, 0.3)}
        ),
        fixed={"angle": 0.35},
        uncertainty=UncertaintySpec(outputs=("e", "F"), percentiles=(5.0, 95.0)),
    )
    ds = run_sweep(st, tmp_path / "mcg.zarr", evaluator=fake, quiet=True).dataset
    reports = uncertainty_reports(ds)
    assert list(reports) == ["law = ghaednia", "law = hertz"]
    for law, rep in reports.items():
        one = uncertainty_report(
            ds.sel(law=law.split(" = ")[1]), ["e", "mean_force"], percentiles=(5.0, 95.0)
        )
        assert list(rep.summary.index) == ["e", "mean_force"]
        assert {"p5", "p95"} <= set(rep.summary.columns)
        assert rep.summary.equals(one.summary)
    assert list(uncertainty_reports(ds, outputs=["delta_p"])["law = hertz"].summary.index) == [
        "delta_p"
    ]
    assert status_counts(ds) == {"0: finished": 1000}
    info = store_info(tmp_path / "mcg.zarr")
    assert info["chunks_done"] == info["chunks_total"] == st.layout.n_chunks
    assert info["dims"] == {"law": 2, "sample": 500} and info["status"] == {"0: finished": 1000}


def test_grid_points_are_named_in_display_units(tmp_path, fake) -> None:
    """An angle in degrees, a length in mm, a law by its name; values that five digits would
    name alike get more digits (every point keeps its own report)."""
    st = Study(
        name="mcu",
        chunk_size=1000,
        grid={
            "law": ["ghaednia", "hertz"],
            "angle": ["20 deg", "40 deg"],
            "tip_radius": ["8.8 mm", "8.800001 mm"],
        },
        sample=Sample(size=20, seed=3, inputs={"mu": Uniform(0.1, 0.3)}),
        fixed={"vy": -1.41},
    )
    ds = run_sweep(st, tmp_path / "mcu.zarr", evaluator=fake, quiet=True).dataset
    titles = list(uncertainty_reports(ds, outputs=["e"]))
    assert len(titles) == 8 and titles[0] == ("law = ghaednia, angle = 20 deg, tip_radius = 8.8 mm")
    assert titles[-1] == "law = hertz, angle = 40 deg, tip_radius = 8.800001 mm"
    two = Study(
        name="mcv",
        chunk_size=1000,
        grid={"angle": ["20 deg", "40 deg"]},
        sample=Sample(size=20, seed=3, inputs={"mu": Uniform(0.1, 0.3)}),
        fixed={"vy": -1.41},
    )
    ds = run_sweep(two, tmp_path / "mcv.zarr", evaluator=fake, quiet=True).dataset
    assert list(uncertainty_reports(ds, outputs=["e"])) == ["angle = 20 deg", "angle = 40 deg"]
