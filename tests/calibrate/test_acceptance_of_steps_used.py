"""A run that uses the first steps of a longer saved chain reports the acceptance of those steps,
the one a run of that many steps gives; before, it reported the whole saved chain's."""

from __future__ import annotations

import emcee
import numpy as np
import pytest

from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
from impactlab.calibrate.result import _acceptance
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")
pytestmark = pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")


def _log_prob(x: np.ndarray) -> np.ndarray:
    return -0.5 * np.sum(x**2, axis=1)


def test_the_acceptance_of_the_first_steps_is_emcees_count_at_that_step():
    sampler = emcee.EnsembleSampler(8, 2, _log_prob, vectorize=True)
    start = np.random.default_rng(1).standard_normal((8, 2))
    sampler.random_state = np.random.RandomState(1).get_state()
    sampler.run_mcmc(start, 40)
    at_40 = np.array(sampler.backend.accepted)
    assert _acceptance(sampler, 40) == np.mean(sampler.acceptance_fraction)  # the whole chain
    sampler.run_mcmc(None, 25)
    assert _acceptance(sampler, 65) == np.mean(sampler.acceptance_fraction)
    assert _acceptance(sampler, 40) == pytest.approx(np.mean(at_40 / 40), rel=1e-12)
    assert _acceptance(sampler, 40) != pytest.approx(np.mean(sampler.acceptance_fraction))


def test_a_shorter_run_on_a_saved_chain_reports_its_own_acceptance(template, tmp_path):
    data = synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip
    kw = {"walkers": 6, "n_ppc": 0, "burn": 10}
    long = calibrate(data, [MU], steps=60, state_dir=tmp_path, **kw)
    short = calibrate(data, [MU], steps=20, state_dir=tmp_path, **kw)
    fresh = calibrate(data, [MU], steps=20, **kw)
    assert short.best.acceptance == pytest.approx(fresh.best.acceptance, rel=1e-12)
    assert short.best.acceptance != pytest.approx(long.best.acceptance)
