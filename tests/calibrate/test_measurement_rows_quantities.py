"""A drop's value may be a pint Quantity of any registry, as everywhere in the Python API: read
as the string of its value and unit (formerly refused: ``vy must be a number or a quantity
string``)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pint
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.calibrate import Measurements

UREG: Any = pint.UnitRegistry()


def test_quantities_of_another_registry_read_as_their_strings() -> None:
    rec = {"label": "q", "angle": UREG("30 deg"), "vy": UREG("-200 cm/s"), "mu": 20 * UREG.percent,
           "e": UREG.Quantity(0.4, ""), "e_sigma": 0.01, "delta_p": UREG("60 um"),
           "delta_p_sigma": UREG("5 um")}  # fmt: skip
    text = {"label": "q", "angle": "30 deg", "vy": "-200 cm/s", "mu": "20 %", "e": 0.4,
            "e_sigma": 0.01, "delta_p": "60 um", "delta_p_sigma": "5 um"}  # fmt: skip
    got, want = Measurements.from_records([rec]), Measurements.from_records([text])
    for k in ("angle", "vy", "mu"):
        np.testing.assert_allclose(got.inputs[k], want.inputs[k], rtol=1e-15)
    for k in ("e", "delta_p"):
        np.testing.assert_allclose(got.observed[k], want.observed[k], rtol=1e-15)
        np.testing.assert_allclose(got.sigma[k], want.sigma[k], rtol=1e-15)
    assert got.inputs["vy"][0] == pytest.approx(-2.0)


def test_a_numpy_magnitude_is_read() -> None:
    m = Measurements.conditions([{"angle": "30 deg", "vy": UREG.Quantity(np.float32(-2), "m/s")}])
    assert m.inputs["vy"][0] == -2.0


ARRAY = r"drop 1: vy must be one number with its unit, got the Quantity"


@pytest.mark.parametrize(
    ("value", "match"),
    [
        (UREG.Quantity(np.array([-2.0, -1.0]), "m/s"), ARRAY),
        (UREG("2 kg"), r"drop 1: vy: '2.0 kg' has the wrong dimension"),
    ],
)
def test_a_quantity_that_is_no_value_of_the_input_is_refused(value: object, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        Measurements.conditions([{"angle": "30 deg", "vy": value}])


def test_a_dimensionless_angle_is_refused_as_a_bare_number_is() -> None:
    with pytest.raises(ValueError, match=r"angle: the bare number '0.5' has no unit"):
        Measurements.conditions([{"angle": UREG.Quantity(0.5, ""), "vy": -2.0}])


@settings(deadline=None, max_examples=40)
@given(st.floats(-50.0, -1e-3), st.sampled_from(["m/s", "cm/s", "mm/s", "km/h", "ft/s"]))
def test_a_quantity_reads_as_its_si_value(x: float, unit: str) -> None:
    m = Measurements.conditions([{"angle": "30 deg", "vy": UREG.Quantity(x, unit)}])
    assert m.inputs["vy"][0] == pytest.approx(UREG.Quantity(x, unit).to("m/s").magnitude, rel=1e-12)
