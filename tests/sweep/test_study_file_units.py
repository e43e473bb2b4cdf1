"""Quantities in a study file follow the rules of every text input (``impactlab.units``): one
number and one unit, the powers of the radian, no hertz for an angular velocity. A quantity
the Python API refuses is refused in a study file too, and one both accept has one value."""

from __future__ import annotations

import math
import re

import pytest

from impactlab.sweep import EngineOptions, Study

_BASE = {"angle": "20 deg", "vy": -1.41, "mu": 0.2}


def _file(where: str, name: str, value: object) -> Study:
    fixed = {k: v for k, v in _BASE.items() if k != name}
    if where == "grid":
        return Study.from_dict({"fixed": fixed, "grid": {name: [value]}})
    return Study.from_dict({"fixed": {**fixed, name: value}, "grid": {"vx": [0.0, 0.1]}})


def _api(name: str, value: object) -> Study:
    fixed = {k: v for k, v in {**_BASE, "angle": math.radians(20)}.items() if k != name}
    return Study(grid={name: [value]}, fixed=fixed)


@pytest.mark.parametrize(
    ("name", "value", "message"),
    [
        ("mu", "20 percent", "'20 percent' is not a plain number; this input has no unit"),
        ("angle", "1 percent", "'1 percent' is not an angle"),
        ("angle", "20 deg 3", "'20 deg 3' holds more than one number"),
        ("angle", "20 deg deg", "'20 deg deg' has dimensionless units .* to the power 2"),
        ("angle", "1 sr", "'1 sr' is not an angle"),
        ("vy", "-1.41 m/s 2", "'-1.41 m/s 2' holds more than one number"),
        ("spin", "5 Hz", "'5 Hz' is a frequency in hertz"),
        ("vy", "0.2 dimensionless", "'0.2 dimensionless' is a pure number"),
        ("angle", "20 degC", "'20 degC' is a temperature"),
    ],
)
@pytest.mark.parametrize("where", ["grid", "fixed"])
def test_a_malformed_quantity_is_refused_by_the_file_as_by_the_api(
    where, name, value, message
) -> None:
    with pytest.raises(ValueError, match=f"\\[{where}\\] {name}: {message}") as caught:
        _file(where, name, value)
    assert "\n" not in str(caught.value)
    with pytest.raises(ValueError, match=name):
        _api(name, value)


@pytest.mark.parametrize(
    ("name", "value", "si"),
    [
        ("angle", "20 deg", math.radians(20)),
        ("angle", "0.35 rad", 0.35),
        ("spin", "30 rpm", math.pi),
        ("spin", "10 deg/s", math.radians(10)),
        ("vy", "-1410 mm/s", -1.41),
    ],
)
def test_a_quantity_both_accept_has_one_value(name, value, si) -> None:
    from_file = _file("grid", name, value).axes[0].values[0]
    assert from_file == pytest.approx(si, rel=1e-12)
    assert from_file == _api(name, value).axes[0].values[0]


def test_a_table_unit_keeps_its_scale() -> None:
    """``unit = "percent"`` scales the bare numbers (20 is 0.2); a bare number string is a
    number, as a bare number is."""
    grid = {"mu": {"values": [10, 20], "unit": "percent"}}
    assert Study.from_dict({"fixed": {"vy": -1.41, "angle": "20 deg"}, "grid": grid}).axes[
        0
    ].values == (0.1, 0.2)
    plain = Study.from_dict({"fixed": {"vy": -1.41, "angle": "20 deg"}, "grid": {"mu": ["0.2"]}})
    assert plain.axes[0].values == (0.2,)


@pytest.mark.parametrize(
    ("unit", "message"),
    [
        ("percent", "'10 percent' is not an angle"),
        ("sr", "'10 sr' is not an angle"),
        ("m/s 2", "unit 'm/s 2' is not a unit"),
    ],
)
def test_a_table_unit_follows_the_same_rules(unit, message) -> None:
    grid = {"angle": {"values": [10, 20], "unit": unit}}
    with pytest.raises(ValueError, match=message):
        Study.from_dict({"fixed": {"vy": -1.41, "mu": 0.2}, "grid": grid})


def test_a_sampled_input_follows_the_same_rules() -> None:
    sample = {"size": 4, "seed": 1, "mu": {"dist": "uniform", "low": "10 percent", "high": 0.3}}
    with pytest.raises(ValueError, match=r"mu\.low: '10 percent' is not a plain number"):
        Study.from_dict({"fixed": {"vy": -1.41, "angle": "20 deg"}, "sample": sample})
    scaled = {**sample, "mu": {"dist": "uniform", "low": 10, "high": 30, "unit": "percent"}}
    study = Study.from_dict({"fixed": {"vy": -1.41, "angle": "20 deg"}, "sample": scaled})
    assert study.sample is not None
    assert study.sample.inputs["mu"].to_dict() == {"dist": "uniform", "low": 0.1, "high": 0.3}


def test_a_range_is_reported_as_written() -> None:
    grid = {"angle": {"start": "80 deg", "stop": "10 deg", "step": "10 deg"}}
    with pytest.raises(ValueError, match="does not lead") as caught:
        Study.from_dict({"fixed": {"vy": -1.41, "mu": 0.2}, "grid": grid})
    assert str(caught.value) == (
        "[grid] angle: step '10 deg' does not lead from start '80 deg' to stop '10 deg'"
    )


@pytest.mark.parametrize(
    ("where", "message"),
    [
        ("fixed", "input 'flat_yield_strength': flat_yield_strength = 276 Pa is below 10000 Pa"),
        ("grid", "grid dimension 'flat_yield_strength': flat_yield_strength = 276 Pa is below"),
    ],
)
def test_a_material_value_of_an_implausible_magnitude_is_refused(where: str, message: str) -> None:
    """``flat_yield_strength = 276`` is 276 Pa, a unit left out: refused when the study is
    built (a material by values and a calibration refuse it too); 276 MPa is read."""
    base = {"vy": -1.41, "mu": 0.2, "angle": 0.349, "flat_E": 69e9, "flat_nu": 0.33}
    values = {"fixed": {**base, "flat_yield_strength": 276.0}, "grid": {"law": ["brake"]}}
    if where == "grid":
        values = {"fixed": base, "grid": {"flat_yield_strength": [276.0, 300e6]}}
    with pytest.raises(ValueError, match="^" + re.escape(message)):
        Study(name="soft", **values)
    Study(name="steel", fixed={**base, "flat_yield_strength": 276e6}, grid={"law": ["brake"]})


@pytest.mark.parametrize(("gravity", "value"), [("9.81 m/s^2", 9.81), ("1 g0", 9.80665)])
def test_engine_gravity_may_be_a_quantity(gravity, value) -> None:
    """``[engine] gravity`` takes a quantity string as every other study value does: the
    same study (and hash) as its number in m/s^2."""
    text = _file("fixed", "mu", 0.2).to_dict()
    quantity = Study.from_dict({**text, "engine": {"gravity": gravity}})
    number = Study.from_dict({**text, "engine": {"gravity": value}})
    assert quantity.engine.gravity == value and quantity.hash() == number.hash()
    assert Study(grid={"mu": [0.1]}, fixed={"vy": -1.41, "angle": 0.35},
                 engine=EngineOptions(gravity=gravity)).engine.gravity == value  # fmt: skip
