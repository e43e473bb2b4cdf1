"""The closed forms at 90 deg (cos(pi/2) in floating point is no lever arm) and an out-of-range
angle given in degrees echoed in degrees."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab import analytic as an
from impactlab.analytic.closed_forms import ALPHA_ROUNDOFF


def test_at_90_deg_alpha_and_mu_c_are_zero():
    assert an.alpha(math.pi / 2, 0.0) == 0.0
    assert an.critical_friction(math.pi / 2) == 0.0
    assert an.alpha("90 deg", 0.0) == 0.0
    # just below 90 deg the lever arm is real
    assert an.alpha(math.pi / 2 - 1e-9, 0.0) < 0
    assert np.all(an.critical_friction(np.array([math.pi / 2 - 1e-6, 1.0])) > 0)


def test_at_90_deg_t_is_refused_not_5e12_s():
    with pytest.raises(ValueError, match=r"mu = 0 >= mu_c = 0 at angle = 90 deg \(the rod stands"):
        an.sliding_length(22e-6, -1.41, 4e-3, math.pi / 2, 0.0)
    with pytest.raises(ValueError, match=r"alpha_ must be < 0 beyond round-off .* got -1\.94e-16"):
        an.impact_duration(22e-6, 1400e-6, -1.41, -1.94e-16)
    with pytest.raises(ValueError, match="beyond round-off"):
        an.impact_duration(22e-6, 1400e-6, -1.41, -ALPHA_ROUNDOFF)
    assert an.impact_duration(22e-6, 1400e-6, -1.41, -1e-6) > 0


def test_an_angle_in_degrees_is_echoed_in_degrees():
    with pytest.raises(
        ValueError,
        match=r"^angle must be <= 90 deg, got 95 deg; in radians, as the closed forms take a "
        r"bare number: <= 1.5708 rad, got 1.658\d* rad$",
    ):
        an.alpha("95 deg", 0.1)
    with pytest.raises(ValueError, match=r"^angle must be >= 0 deg, got -5 deg; "):
        an.critical_friction("-5 deg")
    # a bare number is radians, and so is its echo
    with pytest.raises(ValueError, match=r"^angle must be <= 1.5708 rad, got 1.658 rad$"):
        an.alpha(1.658, 0.1)
