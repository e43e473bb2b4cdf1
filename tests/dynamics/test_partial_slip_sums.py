"""The partial-slip step's sums (``slipcore.sums``: the entries as the inner loop) against the
shared Dormand-Prince kernels bit for bit: the stage points, the error terms (their squares
summed in entry order) and the dense output (its coefficients stored transposed)."""

from __future__ import annotations

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from numba import njit

from impactlab.dynamics.kernels.dormand_prince import (
    dense_coeffs_rows,
    dense_rows,
    error_sum,
    stage_point,
)
from impactlab.dynamics.slipcore.sums import dense_coeffs_t, dense_rows_t, error_terms, stage_sum

LENGTH = 72  # the rigid-body state and room for 64 cells


@njit(cache=True, error_model="numpy")
def _shared_and_slip(y, K, ynew, sc, h, rtol, theta, n):
    """(stage points, error sum, dense output at theta) of the shared kernels and of
    ``slipcore.sums`` over the first ``n`` entries."""
    m = y.shape[0]
    pts0, pts1 = np.zeros((7, m)), np.zeros((7, m))
    for stage in range(1, 7):
        stage_point(y, K, h, stage, pts0[stage], n)
        stage_sum(y, K, h, stage, pts1[stage], n)
    err0 = error_sum(y, ynew, K, h, rtol, sc, n)
    q = np.zeros(m)
    error_terms(y, ynew, K, h, rtol, sc, q, n)
    err1 = 0.0
    for i in range(n):
        err1 += q[i] * q[i]
    Q0, Q1 = np.zeros((m, 4)), np.zeros((4, m))
    dense_coeffs_rows(K, Q0, n)
    dense_coeffs_t(K, Q1, n)
    d0, d1 = np.zeros(m), np.zeros(m)
    dense_rows(y, h, theta, Q0, d0, n)
    dense_rows_t(y, h, theta, Q1, d1, n)
    return pts0, pts1, err0, err1, Q0, Q1, d0, d1


def _state(seed: int) -> tuple[np.ndarray, ...]:
    """A state, its stages and error scales with magnitudes over many decades and exact zeros
    (a cell's entry out of contact)."""
    rng = np.random.default_rng(seed)
    scale = 10.0 ** rng.uniform(-12, 6, LENGTH)
    y = rng.standard_normal(LENGTH) * scale
    K = rng.standard_normal((7, LENGTH)) * scale * 10.0 ** rng.uniform(0, 6)
    K[:, rng.random(LENGTH) < 0.1] = 0.0
    ynew = y + 1e-3 * rng.standard_normal(LENGTH) * scale
    sc = 10.0 ** rng.uniform(-12, 0, LENGTH)
    return y, K, ynew, sc


@settings(deadline=None, max_examples=60)
@given(
    seed=st.integers(0, 2**32 - 1),
    n=st.integers(1, LENGTH),
    h=st.floats(1e-12, 1e-3),
    theta=st.floats(0.0, 1.0),
)
def test_sums_equal_the_shared_kernels_bit_for_bit(seed, n, h, theta) -> None:
    y, K, ynew, sc = _state(seed)
    pts0, pts1, err0, err1, Q0, Q1, d0, d1 = _shared_and_slip(y, K, ynew, sc, h, 3e-8, theta, n)
    assert pts1.tobytes() == pts0.tobytes()
    assert np.float64(err1).tobytes() == np.float64(err0).tobytes()
    assert Q1.T.copy().tobytes() == Q0.tobytes()
    assert d1.tobytes() == d0.tobytes()
    # the entries beyond n are left as they were (zero here)
    assert not pts1[:, n:].any() and not d1[n:].any()
