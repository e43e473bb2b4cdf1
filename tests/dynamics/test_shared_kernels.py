"""The shared compiled kernels (``impactlab.dynamics.kernels``) against closed forms: the
Dormand-Prince tableau and dense output, the event search's Illinois update, the step-size
factor, and the partial-slip cells."""

from __future__ import annotations

import math
from fractions import Fraction

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.dynamics.kernels import cells
from impactlab.dynamics.kernels.dormand_prince import (
    DENSE_P,
    DP_A,
    DP_E,
    dense,
    dense_coeffs,
    error_sum,
    stage_point,
)
from impactlab.dynamics.kernels.roots import THETA_TOL, illinois, past_root
from impactlab.dynamics.kernels.step_control import growth, power_growth

#: Dormand & Prince (1980): c_i, the 5th-order weights b_i and the 4th-order weights.
C = (0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0)
B4 = (5179 / 57600, 0.0, 7571 / 16695, 393 / 640, -92097 / 339200, 187 / 2100, 1 / 40)


def test_tableau_rows_sum_to_the_nodes_and_the_error_weights_are_b4_minus_b5() -> None:
    for s in range(7):
        assert math.isclose(DP_A[s].sum(), C[s], abs_tol=1e-15)
    assert math.isclose(DP_A[6].sum(), 1.0, rel_tol=1e-15)
    for j in range(7):
        b5 = DP_A[6, j] if j < 6 else 0.0
        assert math.isclose(DP_E[j], B4[j] - b5, abs_tol=1e-16)


def test_dense_output_at_theta_1_is_the_5th_order_step() -> None:
    """Shampine's polynomial ends at the step's 5th-order result: sum_k P[s, k] = b_s."""
    for s in range(7):
        b5 = DP_A[6, s] if s < 6 else 0.0
        assert math.isclose(DENSE_P[s].sum(), b5, abs_tol=1e-15)


def _dp_step(lam: float, y0: np.ndarray, h: float) -> tuple[np.ndarray, np.ndarray]:
    """One step of y' = lam y with the shared stage point (stages K, 5th-order result)."""
    n = y0.shape[0]
    K = np.zeros((7, n))
    K[0] = lam * y0
    yt = np.empty(n)
    for stage in range(1, 7):
        stage_point(y0, K, h, stage, yt, n)
        K[stage] = lam * yt
    return K, yt


@pytest.mark.parametrize("h", [0.1, 0.05])
def test_a_step_of_exponential_growth_is_5th_order(h: float) -> None:
    y0 = np.array([1.0, -2.0])
    K, y1 = _dp_step(1.0, y0, h)
    exact = y0 * math.exp(h)
    # local error of a 5th-order step: h^6/720 times the 6th derivative (the leading term)
    assert np.all(np.abs(y1 - exact) <= 2.0 * h**6 / 720.0 * np.abs(y0))
    # the error estimate (5th minus 4th order) is of order h^5 and not zero
    sc = np.zeros(2)
    est = math.sqrt(error_sum(y0, y1, K, h, 1.0, sc, 2) / 2)
    assert 0.0 < est < h**5


def test_dense_output_interpolates_to_4th_order_and_ends_at_the_step() -> None:
    h = 0.1
    y0 = np.array([1.0, 3.0])
    K, y1 = _dp_step(1.0, y0, h)
    Q = np.empty((2, 4))
    dense_coeffs(K, Q)
    out = np.empty(2)
    dense(y0, h, 1.0, Q, out)
    assert np.allclose(out, y1, rtol=1e-15, atol=0.0)
    for theta in (0.25, 0.5, 0.75):
        dense(y0, h, theta, Q, out)
        assert np.all(np.abs(out - y0 * math.exp(theta * h)) <= h**5 * np.abs(y0))


def test_illinois_halves_the_stale_end_when_one_side_moves_twice() -> None:
    a, fa, b, fb, side = illinois(0.0, -1.0, 1.0, 1.0, 0, 0.5, -0.2)
    assert (a, fa, b, fb, side) == (0.5, -0.2, 1.0, 1.0, -1)
    a, fa, b, fb, side = illinois(a, fa, b, fb, side, 0.6, -0.1)
    assert (a, fa, b, fb, side) == (0.6, -0.1, 1.0, 0.5, -1)
    assert illinois(a, fa, b, fb, side, 0.7, 0.3) == (0.6, -0.1, 0.7, 0.3, 1)


@settings(max_examples=60)
@given(st.floats(min_value=0.01, max_value=0.99), st.floats(min_value=0.5, max_value=3.0))
def test_illinois_with_the_round_off_probe_brackets_a_cubic_root(root: float, k: float) -> None:
    def g(x: float) -> float:
        return k * (x - root) + (x - root) ** 3

    a, fa, b, fb = 0.0, g(0.0), 1.0, g(1.0)
    side = 0
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        f = g(th)
        if f <= 0.0 and abs(f) <= 1e-13 * max(-g(0.0), g(1.0)):
            probe = past_root(th, f, b, fb)
            assert probe >= th + THETA_TOL
            if probe < b and g(probe) > 0.0:
                b = probe
                break
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
        if b - a <= THETA_TOL:
            break
    assert g(b) > 0.0
    assert abs(b - root) < 1e-12


