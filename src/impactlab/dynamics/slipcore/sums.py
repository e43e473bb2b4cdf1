"""The Dormand-Prince sums of the partial-slip step over the entries in use: the stage points,
the local error terms and Shampine's dense output.

The tableau and the dense-output polynomial are the shared kernels' (``kernels.dormand_prince``:
Dormand & Prince 1980, doi:10.1016/0771-050X(80)90013-3; Shampine 1986,
doi:10.1090/S0025-5718-1986-0815836-3), and each entry is summed exactly as the shared loops
sum it (from 0.0, term by term in stage order, zero coefficients included): the same bits. The
shared ``stage_point`` loops over the stages inside the loop over the entries, a chain of up
to seven dependent additions per entry with a coefficient read per term; here the loop over
the entries is the inner one (each term added to all entries in turn; LLVM vectorises it from
32 entries, below which it keeps the scalar loop), and the dense-output coefficients are
stored one row per power of theta (``Q``: 4 x n, each row contiguous over the entries).
"""

from __future__ import annotations

from impactlab.dynamics.kernels._jit import njit_llvm_inline
from impactlab.dynamics.kernels.dormand_prince import DENSE_P, DP_A, DP_E


@njit_llvm_inline
def stage_sum(y, K, h, stage, out, n):
    """``kernels.dormand_prince.stage_point`` for the first ``n`` entries (the same bits):
    ``out = y + h sum_j a_{stage,j} K[j]`` (stage 6: the new point, FSAL), the sum kept in
    ``out`` term by term."""
    for i in range(n):
        out[i] = 0.0
    for j in range(stage):
        a = DP_A[stage, j]
        for i in range(n):
            out[i] += a * K[j, i]
    for i in range(n):
        out[i] = y[i] + h * out[i]


@njit_llvm_inline
def error_terms(y, ynew, K, h, rtol, sc, q, n):
    """The scaled local error of each of the first ``n`` entries into ``q``: h e_i over
    rtol (sc[i] + max(|y_i|, |ynew_i|)), e_i = sum_j (b*_j - b_j) K[j, i] (the terms of
    ``kernels.dormand_prince.error_sum``, the same bits)."""
    for i in range(n):
        q[i] = 0.0
    for j in range(7):
        e = DP_E[j]
        for i in range(n):
            q[i] += e * K[j, i]
    for i in range(n):
        q[i] = h * q[i] / (rtol * (sc[i] + max(abs(y[i]), abs(ynew[i]))))


@njit_llvm_inline
def dense_coeffs_t(K, Q, n):
    """Shampine's dense-output coefficients of the first ``n`` entries, one row per power of
    theta: Q[j, i] = sum_st K[st, i] P[st, j] (P: ``DENSE_P``; the sums of
    ``kernels.dormand_prince.dense_coeffs_rows``, the same bits, transposed)."""
    for j in range(4):
        for i in range(n):
            Q[j, i] = 0.0
        for st in range(7):
            pj = DENSE_P[st, j]
            for i in range(n):
                Q[j, i] += K[st, i] * pj


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
