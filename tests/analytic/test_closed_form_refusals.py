"""The closed forms refuse input that makes their formula meaningless, naming the keyword, the
value and what is allowed: a centre-of-mass velocity change that is not upward (no normal
impulse) and a duration too short to reach the dent's bottom (a negative normal impulse)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.analytic import (
    G0,
    friction_from_velocities,
    impact_duration,
    mean_force_momentum,
    sliding_length,
)

ANGLE = math.radians(20)


@pytest.mark.parametrize("dv_cy", [-0.618, 0.0, np.array([0.5, -0.618])])
def test_friction_needs_an_upward_velocity_change(dv_cy) -> None:
    for duration in (None, 4e-3):  # with T, g T was once added to the negative change
        with pytest.raises(ValueError, match=r"^dv_cy must be > 0 \(the upward change") as err:
            friction_from_velocities(0.1, dv_cy, duration=duration)
        bad = float(np.min(dv_cy))
        assert str(err.value).endswith(f"got {bad!r} m/s") and "\n" not in str(err.value)


def test_friction_from_an_upward_change_is_unchanged() -> None:
    assert friction_from_velocities(0.1, 0.618) == pytest.approx(0.1 / 0.618, rel=1e-15)
    assert friction_from_velocities(-0.1, 0.618) == pytest.approx(0.1 / 0.618, rel=1e-15)
    with_g = friction_from_velocities(0.1, 0.618, duration=4e-3)
    assert with_g == pytest.approx(0.1 / (0.618 + G0 * 4e-3), rel=1e-15)


@pytest.mark.parametrize("gravity", [False, True])
def test_momentum_force_needs_an_upward_velocity_change(gravity: bool) -> None:
    with pytest.raises(ValueError, match=r"^dv_cy must be > 0 .*got -0.618 m/s$"):
        mean_force_momentum(4.106e-3, 0.4607, -0.618, gravity=gravity)
    with pytest.raises(ValueError, match=r"^dv_cy must be > 0 .*got 0.0 m/s$"):
        mean_force_momentum(4.106e-3, 0.4607, 0.0, gravity=gravity)
    F = mean_force_momentum(4.106e-3, 0.4607, 0.618, gravity=gravity)
    assert F == pytest.approx(0.4607 * 0.618 / 4.106e-3 + (0.4607 * G0 if gravity else 0.0))


def test_sliding_length_refuses_a_negative_impulse() -> None:
    least = 22e-6 / 1.41  # T at which the tip just reaches the dent's bottom: no impulse
    with pytest.raises(ValueError, match=r"^duration must be >= delta_p/\|v_i\| = 1.56e-05 s") as e:
        sliding_length(22e-6, -1.41, 1e-6, ANGLE, 0.2)
    assert str(e.value).endswith("got 1e-06 s")
    assert sliding_length(22e-6, -1.41, least, ANGLE, 0.2) == pytest.approx(0.0, abs=1e-18)
    assert sliding_length(22e-6, -1.41, 4.106e-3, ANGLE, 0.2) == pytest.approx(-1400e-6, rel=1e-3)
    with pytest.raises(ValueError, match=r"got 2e-06 s$"):  # an array: the first short element
        sliding_length(22e-6, -1.41, np.array([4e-3, 2e-6, 1e-6]), ANGLE, 0.2)


@pytest.mark.parametrize("alpha_", [0.1, [-0.3, 0.1], np.array([[-0.3], [0.1]])])
def test_a_sticking_alpha_is_shown_as_a_plain_number(alpha_) -> None:
    with pytest.raises(ValueError, match=r"^alpha_ must be < 0 \(gross sliding\), got 0\.1: "):
        impact_duration(22e-6, 1.4e-3, -1.41, alpha_)
