"""Recording of the contact history: one row (``HISTORY_FIELDS``) per accepted step, dense-output
point and event, in a buffer that grows by doubling."""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import grown
from impactlab.dynamics.kernels.dormand_prince import dense_llvm
from impactlab.dynamics.kernels.friction import sticking
from impactlab.dynamics.kernels.layout import (
    C_C0,
    C_D,
    C_R,
    C_S0,
    H_DELTA,
    H_ENERGY,
    H_FN,
    H_FT,
    H_PHASE,
    H_PHI,
    H_SPIN,
    H_STICK,
    H_T,
    H_VN,
    H_VSLIP,
    H_VX,
    H_VY,
    H_X,
    H_XC,
    H_Y,
    HISTORY_SUBSTEPS,
    M_PHASE,
    S_PHI,
    S_SPIN,
    S_VX,
    S_VY,
    S_X,
    S_Y,
)
from impactlab.dynamics.kernels.normal import geometry
from impactlab.dynamics.kernels.rhs import energy, evaluate_cold
from impactlab.dynamics.kernels.tuples import state_tuple


@njit(cache=True, error_model="numpy")
def record(hist, n, t, law, p, fric, c, md, y):
    """Append one history row at time ``t`` [s] and state ``y`` (growing the buffer); returns
    (hist, n + 1)."""
    if n >= hist.shape[0]:
        hist = grown(hist, n, np.int64(16))
    delta, _a, _b, Fn, Ft, vn, vs, kt = evaluate_cold(law, p, fric, c, md, y)
    _d, _a, _b, xs, _sl = geometry(c, y)
    row = hist[n]
    row[H_T] = t
    row[H_DELTA] = delta
    row[H_FN] = Fn
    row[H_FT] = Ft
    row[H_XC] = xs
    row[H_VSLIP] = vs
    row[H_X] = c[C_D] * c[C_C0] + y[S_X]
    row[H_Y] = c[C_D] * c[C_S0] + c[C_R] + y[S_Y]
    row[H_PHI] = y[S_PHI]
    row[H_VX] = y[S_VX]
    row[H_VY] = y[S_VY]
    row[H_SPIN] = y[S_SPIN]
    row[H_VN] = vn
    row[H_PHASE] = md[M_PHASE]
    row[H_STICK] = 1.0 if sticking(fric, md) else 0.0
    row[H_ENERGY] = energy(law, p, fric, c, md, y, Fn, Ft, delta, kt)
    return hist, n + 1


@njit_internal
def record_substeps(hist, n, t, h, theta, law, p, fric, c, md, y, K, Q, yt):
    """Rows at the dense-output points t + j h / HISTORY_SUBSTEPS inside the step from ``y``
    that lie before ``theta`` (the event, or 1); ``Q``: dense-output coefficients, ``yt``: work
    array. Returns (hist, n)."""
    for j in range(1, HISTORY_SUBSTEPS):
        thj = j / HISTORY_SUBSTEPS
        if thj >= theta:
            break
        dense_llvm(y, h, thj, Q, yt)
        hist, n = record(hist, n, t + thj * h, law, p, fric, c, md, state_tuple(yt))
    return hist, n
