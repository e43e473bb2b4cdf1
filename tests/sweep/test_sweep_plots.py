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
            "angle": np.radians(np.linspace(5, 85, 17)),
            "mu": np.linspace(0, 0.6, 13),
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
