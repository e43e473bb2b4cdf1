"""Plots of a study with more dimensions than a map shows. A 4-D study is drawn as
rows x columns of panels (every dimension shown); a fifth dimension is sliced, and the figure's
title and one SliceWarning say which value is shown and how to choose another (``sel``)."""

from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np
import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Study, plot_output_map, plot_regime_map, plot_sweep, run_sweep
from impactlab.sweep.plots import SliceWarning

GRID = {
    "angle": np.radians([20.0, 45.0, 70.0]),
    "mu": [0.1, 0.3],
    "vy": [-1.0, -2.0],
    "law": ["ghaednia", "hertz"],
}


def _sweep(tmp_path, **extra):
    # a flat by values: flat_E with the rest of the flat (no library material is partly changed)
    fixed = {"flat_nu": 0.3, "flat_yield_strength": 305e6} if "flat_E" in extra else {}
    st = Study(name="d", grid={**GRID, **extra}, fixed=fixed)
    return run_sweep(st, tmp_path / "d.zarr", evaluator=FakeEvaluator(), quiet=True)


@pytest.fixture(scope="module")
def five_d(tmp_path_factory):
    """The 5-D store (flat_E the fifth dimension) of the tests, which only read it."""
    return _sweep(tmp_path_factory.mktemp("five_d"), flat_E=[200e9, 100e9])


def test_four_dimensions_as_rows_and_columns(tmp_path) -> None:
    ds = _sweep(tmp_path).dataset
    with warnings.catch_warnings():
        warnings.simplefilter("error", SliceWarning)  # nothing is left out
        axes = plot_regime_map(ds)
        assert axes.shape == (2, 2)  # columns: vy, rows: law
        titles = [a.get_title() for a in axes.flat]
        assert "vy = -1 m/s, law = ghaednia" in titles[0]
        assert "vy = -2 m/s, law = hertz" in titles[3]
        assert axes[0, 0].figure.get_suptitle() == "columns: vy, rows: law"
        plt.close("all")
        axes = plot_output_map(ds, "e", x="angle", y="vy")
        assert axes.shape == (2, 2) and "mu = 0.3, law = hertz" in axes[1, 1].get_title()
        plt.close("all")


def test_fifth_dimension_named_in_title_and_one_warning(tmp_path, five_d) -> None:
    ds = five_d.dataset
    with pytest.warns(SliceWarning) as record:
        # the regime map and the map of e: two plots of the same slice (``sweep plot`` below
        # draws every default plot, with one line)
        files = plot_sweep(ds, tmp_path / "plots", outputs=["e"])
    notes = [str(w.message) for w in record if w.category is SliceWarning]
    assert len(notes) == 1  # one note for all the plots of the same slice
    assert "show only flat_E = 200 GPa (first of 2 values)" in notes[0]
    assert "sel={'flat_E': 100000000000.0}" in notes[0]
    assert {f.name for f in files} == {"regime_map.png", "e_angle_vy.png"}
    with pytest.warns(SliceWarning):
        axes = plot_regime_map(ds)
    sup = axes[0, 0].figure.get_suptitle()
    assert sup.startswith("columns: vy, rows: law; fixed: flat_E = 200 GPa")
    assert "flat_E = 200 GPa" in axes[0, 0].get_title()
    plt.close("all")
    with warnings.catch_warnings():
        warnings.simplefilter("error", SliceWarning)  # a chosen slice is not a surprise
        axes = plot_regime_map(ds, sel={"flat_E": 100e9})
        assert "flat_E = 100 GPa" in axes[0, 0].get_title()
    plt.close("all")


def test_cli_plot_states_the_slice_in_one_line(tmp_path, five_d, monkeypatch, capsys) -> None:
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "plot", str(five_d.path), "--out", str(tmp_path)
    )
    assert code == 0 and "regime_map.png" in out
    lines = err.splitlines()
    assert len(lines) == 1 and lines[0].startswith(
        "warning: more dimensions than a figure shows"
    ), err
    assert "flat_E = 200 GPa" in lines[0]
