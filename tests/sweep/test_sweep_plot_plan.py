"""Every study that can be plotted is plotted, and what cannot be is named with the reason:
sphere studies (no angle), angle x vy studies (regime map over them), single-input lines, and
regime codes on a categorical scale."""

from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pytest
from sweep_fakes import run_cli

from impactlab.sweep import PlotSkipped, Study, plot_output_map, plot_plan, plot_sweep, run_sweep

_AM = {"angle": 0.5, "mu": 0.2}


def _run(tmp_path, fake, name, **kw):
    return run_sweep(Study(name=name, **kw), tmp_path / f"{name}.zarr", evaluator=fake, quiet=True)


def test_sphere_study_is_plotted(tmp_path, fake) -> None:
    # a study without an angle axis (a sphere's): maps over its swept inputs
    ds = _run(
        tmp_path, fake, "sphere", fixed={"angle": 1.5},
        grid={"vy": [-0.5, -1.0, -2.0], "mu": [0.0, 0.2, 0.4]},
    ).dataset  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("error", PlotSkipped)
        files = {f.name for f in plot_sweep(ds, tmp_path / "p")}
    assert {"regime_map.png", "e_mu_vy.png", "delta_p_mu_vy.png"} <= files


def test_angle_vy_study_has_a_regime_map_without_mu_c(tmp_path, fake) -> None:
    ds = _run(
        tmp_path, fake, "av", fixed={"mu": 0.2},
        grid={"angle": np.radians([10.0, 30.0, 50.0]), "vy": [-1.0, -2.0]},
    ).dataset  # fmt: skip
    names = [n for n, _ in plot_plan(ds).plots]
    assert "regime_map.png" in names and "e_angle_vy.png" in names
    ax = plot_plan(ds).plots[0][1]()
    assert not [ln for ln in ax.get_lines() if "mu_c" in ln.get_label()]  # mu_c needs mu
    plt.close("all")


def test_single_input_lines_and_named_skips(tmp_path, fake) -> None:
    ds = _run(tmp_path, fake, "line", fixed=_AM, grid={"vy": [-0.5, -1.0, -2.0]}).dataset
    with pytest.warns(PlotSkipped) as caught:
        files = {f.name for f in plot_sweep(ds, tmp_path / "p", outputs=("e", "nope"))}
    said = [str(w.message) for w in caught]
    assert any("need two swept numeric inputs" in s for s in said), said
    assert any("nope: the study did not keep this output" in s for s in said), said
    assert files == {"e_vy.png"}
    assert any("nope: the study did not keep" in s for s in plot_plan(ds, ("nope",)).skipped)


def test_nothing_to_plot_says_why(tmp_path, fake) -> None:
    ds = _run(
        tmp_path, fake, "laws", fixed={"vy": -1.0, **_AM}, grid={"law": ["ghaednia", "hertz"]}
    ).dataset
    plan = plot_plan(ds)
    assert plan.plots == [] and any("only categories (law)" in s for s in plan.skipped)


def test_regime_as_output_is_categorical(tmp_path, fake) -> None:
    ds = _run(
        tmp_path, fake, "cat", fixed={"vy": -1.0},
        grid={"angle": np.radians([10.0, 30.0, 50.0]), "mu": [0.0, 0.3]},
    ).dataset  # fmt: skip
    ax = plot_output_map(ds, "regime", x="angle", y="mu")
    assert len(ax.figure.axes) == 1  # no continuous colour bar beside the map
    assert ax.get_legend() is not None
    line_ax = plot_output_map(ds, "regime", x="angle", sel={"mu": 0.3})
    labels = {t.get_text() for t in line_ax.get_yticklabels()}
    assert labels and not any(t.isdigit() for t in labels)  # names, not codes
    plt.close("all")


def test_cli_names_what_it_did_not_plot(tmp_path, fake, monkeypatch, capsys) -> None:
    _run(tmp_path, fake, "line", fixed=_AM, grid={"vy": [-0.5, -1.0, -2.0]})
    store, out = str(tmp_path / "line.zarr"), str(tmp_path / "p")
    code, stdout, err = run_cli(monkeypatch, capsys, "sweep", "plot", store, "--out", out)
    assert code == 0 and "e_vy.png" in stdout
    assert "not plotted: regime map and output maps: they need two swept numeric inputs" in err
    _run(tmp_path, fake, "laws", fixed={"vy": -1.0, **_AM}, grid={"law": ["ghaednia", "hertz"]})
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", "plot", str(tmp_path / "laws.zarr"), "--out", out
    )
    assert code != 0 and "nothing to plot: maps: they need a swept numeric input" in err
