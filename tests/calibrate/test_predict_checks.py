"""``Calibration.predict`` checks the drops to predict as ``calibrate`` checks the measured ones
(``input_checks``): a calibrated material property is refused for a drop on another material
than the calibrated drops', a drop's value of a calibrated parameter is warned about (the
posterior draws replace it), and a rod of another material needs its mass (formerly each was
predicted without a word)."""

from __future__ import annotations

import warnings

import pytest

from impactlab.calibrate import (
    Calibration,
    CalibrationWarning,
    Measurements,
    calibrate,
    parse_parameter,
)
from impactlab.calibrate.drop_predictions import predict_drops

SY = parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)")
DROP = {"angle": "20 deg", "vy": -1.41, "mu": 0.2, "e": 0.45, "e_sigma": 0.02}
NEW = {"label": "new", "angle": "30 deg", "vy": -2.0, "mu": 0.2}


@pytest.fixture(scope="module")
def cal() -> Calibration:
    drops = [{**DROP, "label": "a"}, {**DROP, "label": "b", "angle": "45 deg", "vy": -2.18}]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return calibrate(Measurements.from_records(drops), [SY], walkers=6, steps=12, n_ppc=0)


def _predict(cal: Calibration, conditions: list[dict]) -> object:
    return predict_drops(cal.posteriors, cal.settings, conditions, ["e"], draws=3,
                         calibrated=cal.measurements)  # fmt: skip


def test_a_calibrated_property_is_refused_on_another_material(cal: Calibration) -> None:
    with pytest.raises(ValueError, match=(
        r"model 'ghaednia/coulomb' cannot predict these drops: flat_yield_strength is one free "
        r"parameter.*flat_material differ \(aisi-1010: a \(calibrated\), b \(calibrated\); "
        r"al-6061-t6: al\)"
    )):  # fmt: skip
        _predict(cal, [{**NEW, "label": "al", "flat_material": "al-6061-t6"}])
    with pytest.raises(ValueError, match=r"al-6061-t6: al\)"):  # through Calibration.predict
        cal.predict([{**NEW, "label": "al", "flat_material": "al-6061-t6"}], draws=3)
    with pytest.raises(ValueError, match="flat_material differ"):  # among the new drops too
        cal.predict([NEW, {**NEW, "label": "al", "flat_material": "al-6061-t6"}], draws=3)


def test_the_calibrated_material_and_another_rod_side_are_predicted(cal: Calibration) -> None:
    sphere = {"label": "sphere", "body": "sphere", "radius": 0.01, "vy": -1.0, "mu": 0.2}
    got = _predict(cal, [NEW, sphere])
    assert got.labels == ("new", "sphere")  # type: ignore[attr-defined]


def test_a_given_value_of_a_calibrated_parameter_is_warned_about(cal: Calibration) -> None:
    with pytest.warns(CalibrationWarning, match=(
        r"flat_yield_strength is a free parameter: the value given for 1 drop\(s\) to predict "
        r"is not used: model 'ghaednia/coulomb' predicts with its posterior draws"
    )):  # fmt: skip
        cal.predict([{**NEW, "flat_yield_strength": "2 GPa"}], draws=3)
    with warnings.catch_warnings(record=True) as seen:
        warnings.simplefilter("always")
        cal.predict([NEW], draws=3)
    assert not [w for w in seen if "free parameter" in str(w.message)]


def test_a_rod_of_another_material_needs_its_mass(cal: Calibration) -> None:
    with pytest.raises(ValueError, match=r"drop 'r': give the rod's mass"):
        cal.predict([{**NEW, "label": "r", "body_material": "al-6061-t6"}], draws=3)
