"""Flagged cases (a result flag that says the case is not plain success) are not used as plain
data: the uncertainty report excludes and counts them, the plots leave them blank and say how
many (impactlab.sweep.uncertainty, impactlab.sweep.plots)."""

from __future__ import annotations

import numpy as np
import xarray as xr

from impactlab.flags import ResultFlag
from impactlab.sweep.plots import plot_histograms, plot_output_map
from impactlab.sweep.uncertainty import format_report, uncertainty_report


def _sample(n: int = 20, n_gain: int = 11) -> xr.Dataset:
    rng = np.random.default_rng(3)
    mu = rng.uniform(0.1, 0.3, n)
    e = 0.6 - mu
    flags = np.zeros(n, dtype=np.int16)
    flags[:n_gain] = int(ResultFlag.ENERGY_GAIN)
    e[:n_gain] = 1.5  # energy-gain cases: e > 1
    flags[n_gain] |= int(ResultFlag.LAW_EXTRAPOLATED)  # advisory: stays
    ds = xr.Dataset(
        {
            "e": ("sample", e),
            "status": ("sample", np.zeros(n, dtype=np.int32)),
            "flags": ("sample", flags),
            "mu": ("sample", mu, {"distribution": "uniform(0.1, 0.3)"}),
        },
        coords={"sample": np.arange(n)},
    )
    ds["e"].attrs["units"] = "1"
    return ds


def test_uncertainty_excludes_and_counts_flagged_cases() -> None:
    rep = uncertainty_report(_sample(), outputs=["e"])
    assert rep.n_flagged == 11 and rep.n_invalid == 0 and not rep.flagged_included
    assert rep.summary.loc["e", "n"] == 9
    assert rep.summary.loc["e", "mean"] < 0.6  # the e = 1.5 cases are out
    text = format_report(rep)
    assert "flagged" in text and "11, excluded" in text
    both = uncertainty_report(_sample(), outputs=["e"], include_flagged=True)
    assert both.summary.loc["e", "n"] == 20 and both.to_dict()["n_flagged"] == 11


def test_plots_blank_and_count_flagged_cases() -> None:
    fig = plot_histograms(_sample(), ["e"])
    assert "11 flagged cases excluded" in fig.axes[0].get_title()
    angle = np.radians([10.0, 20.0, 30.0, 40.0])
    flags = np.array([0, int(ResultFlag.ENERGY_GAIN), 0, 0], dtype=np.int16)
    ds = xr.Dataset(
        {
            "e": ("angle", np.array([0.5, 1.4, 0.5, 0.4])),
            "status": ("angle", np.zeros(4, dtype=np.int32)),
            "flags": ("angle", flags),
        },
        coords={"angle": angle},
    )
    ds["angle"].attrs["units"] = "rad"
    ax = plot_output_map(ds, "e", x="angle")
    assert "1 flagged case blank" in ax.get_title()
    line = ax.get_lines()[0]
    assert np.isnan(line.get_ydata()[1])
