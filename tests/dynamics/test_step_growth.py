"""The controller's step-size factor without ``pow`` (``kernels.step_control.growth``)."""

from __future__ import annotations

import math

from hypothesis import given
from hypothesis import strategies as st

from impactlab.dynamics.kernels.step_control import growth


@given(st.floats(min_value=1e-19, max_value=1e19, allow_nan=False, allow_infinity=False))
def test_growth_is_the_fifth_order_factor_within_2e_4(err: float) -> None:
    exact = 0.9 * err**-0.2
    assert abs(growth(err) / exact - 1.0) < 2e-4


def test_growth_beyond_the_table_is_clipped_by_the_callers_bounds() -> None:
    assert growth(1e-30) >= 10.0  # an error this small: grow by the largest factor
    assert growth(1e30) <= 0.2  # this large: shrink by the largest factor
    assert math.isclose(growth(1.0), 0.9, rel_tol=2e-4)
