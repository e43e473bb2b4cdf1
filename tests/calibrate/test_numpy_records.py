"""``Measurements.from_records`` takes numpy real scalars as the numbers they hold (a row read
from a numpy array or a DataFrame), NaN of any float type as "not measured", and refuses a
numpy bool as it does a Python one."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.calibrate import Measurements

BASE = {"label": "a", "angle": "20 deg", "vy": -1.41}


@pytest.mark.parametrize("kind", [np.float16, np.float32, np.float64])
def test_numpy_floats_are_numbers(kind):
    m = Measurements.from_records([dict(BASE, e=kind(0.4), e_sigma=kind(0.02))])
    assert m.observed["e"][0] == pytest.approx(0.4, rel=1e-3)
    assert m.sigma["e"][0] == pytest.approx(0.02, rel=1e-3)


@pytest.mark.parametrize("kind", [np.int8, np.int64])
def test_numpy_integers_are_numbers(kind):
    m = Measurements.from_records([dict(BASE, vy=kind(-2), e=0.4, e_sigma=0.02,
                                        mass=np.uint16(3))])  # fmt: skip
    assert m.inputs["vy"][0] == -2.0 and m.inputs["mass"][0] == 3.0


def test_a_numpy_nan_pair_is_not_measured():
    nan = np.float32("nan")
    m = Measurements.from_records(
        [dict(BASE, e=nan, e_sigma=nan, delta_p=6e-5, delta_p_sigma=3e-6)]
    )
    assert list(m.quantities) == ["delta_p"]
    with pytest.raises(ValueError, match="e is NaN"):
        Measurements.from_records([dict(BASE, e=nan, e_sigma=np.float32(0.02))])
    with pytest.raises(ValueError, match="e_sigma is NaN"):
        Measurements.from_records([dict(BASE, e=np.float64(0.4), e_sigma=np.float16(math.nan))])


def test_a_numpy_bool_is_refused_as_a_value():
    with pytest.raises(ValueError, match="e must be a number or a quantity string"):
        Measurements.from_records([dict(BASE, e=np.True_, e_sigma=0.02)])
