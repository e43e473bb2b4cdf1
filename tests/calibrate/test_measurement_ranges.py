"""A measured value against its quantity's possible range: e leaves out the gravity impulse of
the contact, (v_n,out + g T)/|v_n,in|, so a near-elastic impact gives e above 1 (1 + g T/|vy|),
and a value within 3 sigma of the range is measurement noise. The package refused a file of
near-elastic drops that it had written itself."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.calibrate import Measurements, parse_model, read_measurements
from impactlab.calibrate.priors import parse_parameter
from impactlab.calibrate.synthetic import synthetic_measurements

MU = parse_parameter("mu", "uniform(0, 0.6)")


def _spheres(e=0.9, e_sigma=0.01, speeds=(0.1, 0.3, 1.0), **extra):
    return [
        {"label": f"s{v}", "body": "sphere", "radius": "5 mm", "vy": -v, "mu": 0.1, "e": e,
         "e_sigma": e_sigma, **extra}
        for v in speeds
    ]  # fmt: skip


def test_a_synthetic_file_of_near_elastic_drops_reads_back(tmp_path):
    """hertz/coulomb predicts e = 1 + g T/v (1.0055 at 0.1 m/s); with noise 1.009."""
    m = Measurements.from_records(_spheres())
    data = synthetic_measurements(m, parse_model("hertz/coulomb"), [MU], [0.0],
                                  np.random.default_rng(1))  # fmt: skip
    assert data.observed["e"].max() > 1.005
    back = read_measurements(data.to_csv(tmp_path / "elastic.csv"))
    np.testing.assert_allclose(back.observed["e"], data.observed["e"], rtol=1e-12)


def test_the_noise_free_prediction_above_1_is_accepted_with_a_small_sigma():
    """e = 1.0055 +- 0.0005 at 0.1 m/s: 11 sigma above 1, within the gravity allowance."""
    m = Measurements.from_records(_spheres(e=1.0055, e_sigma=0.0005, speeds=(0.1,)))
    assert m.observed["e"][0] == 1.0055


def test_e_within_3_sigma_of_its_range_is_noise_beyond_is_refused():
    """At 1.4 m/s the range ends at 1 + g (2 ms)/1.4 m/s = 1.01401; 3 sigma = 0.03 more."""
    rec = {"label": "x", "angle": "20 deg", "vy": -1.4, "mu": 0.2, "e_sigma": 0.01}
    for ok in (1.04, -0.029):
        Measurements.from_records([{**rec, "e": ok}])
    for bad in (1.045, -0.031):
        with pytest.raises(ValueError, match="lies outside the possible range") as info:
            Measurements.from_records([{**rec, "e": bad}])
        text = str(info.value)
        assert f"e = {bad:g} lies outside the possible range [0, 1.01401] by more than 3" in text
        assert "(e_sigma = 0.01; within 3 sigma a value is read as measurement noise)" in text
        assert "(v_n,out + g T)/|v_n,in|, reaches 1 + g T/|vy|" in text
        assert "\n" not in text


def test_a_measured_duration_longer_than_2_ms_widens_the_allowance():
    """T = 20 ms at 0.1 m/s: e up to 1 + 9.80665 x 0.02/0.1 = 2.96."""
    long = {"duration": "20 ms", "duration_sigma": "1 ms"}
    m = Measurements.from_records(_spheres(e=2.5, speeds=(0.1,), **long))
    assert m.observed["e"][0] == 2.5
    with pytest.raises(ValueError, match=r"range \[0, 1.19613\] by more than 3 sigma"):
        Measurements.from_records(_spheres(e=2.5, speeds=(0.1,)))


def test_other_bounded_quantities_take_their_noise_too():
    """A shallow dent measured at -0.5 +- 1 um, e_energy 1.01 +- 0.01, angle_out 181 +- 1 deg."""
    rec = {"label": "x", "angle": "20 deg", "vy": -1.4, "mu": 0.2}
    m = Measurements.from_records([
        {**rec, "delta_p": "-0.5 um", "delta_p_sigma": "1 um", "e_energy": 1.01,
         "e_energy_sigma": 0.01, "angle_out": "181 deg", "angle_out_sigma": "1 deg"}
    ])  # fmt: skip
    assert m.observed["delta_p"][0] == pytest.approx(-0.5e-6)
    text = r"angle_out = 190 deg lies outside the possible range \[0, 180\] deg by more than 3"
    with pytest.raises(ValueError, match=text + r" sigma \(angle_out_sigma = 1 deg;"):
        Measurements.from_records([{**rec, "angle_out": "190 deg", "angle_out_sigma": "1 deg"}])
