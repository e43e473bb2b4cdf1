"""The corner plot's titles give each parameter's median and 90 % interval with enough digits for
the interval: before, corner's one format (".2f") wrote mu = 0.2004 [0.1961, 0.2051] as
0.20 +0.00 -0.00."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.calibrate import parse_parameter
from impactlab.calibrate.plots import corner_figure, interval_title
from impactlab.calibrate.result import ModelPosterior


def _posterior(samples: np.ndarray) -> ModelPosterior:
    params = (
        parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)"),
        parse_parameter("mu", "uniform(0, 0.6)"),
    )
    med = np.median(samples, axis=0)
    return ModelPosterior(
        model="ghaednia/coulomb", params=params, samples=samples, chains=samples[None],
        log_lik=np.zeros((1, len(samples), 1)), summary={}, best={"flat_yield_strength": med[0],
        "mu": med[1]}, best_log_prob=0.0, loo={}, ppc=[], failures={}, evaluations=0,
        acceptance=0.7, steps=2000, burn=1000,
    )  # fmt: skip


def test_each_title_shows_its_interval():
    rng = np.random.default_rng(0)
    x = np.column_stack([329e6 + 11e6 * rng.standard_normal(4000),
                         0.2004 + 0.0027 * rng.standard_normal(4000)])  # fmt: skip
    fig = corner_figure(_posterior(x))
    axes = np.asarray(fig.axes).reshape(2, 2)
    titles = [axes[j, j].get_title() for j in range(2)]
    lo, mid, hi = np.quantile(x[:, 1], [0.05, 0.5, 0.95])
    assert titles[1] == rf"mu [-] = ${mid:.4f}_{{-{mid - lo:.4f}}}^{{+{hi - mid:.4f}}}$"
    assert "0.00}" not in titles[1]
    lo, mid, hi = np.quantile(x[:, 0] / 1e6, [0.05, 0.5, 0.95])
    assert titles[0] == (
        rf"flat_yield_strength [MPa] = ${mid:.0f}_{{-{mid - lo:.0f}}}^{{+{hi - mid:.0f}}}$"
    )


@pytest.mark.parametrize(
    ("centre", "spread", "expected"),
    [
        (0.2004, 0.0027, r"$0.2004_{-0.0044}^{+0.0044}$"),  # the shorter distance: 2 digits
        (328.9, 11.0, r"$329_{-18}^{+18}$"),
        (5.0, 0.0, r"$5_{-0}^{+0}$"),  # no spread
    ],
)
def test_interval_title_digits(centre, spread, expected):
    x = centre + spread * np.random.default_rng(0).standard_normal(16000)
    assert interval_title(x) == expected
