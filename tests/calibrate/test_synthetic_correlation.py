"""Synthetic measurements of a template with correlation coefficients: each drop's noise has
the covariance D R D the likelihood gives its values; drops without a coefficient keep the
independent noise, the same numbers bit for bit."""

from __future__ import annotations

import numpy as np

from impactlab.calibrate import CandidateModel, Measurements, parse_parameter
from impactlab.calibrate.models import predict
from impactlab.calibrate.synthetic import synthetic_measurements

N = 400
RHO = -0.97
MU = parse_parameter("mu", "uniform(0, 0.6)")


def _template(coefficients: list[float | None] | None) -> Measurements:
    """``N`` copies of one drop measuring e, spin_out and delta_p, with the e-spin_out
    coefficient of each (None: none given; ``coefficients`` None: no column at all)."""
    recs = []
    for d in range(N):
        r = {"label": f"d{d}", "angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.42,
             "e_sigma": 0.02, "spin_out": -9.8, "spin_out_sigma": 0.3,
             "delta_p": 60e-6, "delta_p_sigma": 3e-6}  # fmt: skip
        if coefficients is not None:
            r["correlation_e_spin_out"] = coefficients[d]
        recs.append(r)
    return Measurements.from_records(recs)


def _noise(m: Measurements, seed: int) -> dict[str, np.ndarray]:
    """The synthetic set's noise over sigma (quantity -> (N,))."""
    data = synthetic_measurements(m, CandidateModel(), [MU], [0.15], np.random.default_rng(seed))
    pred = predict(CandidateModel(), m, [MU], np.array([[0.15]]))
    return {q: (data.observed[q] - pred.values[q][0]) / m.sigma[q] for q in m.quantities}


def test_the_noise_has_the_drops_correlation() -> None:
    """Noise of e and spin_out correlates as the coefficient; delta_p's stays independent
    (within 4 standard errors of Fisher's z, 1 / sqrt(N - 3), over the N drops)."""
    z = _noise(_template([RHO] * N), seed=1)
    bound = 4.0 / np.sqrt(N - 3)
    r = np.corrcoef(z["e"], z["spin_out"])[0, 1]
    assert abs(np.arctanh(r) - np.arctanh(RHO)) < bound
    assert abs(np.arctanh(np.corrcoef(z["e"], z["delta_p"])[0, 1])) < bound
    for q in z:  # each value keeps its sigma
        assert 0.85 < np.std(z[q]) < 1.15


def test_drops_without_a_coefficient_keep_the_independent_noise_bit_for_bit() -> None:
    """No column, coefficients of 0 and a drop without one give the numbers of independent
    noise drawn as before (one standard normal per value, quantity by quantity)."""
    plain = _template(None)
    params = [MU]
    pred = predict(CandidateModel(), plain, params, np.array([[0.15]]))
    rng = np.random.default_rng(3)
    before = {q: pred.values[q][0] + plain.sigma[q] * rng.standard_normal(N)
              for q in plain.observed}  # fmt: skip
    for template in (plain, _template([0.0] * N)):
        got = synthetic_measurements(template, CandidateModel(), params, [0.15],
                                     np.random.default_rng(3))  # fmt: skip
        for q in before:
            np.testing.assert_array_equal(got.observed[q], before[q])
    some = _template([RHO] + [None] * (N - 1))
    got = synthetic_measurements(some, CandidateModel(), params, [0.15], np.random.default_rng(3))
    for q in before:
        np.testing.assert_array_equal(got.observed[q][1:], before[q][1:])
    np.testing.assert_array_equal(got.observed["e"][0], before["e"][0])  # the first of R's rows
    assert got.observed["spin_out"][0] != before["spin_out"][0]
    assert got.correlation[("e", "spin_out")][0] == RHO
