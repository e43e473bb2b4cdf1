"""Drops that were not measured predicted from a calibration; a prior without a likelihood
naming the drops at fault; a rate law's refusals and range named; correlation coefficients
fingerprinted as they act."""

from __future__ import annotations

import json

import numpy as np
import pytest

from impactlab.calibrate import (
    CandidateModel,
    Measurements,
    calibrate,
    parse_model,
    parse_parameter,
    predict,
)
from impactlab.calibrate.posterior import LogPosterior
from impactlab.calibrate.run_warnings import fitted_range_note
from impactlab.calibrate.sampler import _changed, _hash, _inputs

SY = parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")
DROP = {"angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.45, "e_sigma": 0.02}


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")
def test_drops_without_measurements_are_predicted_from_the_posterior():
    """'no measured quantity in any drop', and predict gave only the measured quantities."""
    new = Measurements.conditions([{"label": "new", "angle": "30 deg", "vy": -2.0, "mu": 0.2}])
    assert new.labels == ("new",) and new.quantities == ()
    with pytest.raises(ValueError, match=r"no measured quantity in any drop.*conditions"):
        Measurements.from_records([{"label": "new", "angle": "30 deg", "vy": -2.0}])
    model = parse_model("ghaednia/coulomb")
    pred = predict(model, new, [SY], np.array([[305e6], [400e6]]),
                   quantities=["e", "delta_p", "max_force"])  # fmt: skip
    assert set(pred.values) == {"e", "delta_p", "max_force"}
    assert np.isfinite(pred.values["max_force"]).all()
    with pytest.raises(ValueError, match="'peak' is not a measurable quantity"):
        predict(model, new, [SY], np.array([[305e6]]), quantities=["peak"])
    drops = [{**DROP, "label": "a"}, {**DROP, "label": "b", "angle": "45 deg", "vy": -2.18}]
    cal = calibrate(Measurements.from_records(drops), [SY], walkers=6, steps=12, n_ppc=0)
    got = cal.predict([{"label": "new", "angle": "30 deg", "vy": -2.0, "mu": 0.2}],
                      ["e", "delta_p", "max_force"], draws=5)  # fmt: skip
    rows = {r["quantity"]: r for r in got.summary()}
    assert got.values["delta_p"].shape == (5, 1) and got.model == "ghaednia/coulomb"
    assert rows["delta_p"]["q05"] <= rows["delta_p"]["median"] <= rows["delta_p"]["q95"]
    assert rows["max_force"]["unit"] == "N" and rows["e"]["failed"] == 0.0
    with pytest.raises(ValueError, match="give no mu, and mu was not calibrated"):
        cal.predict([{"label": "n", "angle": "30 deg", "vy": -2.0}])
    with pytest.raises(ValueError, match="model 'x' was not calibrated"):
        cal.predict([{"angle": "30 deg", "vy": -2.0, "mu": 0.2}], model="x")


def test_a_prior_without_a_likelihood_names_the_drops_at_fault():
    slow = Measurements.from_records([{**DROP, "label": "a"}, {**DROP, "label": "slow",
                                      "vy": -0.002}])  # fmt: skip
    with pytest.raises(ValueError, match=r"zero at every value drawn: 'slow' \(angle 20 deg, "
                       r"vy -0.002 m/s\): result flagged GRAVITY_DOMINATED"):  # fmt: skip
        calibrate(slow, [SY], walkers=6, steps=10, n_ppc=0)


def test_a_velocity_in_cm_s_given_bare_is_refused_with_the_unit_to_give():
    with pytest.raises(ValueError, match=r"column 'vy': vy = -141 m/s is below -100 m/s: an "
                       r"implausible magnitude .* e.g. '-141 cm/s'"):  # fmt: skip
        Measurements.from_records([{**DROP, "vy": -141}])


def test_a_rate_laws_refusal_is_named_with_its_range():
    """'simulate refused the case (or the drop failed)' hid the law's 150-450 MPa."""
    model = CandidateModel("ghaednia", "coulomb", body="flexible_rod", rate="cowper-symonds")
    meas = Measurements.from_records([DROP])
    post = LogPosterior(model, meas, [SY])
    post.evaluate(np.array([[110e6], [900e6], [120e6]]))
    (reason,) = post.failures
    assert reason.startswith("simulate refused the case: rate 'cowper-symonds': its constants")
    assert "outside 150 to 450 MPa" in reason and post.failures[reason] == 3


def test_a_posterior_against_a_rate_laws_range_is_warned():
    draws = np.random.default_rng(0).uniform(430e6, 450e6, 400)
    note = fitted_range_note(SY, draws, "cowper-symonds")
    assert note is not None and "against the upper end of the range the rate law" in note
    assert "450 MPa" in note and "150 MPa to 450 MPa" in note
    assert fitted_range_note(SY, draws, None) is None
    inside = np.random.default_rng(0).uniform(250e6, 350e6, 400)
    assert fitted_range_note(SY, inside, "cowper-symonds") is None


def _doc(**columns):
    recs = [{**DROP, "label": x, "spin_out": -10, "spin_out_sigma": 0.3, **columns} for x in "ab"]
    post = LogPosterior(parse_model("ghaednia/coulomb"), Measurements.from_records(recs), [SY])
    return _inputs(post, 8, 0)


def test_correlation_coefficients_are_fingerprinted_as_they_act():
    """A zero or blank column blocked resuming a chain saved without it."""
    none = _hash(_doc())
    assert _hash(_doc(correlation_e_spin_out=0)) == none
    assert _hash(_doc(correlation_e_spin_out="")) == none
    assert _hash(_doc(correlation_e_spin_out=-0.5)) != none
    zeros = _doc(correlation_e_spin_out=0)
    other = _doc(flat_material="al-6061-t6")
    parts = json.dumps({k: _hash(v) for k, v in zeros.items()})
    text = _changed(parts, {k: _hash(v) for k, v in other.items()})
    assert text == "was made with other inputs (the drops' bodies or materials changed)"
