"""Plots of a grid + sample study (maps of one sample, chosen by its index; histograms of one
grid point, named in the title), the regime map's axes when angle, mu and a velocity are all
swept, and ``sweep run --plot`` whose plots fail after the sweep finished."""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
from sweep_fakes import FakeEvaluator

from impactlab.sweep import (
    PlotSkipped,
    Sample,
    Study,
    Uniform,
    plot_output_map,
    plot_plan,
    plot_sweep,
    run_sweep,
)

SWEEP_TESTS = Path(__file__).resolve().parent


@pytest.fixture
def grid_sample(tmp_path, fake) -> Any:
    """angle x mu, then a sample of vx: dimensions angle, mu, sample (no coordinate)."""
    study = Study(
        name="gs",
        fixed={"vy": -1.41},
        grid={"angle": np.radians([10.0, 30.0, 50.0]), "mu": [0.1, 0.3]},
        sample=Sample(size=20, seed=3, inputs={"vx": Uniform(-0.05, 0.05)}),
    )
    return run_sweep(study, tmp_path / "gs.zarr", evaluator=fake, quiet=True).dataset


def _titles(axes: Any) -> list[str]:
    return [a.get_title() for a in np.ravel(axes)]


def test_grid_and_sample_study_is_plotted(tmp_path, grid_sample) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlotSkipped)
        files = {f.name for f in plot_sweep(grid_sample, tmp_path / "p")}
    assert {"regime_map.png", "e_angle_mu.png", "histograms.png"} <= files
    plan = dict(plot_plan(grid_sample).plots)
    assert all("sample = 0" in t for t in _titles(plan["regime_map.png"]()))
    (fig,) = {a.figure for a in plan["histograms.png"]()}
    assert fig.get_suptitle() == "angle = 10 deg, mu = 0.1"  # the grid point they count
    plt.close("all")


def test_the_sample_is_chosen_by_its_index(grid_sample) -> None:
    ax = plot_output_map(grid_sample, "e", x="angle", y="mu", sel={"sample": 7})
    assert "sample = 7" in ax.get_title()
    plt.close("all")
    with pytest.raises(ValueError, match=r"sel\['sample'\] must be an index in \[0, 19\]"):
        plot_output_map(grid_sample, "e", x="angle", y="mu", sel={"sample": 20})
    plt.close("all")


def test_regime_map_is_over_angle_and_mu_when_a_velocity_is_swept_too(tmp_path, fake) -> None:
    # the shape of examples/study-benchmark.toml: angle, vy and mu swept
    study = Study(
        name="avm",
        grid={
            "angle": np.radians([10.0, 30.0, 50.0]),
            "vy": [-1.0, -2.0],
            "mu": [0.0, 0.2, 0.4],
        },
    )
    ds = run_sweep(study, tmp_path / "avm.zarr", evaluator=fake, quiet=True).dataset
    plan = dict(plot_plan(ds).plots)
    assert "e_angle_vy.png" in plan  # the output maps: angle x the velocity
    axes = np.ravel(plan["regime_map.png"]())
    assert len(axes) == 2  # one panel per vy
    for ax in axes:
        assert ax.get_xlabel().startswith("angle") and ax.get_ylabel() == "mu"
        assert [ln for ln in ax.get_lines() if "mu_c" in ln.get_label()]
    plt.close("all")


@pytest.fixture
def fake_engine(monkeypatch: pytest.MonkeyPatch) -> None:
    """``run_sweep`` with the closed-form stand-in of the engine (sweep_fakes)."""
    import impactlab.sweep as sweep_pkg

    real = sweep_pkg.run_sweep

    def run_sweep(*args: Any, **kwargs: Any) -> Any:
        return real(*args, **{**kwargs, "evaluator": FakeEvaluator()})

    monkeypatch.setattr(sweep_pkg, "run_sweep", run_sweep)


@pytest.mark.parametrize("as_json", [False, True])
def test_failed_plots_keep_the_summary(
    cli_main: Any, tmp_path: Path, fake_engine: None, monkeypatch, as_json: bool
) -> None:
    import impactlab.sweep as sweep_pkg

    def broken(*args: Any, **kwargs: Any) -> Any:
        raise RuntimeError("the plotting failed")

    monkeypatch.setattr(sweep_pkg, "plot_sweep", broken)
    study = tmp_path / "g.toml"
    study.write_text("[fixed]\nvy = -1.41\nmu = 0.2\n[grid]\nangle = ['20 deg', '45 deg']\n")
    store = tmp_path / "g.zarr"
    args = ["sweep", "run", str(study), "--out", str(store), "--plot", str(tmp_path / "p")]
    code, out, err = cli_main(*args, *(["--json"] if as_json else []))
    assert code == 1
    assert err.count("\n") == 1 and err.startswith("error: --plot "), err
    assert "the plotting failed" in err and str(store) in err
    assert ('"cases": 2' if as_json else "chunks_computed") in out  # the summary printed