@given(st.floats(min_value=1e-12, max_value=1e12, allow_nan=False))
def test_power_growth_is_the_factor_growth_approximates(err: float) -> None:
    assert math.isclose(power_growth(err), 0.9 * err**-0.2, rel_tol=1e-15)
    assert abs(growth(err) / power_growth(err) - 1.0) < 2e-4


@settings(max_examples=80)
@given(
    st.floats(min_value=1e-6, max_value=1e-3),  # contact radius [m]
    st.integers(min_value=1, max_value=40),  # cells over a_est
    st.floats(min_value=0.3, max_value=1.5),  # a / a_est
    st.floats(min_value=0.01, max_value=1.0),  # mu
    st.floats(min_value=1.0, max_value=1e5),  # F_n [N]
)
def test_cell_limits_sum_to_the_coulomb_limit(
    a_est: float, n: int, frac: float, mu: float, fn: float
) -> None:
    """sum_i L_i = mu F_n for any contact radius (the Hertzian line load, cut into cells)."""
    dx = a_est / n
    ar = frac * a_est
    total = sum(cells.limits.py_func(i, dx, mu, fn, 0.0, ar, 0.0)[0] for i in range(4 * n + 2))
    assert math.isclose(total, mu * fn, rel_tol=1e-11)


def test_cell_limit_of_a_lone_cell_is_the_whole_limit_and_its_rate_is_consistent() -> None:
    mu, fn, fd, ar, ad = 0.3, 10.0, 4.0, 1e-4, 2e-3
    L, Ld = cells.limits.py_func(0, 2e-4, mu, fn, fd, ar, ad)  # one cell covers the contact
    assert math.isclose(L, mu * fn, rel_tol=1e-14)
    assert math.isclose(Ld, mu * fd, rel_tol=1e-12)  # d(mu F_n g)/dt with g = 1
    # a cell outside the contact carries nothing
    assert cells.limits.py_func(3, 2e-4, mu, fn, fd, ar, ad) == (0.0, 0.0)


def test_boundary_time_and_cell_count() -> None:
    cm = np.array([cells.STICK, cells.SLIP, cells.OUT, cells.OUT], dtype=np.int64)
    assert cells.n_in.py_func(cm) == 2
    dx = 1e-4
    # growing radius: the next boundary is 2 dx
    assert math.isclose(cells.boundary_time.py_func(cm, dx, 1.5e-4, 1.0), 0.5e-4)
    # receding radius: the outermost cell's inner boundary is dx
    assert math.isclose(cells.boundary_time.py_func(cm, dx, 1.5e-4, -1.0), 0.5e-4)
    assert cells.boundary_time.py_func(cm, dx, 1.5e-4, 0.0) == math.inf
    assert cells.any_stuck.py_func(cm)
    assert not cells.any_stuck.py_func(np.array([cells.SLIP, cells.OUT], dtype=np.int64))


def test_settle_pass_is_a_no_op_when_nothing_is_due_and_releases_a_receded_cell() -> None:
    cp = np.array([4.0e10, 1e-4, 1e-9, 1e-13])
    y = np.zeros(6)
    o = 2
    cm = np.array([cells.STICK, cells.STICK, cells.OUT, cells.OUT], dtype=np.int64)
    sg = np.zeros(4)
    L = np.array([1.0, 1.0, 0.0, 0.0])
    Ld = np.zeros(4)
    f = np.array([0.1, 0.1, 0.0, 0.0])
    y[o : o + 2] = f[:2]
    args = (0.3, 2e11, 10.0, -0.1, 0.0)  # mu, E*, F_n, v_n, v_slip
    # radius inside the second cell, not growing: nothing due
    assert not cells.apply_due(y, o, cm, sg, cp, L, Ld, f, *args, 1.5e-4, 0.0)
    # the radius receded below the second cell's inner boundary: released at zero force
    assert cells.apply_due(y, o, cm, sg, cp, L, Ld, f, *args, 0.9e-4, -1.0)
    assert cm[1] == cells.OUT and y[o + 1] == 0.0
    # a stuck cell past its limit slips in the direction of its force, clamped to the limit
    f[0] = -2.0
    y[o] = -2.0
    assert cells.apply_due(y, o, cm, sg, cp, L, Ld, f, *args, 0.9e-4, 0.0)
    assert cm[0] == cells.SLIP and sg[0] == -1.0 and y[o] == -1.0


def test_fractions_check_of_the_dense_weights() -> None:
    """The first dense-output row in exact arithmetic sums to b_1 = 35/384."""
    row = (
        Fraction(1),
        Fraction(-8048581381, 2820520608),
        Fraction(8663915743, 2820520608),
        Fraction(-12715105075, 11282082432),
    )
    assert sum(row) == Fraction(35, 384)
