"""The posterior predictive figure draws the band with the noise within the quantity's possible
range: a length's never below 0, e's never above 1 unless the model itself predicts more (its
gravity impulse removed); a signed quantity's as computed."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

from impactlab.calibrate import parse_parameter
from impactlab.calibrate.plots import in_range, ppc_figure
from impactlab.calibrate.result import ModelPosterior


def _row(drop: str, q: str, unit: str, med: float, band: tuple[float, ...]) -> dict[str, Any]:
    q05, q95, pred_q05, pred_q95 = band
    return {"drop": drop, "quantity": q, "unit": unit, "observed": med, "sigma": 1.0,
            "best": med, "median": med, "q05": q05, "q95": q95, "pred_q05": pred_q05,
            "pred_q95": pred_q95, "z_best": 0.0}  # fmt: skip


ROWS = [
    # a dent of 1 um +- 2 um: the Gaussian band reaches -2.3 um
    _row("a", "delta_p", "m", 1e-6, (0.8e-6, 1.2e-6, -2.3e-6, 4.3e-6)),
    _row("b", "delta_p", "m", 5e-6, (4.8e-6, 5.2e-6, 1.7e-6, 8.3e-6)),
    _row("a", "e", "1", 0.98, (0.97, 0.99, 0.93, 1.03)),  # noise past 1: cut at 1
    _row("b", "e", "1", 1.004, (1.002, 1.006, 0.95, 1.05)),  # the model's e above 1: kept
    _row("a", "sliding_length", "m", -1e-6, (-1.2e-6, -0.8e-6, -4e-6, 2e-6)),  # signed
    _row("b", "sliding_length", "m", 1e-6, (0.8e-6, 1.2e-6, -2e-6, 4e-6)),
]


def _posterior() -> ModelPosterior:
    s = np.full((4, 1), 0.2)
    return ModelPosterior(
        model="ghaednia/coulomb", params=(parse_parameter("mu", "uniform(0, 0.6)"),), samples=s,
        chains=s[None], log_lik=np.zeros((1, 4, 2)), summary={}, best={"mu": 0.2},
        best_log_prob=0.0, loo={}, ppc=ROWS, failures={}, evaluations=0, acceptance=0.7,
        steps=20, burn=10,
    )  # fmt: skip


def _bands(ax: Any) -> tuple[np.ndarray, np.ndarray]:
    """(noise band, model band) of the one model on ``ax``: (drops, 2) [low, high] each."""
    noisy, model = ax.collections[-2:]  # drawn after the measured values' error bars
    segs = [np.array([[s[0, 1], s[1, 1]] for s in c.get_segments()]) for c in (noisy, model)]
    return segs[0], segs[1]


def test_the_noise_band_stays_in_the_quantitys_range() -> None:
    fig = ppc_figure({"ghaednia/coulomb": _posterior()})
    try:
        axes = {ax.get_ylabel().split(" [")[0]: ax for ax in fig.axes}
        noisy, model = _bands(axes["delta_p"])  # um
        assert noisy[:, 0] == pytest.approx([0.0, 1.7]) and noisy[:, 1] == pytest.approx([4.3, 8.3])
        assert model == pytest.approx(np.array([[0.8, 1.2], [4.8, 5.2]]))
        noisy, model = _bands(axes["e"])
        assert noisy == pytest.approx(np.array([[0.93, 1.0], [0.95, 1.006]]))
        assert model == pytest.approx(np.array([[0.97, 0.99], [1.002, 1.006]]))
        noisy, _ = _bands(axes["sliding_length"])
        assert noisy == pytest.approx(np.array([[-4.0, 2.0], [-2.0, 4.0]]))
    finally:
        import matplotlib.pyplot as plt

        plt.close(fig)


def test_in_range_keeps_what_is_not_predicted() -> None:
    lo, hi = in_range("duration", np.array([-1e-5, np.nan]), np.array([2e-4, np.nan]),
                      np.array([5e-5, np.nan]), np.array([1e-4, np.nan]))  # fmt: skip
    assert lo[0] == 0.0 and hi[0] == 2e-4 and np.isnan(lo[1]) and np.isnan(hi[1])
    same = in_range("not_a_quantity", np.array([-1.0]), np.array([1.0]), np.array([0.0]),
                    np.array([0.5]))  # fmt: skip
    assert same[0][0] == -1.0 and same[1][0] == 1.0
