"""Plots of a sweep: regime map with the analytic mu_c boundary, output maps, histograms."""

from __future__ import annotations

import matplotlib

matplotlib.use("Agg")

import matplotlib.pyplot as plt
import numpy as np

from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD
from impactlab.sweep import (
    Normal,
    Sample,
    Study,
    plot_regime_map,
    plot_sweep,
    run_sweep,
)


def test_regime_map_draws_mu_c(tmp_path, fake) -> None:
    st = Study(
        name="map",
        grid={
            "angle": np.radians(np.linspace(5, 85, 9)),
            "mu": np.linspace(0, 0.6, 4),  # each output map has a panel per mu
            "vy": [-1.0, -2.0],
        },
    )
    ds = run_sweep(st, tmp_path / "m.zarr", evaluator=fake, quiet=True).dataset
    fig, ax = plt.subplots()
    plot_regime_map(ds, ax=ax, sel={"vy": -2.0})
    (line,) = [ln for ln in ax.get_lines() if "mu_c" in ln.get_label()]
    th = np.radians(line.get_xdata())
    np.testing.assert_allclose(line.get_ydata(), critical_friction(th, PAPER_ROD), rtol=1e-12)
    plt.close(fig)
    files = {f.name for f in plot_sweep(ds, tmp_path / "plots")}
    assert "regime_map.png" in files
    assert {
        "e_angle_vy.png",
        "delta_p_angle_vy.png",
        "sliding_length_angle_vy.png",
        "duration_angle_vy.png",
    } <= files


def test_sample_histograms(tmp_path, fake) -> None:
    st = Study(
        name="mc",
        fixed={"angle": 0.35, "mu": 0.2},
        sample=Sample(size=200, seed=1, inputs={"vy": Normal(-1.4, 0.1)}),
    )
    ds = run_sweep(st, tmp_path / "h.zarr", evaluator=fake, quiet=True).dataset
    files = plot_sweep(ds, tmp_path / "p")
    assert [f.name for f in files] == ["histograms.png"] and files[0].stat().st_size > 0


def test_regime_map_leaves_flagged_cases_blank() -> None:
    """A case computed but not plain success (here BEYOND_TIP, 16) is left blank and marked x,
    as in the output maps; an advisory LAW_EXTRAPOLATED (4) case is drawn."""
    import xarray as xr

    angle, mu = np.radians([5.0, 20.0, 40.0]), np.array([0.1, 0.3])
    regime = np.ones((3, 2))
    flags = np.array([[16, 16], [4, 0], [0, 4]], dtype=np.int16)
    ds = xr.Dataset(
        {
            "regime": (("angle", "mu"), regime, {"regimes": {"1": "slip"}}),
            "status": (("angle", "mu"), np.zeros((3, 2), dtype=np.int32)),
            "flags": (("angle", "mu"), flags),
        },
        coords={"angle": angle, "mu": mu},
    )
    fig, ax = plt.subplots()
    plot_regime_map(ds, ax=ax, show_mu_c=False)
    shown = np.ma.getdata(ax.collections[0].get_array()).reshape(2, 3)  # (mu, angle)
    assert np.isnan(shown[:, 0]).all() and np.isfinite(shown[:, 1:]).all()
    marks = [ln for ln in ax.get_lines() if ln.get_marker() == "x"]
    assert len(marks) == 1 and len(marks[0].get_xdata()) == 2
    assert "2 flagged cases blank" in ax.get_title()
    plt.close(fig)
