"""What a calibration says of its chain's length: the kept chain (after burn-in) against 50
autocorrelation times, with the steps that would do; an ESS that too short a chain cannot give
is not assessable; PSIS-LOO's numerical noise stays out of the notes."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
from impactlab.calibrate._arviz import az, quiet
from impactlab.calibrate.diagnostics import TAU_MULTIPLE, convergence_notes, steps_needed
from impactlab.calibrate.result import _loo
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")


def _summary(tau: float, rhat: float = 1.01, ess: float = 300.0):
    return {"mu": {"rhat": rhat, "ess_bulk": ess, "tau": tau}}


def test_the_chain_after_burn_in_is_measured_in_autocorrelation_times():
    """16 walkers x 1000 steps, half burnt, tau = 26: 19 tau kept, 1300 steps needed."""
    notes = convergence_notes(_summary(25.6), kept=500, burn=500, draws=8000)
    assert notes == [
        "mu: the chain is 500 steps after burn-in, 20 autocorrelation times (tau = 26 steps); "
        "50 are needed: run about 1800 steps with burn 500"
    ]
    assert convergence_notes(_summary(25.6), kept=1300, burn=500, draws=20800) == []
    # the whole chain is 51 tau long, the kept part 25: not enough
    assert convergence_notes(_summary(25.6), kept=650, burn=650, draws=8000) != []


@pytest.mark.parametrize(
    ("tau", "burn", "steps"),
    [(25.6, 500, 1800), (0.37, 6, 25), (30.0, 500, 2000), (100.0, 5000, 10_000)],
)
def test_steps_needed_keep_50_autocorrelation_times(tau, burn, steps):
    assert steps_needed(tau, burn) == steps
    assert steps - burn >= TAU_MULTIPLE * tau


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")  # a short chain
def test_an_ess_above_the_number_of_draws_is_not_assessable(template):
    """6 draws per walker x 8 walkers: ArviZ reports 80.7 (its cap, N log10 N), more than the
    48 draws: not a number, and the notes say why."""
    data = synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip
    cal = calibrate(data, [MU], walkers=8, steps=12, burn=6, n_ppc=0)
    s = cal.best.summary["mu"]
    assert math.isnan(s["ess_bulk"]) and math.isfinite(s["rhat"])
    assert any(
        c.startswith("mu: ESS not assessable (the estimate exceeds the 48 draws")
        for c in cal.best.convergence
    )
    assert not cal.best.converged


def test_overflow_in_the_pareto_fit_is_not_a_note():
    """A tail the smoothing cannot tame: numpy's overflow inside ArviZ's Pareto fit (weights
    of 0, the right limit) is no note; the Pareto k count is."""
    rng = np.random.default_rng(0)
    x = np.cumsum(rng.standard_normal((16, 200)), axis=1) * 0.05
    ll = np.stack([-0.5 * (x / 0.1) ** 2, -0.5 * ((x - 0.3) / 0.05) ** 2], axis=-1)
    with quiet():
        idata = az.from_dict(posterior={"a": x}, log_likelihood={"drops": ll})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        az.loo(idata, pointwise=True)
    assert any("overflow" in str(w.message) for w in caught)  # the case: numpy overflows
    loo, notes, pointwise = _loo(idata)
    assert pointwise.shape == (2,) and pointwise.sum() == pytest.approx(loo["elpd"])
    assert math.isfinite(loo["elpd"])
    assert notes == ["PSIS-LOO: 2 drop(s) with Pareto k > 0.7"]
