"""The Dormand-Prince sums of the partial-slip step, written so that LLVM vectorises them over
the state entries: the stage points, the local error terms and Shampine's dense output.

The tableau and the dense-output polynomial are the shared kernels' (``kernels.dormand_prince``:
Dormand & Prince 1980, doi:10.1016/0771-050X(80)90013-3; Shampine 1986,
doi:10.1090/S0025-5718-1986-0815836-3), and each entry is summed exactly as the shared loops
sum it (from 0.0, term by term in stage order, zero coefficients included): the same bits. The
shared ``stage_point`` loops over the stages inside the loop over the entries, a chain of up
to seven dependent additions per entry with a coefficient read per term; here every stage has
its own loop over the entries with its coefficients fixed, which LLVM vectorises (the entries
are independent), and the dense-output coefficients are stored one row per power of theta
(``Q``: 4 x n, each row contiguous over the entries).
"""

from __future__ import annotations

from impactlab.dynamics.kernels._jit import njit_llvm_inline
from impactlab.dynamics.kernels.dormand_prince import (
    A21,
    A31,
    A32,
    A41,
    A42,
    A43,
    A51,
    A52,
    A53,
    A54,
    A61,
    A62,
    A63,
    A64,
    A65,
    B1,
    B3,
    B4,
    B5,
    B6,
    DENSE_P,
    DP_E,
)

# the 5th-order weights as DP_A's last row holds them (b_2 = 0 is summed too: the same bits)
_B2 = 0.0
_E1, _E2, _E3, _E4, _E5, _E6, _E7 = DP_E


@njit_llvm_inline
def stage_sum(y, K, h, stage, out, n):
    """``kernels.dormand_prince.stage_point`` for the first ``n`` entries (the same bits):
    ``out = y + h sum_j a_{stage,j} K[j]``, stage 6 being the new point (FSAL)."""
    if stage == 1:
        for i in range(n):
            out[i] = y[i] + h * (0.0 + A21 * K[0, i])
    elif stage == 2:
        for i in range(n):
            out[i] = y[i] + h * ((0.0 + A31 * K[0, i]) + A32 * K[1, i])
    elif stage == 3:
        for i in range(n):
            out[i] = y[i] + h * (((0.0 + A41 * K[0, i]) + A42 * K[1, i]) + A43 * K[2, i])
    elif stage == 4:
        for i in range(n):
            s = ((0.0 + A51 * K[0, i]) + A52 * K[1, i]) + A53 * K[2, i]
            out[i] = y[i] + h * (s + A54 * K[3, i])
    elif stage == 5:
        for i in range(n):
            s = ((0.0 + A61 * K[0, i]) + A62 * K[1, i]) + A63 * K[2, i]
            out[i] = y[i] + h * ((s + A64 * K[3, i]) + A65 * K[4, i])
    else:
        for i in range(n):
            s = ((0.0 + B1 * K[0, i]) + _B2 * K[1, i]) + B3 * K[2, i]
            out[i] = y[i] + h * (((s + B4 * K[3, i]) + B5 * K[4, i]) + B6 * K[5, i])


@njit_llvm_inline
def error_terms(y, ynew, K, h, rtol, sc, q, n):
    """The scaled local error of each of the first ``n`` entries into ``q``: h e_i over
    rtol (sc[i] + max(|y_i|, |ynew_i|)), e_i = sum_j (b*_j - b_j) K[j, i] (the terms of
    ``kernels.dormand_prince.error_sum``, the same bits)."""
    for i in range(n):
        e = ((0.0 + _E1 * K[0, i]) + _E2 * K[1, i]) + _E3 * K[2, i]
        e = (((e + _E4 * K[3, i]) + _E5 * K[4, i]) + _E6 * K[5, i]) + _E7 * K[6, i]
        q[i] = h * e / (rtol * (sc[i] + max(abs(y[i]), abs(ynew[i]))))


@njit_llvm_inline
def dense_coeffs_t(K, Q, n):
    """Shampine's dense-output coefficients of the first ``n`` entries, one row per power of
    theta: Q[j, i] = sum_st K[st, i] P[st, j] (P: ``DENSE_P``; the sums of
    ``kernels.dormand_prince.dense_coeffs_rows``, the same bits, transposed)."""
    for j in range(4):
        p0, p1, p2, p3 = DENSE_P[0, j], DENSE_P[1, j], DENSE_P[2, j], DENSE_P[3, j]
        p4, p5, p6 = DENSE_P[4, j], DENSE_P[5, j], DENSE_P[6, j]
        for i in range(n):
            s = ((0.0 + K[0, i] * p0) + K[1, i] * p1) + K[2, i] * p2
            s = (((s + K[3, i] * p3) + K[4, i] * p4) + K[5, i] * p5) + K[6, i] * p6
            Q[j, i] = s


@njit_llvm_inline
def dense_entry_t(y0, h, i, theta, t2, t3, t4, Q, out):
    """Entry ``i`` of the dense output at t0 + theta h from ``dense_coeffs_t``'s ``Q`` (t2, t3,
    t4: the powers of theta; ``kernels.dormand_prince.dense_entry``'s sum, the same bits)."""
    out[i] = y0[i] + h * (Q[0, i] * theta + Q[1, i] * t2 + Q[2, i] * t3 + Q[3, i] * t4)


@njit_llvm_inline
def dense_rows_t(y0, h, theta, Q, out, n):
    """The dense output at t0 + theta h of the first ``n`` entries (``dense_coeffs_t``'s Q)."""
    t2 = theta * theta
    t3 = t2 * theta
    t4 = t3 * theta
    for i in range(n):
        out[i] = y0[i] + h * (Q[0, i] * theta + Q[1, i] * t2 + Q[2, i] * t3 + Q[3, i] * t4)
