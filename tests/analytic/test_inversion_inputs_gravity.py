"""The inversion's gravitational acceleration obeys the engine's bound (a million g): one number,
``impactlab._input_limits.MAX_GRAVITY``, for ``simulate`` and ``invert``."""

from __future__ import annotations

import pytest

from impactlab import analytic
from impactlab._input_limits import MAX_GRAVITY
from impactlab.dynamics.kernels.inputs import IN_GRAVITY, INPUT_RULES


def test_a_huge_g_is_refused_by_the_closed_forms_and_the_inversion() -> None:
    with pytest.raises(ValueError, match=r"g must lie in \[0, 1e\+07\] m/s\^2 \(a million g\)"):
        analytic.mean_force_momentum(1e-4, 0.46, 1.0, gravity=True, g=1e30)
    with pytest.raises(ValueError, match=r"g must lie in \[0, 1e\+07\]"):
        analytic.invert(
            e=0.4216, mu=0.2, angle="20 deg", v_i=-1.41, delta_p=22e-6, sliding_length=1400e-6,
            gravity=True, g=1e30, n_samples=200,
        )  # fmt: skip
    assert analytic.mean_force_momentum(1e-4, 0.46, 1.0, gravity=True, g=MAX_GRAVITY) > 0


def test_the_engine_states_the_same_bound() -> None:
    assert (
        INPUT_RULES[IN_GRAVITY][1]
        == f"gravity must lie in [0, {MAX_GRAVITY:g}] m/s^2 (a million g)"
    )
