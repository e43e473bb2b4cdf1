"""The closed forms refuse what ``invert`` refuses, with the same words: a drop speed below
``MIN_SPEED`` (0 included), a duration at which the mean force over- or underflows, and an
exported ``lever_arms`` that checks its lengths and its angle as the other closed forms do."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from impactlab import bodies
from impactlab.analytic import (
    impact_duration,
    invert,
    lever_arms,
    mean_force_momentum,
    mean_force_rigid,
    sliding_length,
)
from impactlab.analytic._inputs import MIN_SPEED

ANGLE = math.radians(20)
ALPHA = -0.24274
BASE = {"angle": ANGLE, "v_i": -1.41, "e": 0.5, "mu": 0.2, "delta_p": 22e-6,
        "sliding_length": 1400e-6, "n_samples": 200}  # fmt: skip


def _closed_forms(vi: object, duration: float = 4e-3) -> dict[str, object]:
    return {
        "impact_duration": lambda: impact_duration(22e-6, 1400e-6, vi, ALPHA),
        "sliding_length": lambda: sliding_length(22e-6, vi, duration, ANGLE, 0.2),
        "mean_force_rigid": lambda: mean_force_rigid(duration, 0.5, vi, 7.43),
    }


def _refusal(call: object) -> str:
    with pytest.raises(ValueError, match=r"\S") as err:
        call()  # type: ignore[operator]
    return str(err.value)


@pytest.mark.parametrize("vi", [0.0, -0.0, 1e-300, -1e-7, np.array([1.41, 1e-9])])
def test_a_drop_speed_below_the_bound_is_refused_as_invert_refuses_it(vi: object) -> None:
    """mean_force_rigid(4e-3, 0.5, 0.0, 7.43) was 0.0; impact_duration at 1e-300 m/s was
    5.8e297 s."""
    scalar = float(np.min(np.abs(vi)))
    expected = _refusal(lambda: invert(**{**BASE, "v_i": scalar}))
    assert f"|v_i| >= {MIN_SPEED:g} m/s" in expected
    for name, call in _closed_forms(vi).items():
        assert _refusal(call) == expected, name


def test_a_drop_speed_at_the_bound_is_taken() -> None:
    for name, call in _closed_forms(MIN_SPEED, duration=30.0).items():
        assert math.isfinite(call()), name  # type: ignore[operator]
    assert mean_force_rigid(4e-3, 0.5, -1.41, 7.43) == pytest.approx(1.5 * 1.41 / (7.43 * 4e-3))


@pytest.mark.parametrize(
    "call",
    [
        lambda: mean_force_rigid(1e-320, 0.5, 1.41, 7.43),
        lambda: mean_force_momentum(1e-320, 0.4607, 0.62),
        lambda: mean_force_momentum(1e300, 1e-20, 1e-10),
    ],
)
def test_a_force_that_over_or_underflows_is_refused(call: object) -> None:
    """They returned inf with numpy's "overflow encountered in divide" (and 0 below)."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no numpy RuntimeWarning either
        text = _refusal(call)
    assert text.startswith("duration = ") and "gives the mean force F = " in text
    assert "N (it over- or underflows); allowed: a duration > 0 s at which F is finite" in text


def test_a_duration_that_overflows_is_refused() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        text = _refusal(lambda: impact_duration(22e-6, 1e308, 1.41, -1e-11))
    assert text.startswith("delta_p = 2.2e-05 m, sliding_length = 1e+308 m, v_i = 1.41 m/s")
    assert "gives the duration T = inf s (it over- or underflows); allowed: " in text


def test_lever_arms_checks_its_inputs_and_takes_an_angles_unit() -> None:
    """It was the unchecked bodies function: "20 deg" raised numpy's TypeError, a bare 20
    (degrees meant) returned numbers, negative lengths and NaN passed."""
    a, b = lever_arms(0.1524, 0.0088, "20 deg")
    assert (a, b) == pytest.approx(bodies.lever_arms(0.1524, 0.0088, ANGLE), rel=1e-15)
    assert isinstance(a, float) and isinstance(b, float)
    assert lever_arms("152.4 mm", "8.8 mm", ANGLE) == pytest.approx((a, b), rel=1e-15)
    assert lever_arms(0.1524, 0.0088, math.pi / 2) == (0.0, 0.1524 + 0.0088)
    arms = lever_arms(0.1524, 0.0088, np.radians([20.0, 45.0]))
    assert arms[0].shape == (2,)
    for args, needle in [
        ((0.1524, 0.0088, 20.0), "angle must be <= 1.5708 rad, got 20.0 rad"),
        ((0.1524, 0.0088, "95 deg"), "angle must be <= 90 deg, got 95 deg"),
        ((-0.1524, 0.0088, ANGLE), "half_length must be >= 0 m, got -0.1524 m"),
        ((0.1524, 0.0, ANGLE), "tip_radius must be > 0 m, got 0.0 m"),
        ((0.1524, 0.0088, math.nan), "angle must be finite"),
        ((0.1524, "8.8", ANGLE), "tip_radius"),
    ]:
        with pytest.raises(ValueError, match=r"^" + needle.split(",")[0]) as err:
            lever_arms(*args)
        assert needle in str(err.value) or needle == "tip_radius"
    assert lever_arms(0.0, 3e-3, ANGLE) == (0.0, 3e-3)  # a sphere: no half length
