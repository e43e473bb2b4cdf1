"""The Dormand-Prince 5(4) pair shared by every engine: the tableau, Shampine's dense output
and the generic stage point and error sum of a state array of any length.

Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3;
dense output: Shampine, Math. Comp. 46 (1986) 135, doi:10.1090/S0025-5718-1986-0815836-3.
The rigid engine's step (``core.integrator.dp_step``) writes the stages out for its fixed
state length with the scalar coefficients ``A*``, ``B*``, ``E*``; the partial-slip and
flexible engines, whose state length depends on the cells or modes, loop over ``DP_A`` and
``DP_E`` with ``stage_point`` and ``error_sum``.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.dynamics.kernels._jit import njit_llvm_inline

# --- Dormand-Prince 5(4) tableau (Dormand & Prince 1980) and Shampine's dense output -------------
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = (
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
)
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (
    -71.0 / 57600.0,
    71.0 / 16695.0,
    -71.0 / 1920.0,
    17253.0 / 339200.0,
    -22.0 / 525.0,
    1.0 / 40.0,
)
#: Dormand-Prince stage coefficients: row s holds a_{s,j} (row 6 = the 5th-order weights b_j,
#: so stage 6 is evaluated at the new point: FSAL).
DP_A = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [A21, 0.0, 0.0, 0.0, 0.0, 0.0],
        [A31, A32, 0.0, 0.0, 0.0, 0.0],
        [A41, A42, A43, 0.0, 0.0, 0.0],
        [A51, A52, A53, A54, 0.0, 0.0],
        [A61, A62, A63, A64, A65, 0.0],
        [B1, 0.0, B3, B4, B5, B6],
    ]
)
#: Error weights: the 4th- minus the 5th-order weights (the error norm squares them).
DP_E = np.array([E1, 0.0, E3, E4, E5, E6, E7])
#: Shampine's dense-output polynomial coefficients (theta^1 ... theta^4 per stage).
DENSE_P = np.array(
    [
        [
            1.0,
            -8048581381.0 / 2820520608.0,
            8663915743.0 / 2820520608.0,
            -12715105075.0 / 11282082432.0,
        ],
        [0.0, 0.0, 0.0, 0.0],
        [
            0.0,
            131558114200.0 / 32700410799.0,
            -68118460800.0 / 10900136933.0,
            87487479700.0 / 32700410799.0,
        ],
        [
            0.0,
            -1754552775.0 / 470086768.0,
            14199869525.0 / 1410260304.0,
            -10690763975.0 / 1880347072.0,
        ],
        [
            0.0,
            127303824393.0 / 49829197408.0,
            -318862633887.0 / 49829197408.0,
            701980252875.0 / 199316789632.0,
        ],
        [0.0, -282668133.0 / 205662961.0, 2019193451.0 / 616988883.0, -1453857185.0 / 822651844.0],
        [0.0, 40617522.0 / 29380423.0, -110615467.0 / 29380423.0, 69997945.0 / 29380423.0],
    ]
)

#: Scratch lengths, per state component, of a step loop (``step_views``) and of a
#: recomputation (``recompute_views``): an impact's scratch is one allocation (core.driver).
STEP_LEN = 14
RECOMPUTE_LEN = 9


@njit(cache=True, inline="always", error_model="numpy")
def stage_point(y, K, h, stage, out, n):
    """The point ``y + h sum_j a_{stage,j} K[j]`` where stage ``stage`` is evaluated, for the
    first ``n`` components (the rest of ``out`` is left as it is)."""
    for i in range(n):
        acc = 0.0
        for j in range(stage):
            acc += DP_A[stage, j] * K[j, i]
        out[i] = y[i] + h * acc


@njit(cache=True, inline="always", error_model="numpy")
def error_sum(y, ynew, K, h, rtol, sc, n):
    """Sum over the first ``n`` components of the squared scaled local error of the step
    (the difference of the 4th- and 5th-order solutions, ``h sum_j e_j K[j]``); error scale
    of component i: ``rtol (sc[i] + max(|y_i|, |ynew_i|))``. The RMS norm is
    sqrt(sum / count)."""
    err = 0.0
    for i in range(n):
        ei = 0.0
        for j in range(7):
            ei += DP_E[j] * K[j, i]
        q = h * ei / (rtol * (sc[i] + max(abs(y[i]), abs(ynew[i]))))
        err += q * q
    return err


@njit(cache=True, inline="always", error_model="numpy")
def dense_entry(y0, h, i, theta, t2, t3, t4, Q, out):
    """Entry ``i`` of the dense output at t0 + theta h (t2, t3, t4: the powers of theta)."""
    out[i] = y0[i] + h * (Q[i, 0] * theta + Q[i, 1] * t2 + Q[i, 2] * t3 + Q[i, 3] * t4)


@njit(cache=True, inline="always", error_model="numpy")
def dense_rows(y0, h, theta, Q, out, n):
    """Dense output at t0 + theta h of the first ``n`` components (Q = K^T P, computed by
    ``dense_coeffs``)."""
    t2 = theta * theta
    t3 = t2 * theta
    t4 = t3 * theta
    for i in range(n):
        dense_entry(y0, h, i, theta, t2, t3, t4, Q, out)


@njit(cache=True, inline="always", error_model="numpy")
def dense(y0, h, theta, Q, out):
    """Dense output at t0 + theta h (Q = K^T P, computed by ``dense_coeffs``; any state
    length: that of ``out``)."""
    dense_rows(y0, h, theta, Q, out, out.shape[0])


@njit_llvm_inline
def dense_llvm(y0, h, theta, Q, out):
    """``dense`` compiled once and inlined by LLVM (``kernels._jit.njit_llvm_inline``), for the
    rigid engine's event location and history, where numba would otherwise translate and type
    it again at each of its seven call sites."""
    dense(y0, h, theta, Q, out)


@njit(cache=True, inline="always", error_model="numpy")
def dense_coeffs_rows(K, Q, n):
    """The dense-output coefficients Q = K^T DENSE_P of the last step for the first ``n``
    components (each entry sums its 7 terms in stage order)."""
    for i in range(n):
        for j in range(4):
            s = 0.0
            for st in range(7):
                s += K[st, i] * DENSE_P[st, j]
            Q[i, j] = s


@njit(cache=True, inline="always", error_model="numpy")
def dense_coeffs(K, Q):
    """The dense-output coefficients Q = K^T DENSE_P of the last step (any state length: the
    rows of ``Q``)."""
    dense_coeffs_rows(K, Q, Q.shape[0])


@njit(cache=True, inline="always", error_model="numpy")
def step_views(buf, n):
    """The work arrays of a step loop over a state of length ``n``, views of ``buf`` (at least
    STEP_LEN n long): (new state, trial state, event state, stages K (7 x n), dense-output
    coefficients Q (n x 4))."""
    K = buf[3 * n : 10 * n].reshape((7, n))
    return buf[:n], buf[n : 2 * n], buf[2 * n : 3 * n], K, buf[10 * n : 14 * n].reshape((n, 4))


@njit(cache=True, inline="always", error_model="numpy")
def recompute_views(buf, y, k0):
    """The work arrays of a recomputation from ``y`` with derivative ``k0`` (any length n),
    views of ``buf`` (at least RECOMPUTE_LEN n long): (stages K (7 x n), current state = y,
    current derivative = k0)."""
    n = y.shape[0]
    cur = buf[7 * n : 8 * n]
    kc = buf[8 * n : 9 * n]
    for i in range(n):
        cur[i] = y[i]
        kc[i] = k0[i]
    return buf[: 7 * n].reshape((7, n)), cur, kc
