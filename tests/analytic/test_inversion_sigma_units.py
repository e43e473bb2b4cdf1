"""A bare sigma beside a value given with its unit is in that unit, as on the command line."""

from __future__ import annotations

import math

import pint
import pytest

from impactlab import analytic as an

BASE = dict(v_i=-2.18, mu=0.13, e=0.49, delta_p=26e-6, sliding_length=1650e-6, n_samples=100)


def test_a_bare_sigma_takes_the_unit_of_its_value():
    r = an.invert(**{**BASE, "angle": ("45 deg", 0.2), "delta_p": ("22 um", 2)})
    assert r.inputs["angle"] == pytest.approx((math.radians(45), math.radians(0.2)))
    assert r.inputs["delta_p"] == pytest.approx((22e-6, 2e-6))


def test_a_quantity_of_any_registry_lends_its_unit_to_a_bare_sigma():
    other = pint.UnitRegistry()
    r = an.invert(**{**BASE, "angle": "45 deg", "sliding_length": (1.65 * other.mm, 0.05)})
    assert r.inputs["sliding_length"] == pytest.approx((1.65e-3, 0.05e-3))


def test_bare_values_keep_si_sigmas_and_a_sigma_keeps_its_own_unit():
    r = an.invert(
        **{
            **BASE,
            "angle": (math.radians(45), 0.002),
            "v_i": ("-2.18 m/s", "1 cm/s"),
            "sliding_length": ("1650 um", 50),
        }
    )
    assert r.inputs["angle"] == (math.radians(45), 0.002)
    assert r.inputs["v_i"] == pytest.approx((2.18, 0.01))
    assert r.inputs["sliding_length"] == pytest.approx((1650e-6, 50e-6))
    # mu and e are plain numbers: their sigmas too
    assert an.invert(**{**BASE, "angle": "45 deg", "mu": (0.13, 0.01)}).inputs["mu"] == (0.13, 0.01)


def test_a_negative_bare_sigma_is_refused_in_the_values_unit():
    with pytest.raises(ValueError, match=r"the sigma of delta_p must be >= 0 m, got -2e-06 m"):
        an.invert(**{**BASE, "angle": "45 deg", "delta_p": ("22 um", -2)})
