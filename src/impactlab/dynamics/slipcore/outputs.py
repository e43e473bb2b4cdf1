"""Bookkeeping of a partial-slip impact: running extremes over the accepted steps, the history
rows (at the steps' ends, and inside a step from the dense output) and the outputs at
separation (the same ``OUTPUT_FIELDS`` and ``HISTORY_FIELDS`` as the
core; ``stick`` is 1 while at least one cell sticks, i.e. without gross slip)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import grown
from impactlab.dynamics.kernels.cells import any_stuck, n_in
from impactlab.dynamics.kernels.layout import (
    A_DMAX,
    A_EMIN,
    A_ERISE,
    A_FEX,
    A_FMAX,
    A_OWN,
    A_STICK,
    A_TMAX,
    A_VSNEG,
    A_VSPOS,
    A_WCOMP,
    A_WREST,
    C_C0,
    C_D,
    C_G,
    C_I,
    C_M,
    C_MU,
    C_R,
    C_S0,
    FR_COULOMB,
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
    M_DR,
    M_PHASE,
    O_ANG,
    O_CT,
    O_DP,
    O_E,
    O_ED,
    O_EE,
    O_ERISE,
    O_FEX,
    O_FLAGS,
    O_FMEAN,
    O_PN,
    O_PT,
    O_REG,
    O_SL,
    O_SPIN,
    O_STICK,
    O_VNOUT,
    O_VTOUT,
    O_VX,
    O_VY,
    S_PHI,
    S_SPIN,
    S_VX,
    S_VY,
    S_WORK,
    S_X,
    S_Y,
)
from impactlab.dynamics.kernels.quality import result_flags
from impactlab.dynamics.kernels.rhs import energy, geometry_llvm
from impactlab.dynamics.kernels.status import REGIME_REVERSAL, REGIME_SLIP, REGIME_STICK
from impactlab.dynamics.slipcore.layout import Y_CELL
from impactlab.dynamics.slipcore.model import evaluate, stored_energy
from impactlab.dynamics.slipcore.sums import dense_rows_t

# --- accumulators over the accepted steps: kernels.layout.A_*, then ---------------------------
A_JUMP = A_OWN  # largest change of F_t across a switch [N]
NA = A_OWN + 1


@njit_internal
def total_energy(law, p, c, md, y, cm, cp, W, ev):
    """Kinetic + gravity potential + normal elastic + tangential elastic (cells) energy [J]."""
    delta, _a, _b, Fn, Ft, _vn, _vs, ar, _ad, _nin = ev
    e = energy(law, p, np.int64(FR_COULOMB), c, md, y, Fn, Ft, delta, 0.0)
    return e + stored_energy(cm, cp, W, ar)


@njit(cache=True, error_model="numpy")
def track(acc, law, p, c, md, y, cm, cp, W, ev, t0, t1, diag):
    """Update ``acc`` over the accepted step [t0, t1] ending at ``y`` (quantities ``ev`` and
    ``W`` evaluated there); False where the forces are not finite."""
    if any_stuck(cm):
        acc[A_STICK] += t1 - t0
    delta, _a, _b, Fn, Ft, _vn, vs, _ar, _ad, _nin = ev
    if not (math.isfinite(Fn) and math.isfinite(Ft)):
        return False
    if Fn > acc[A_FMAX]:
        acc[A_FMAX] = Fn
    if delta > acc[A_DMAX]:
        acc[A_DMAX] = delta
        acc[A_TMAX] = t1
    acc[A_VSPOS] = max(acc[A_VSPOS], vs)
    acc[A_VSNEG] = min(acc[A_VSNEG], vs)
    if diag:
        en = total_energy(law, p, c, md, y, cm, cp, W, ev)
        acc[A_ERISE] = max(acc[A_ERISE], en - acc[A_EMIN])
        acc[A_EMIN] = min(acc[A_EMIN], en)
        acc[A_FEX] = max(acc[A_FEX], abs(Ft) - c[C_MU] * Fn)
    return True


@njit_internal
def history_row(hist, n, t, law, p, c, md, y, cm, sg, cp, W):
    """Append one history row at time ``t`` and state ``y``; returns (hist, n + 1)."""
    if n >= hist.shape[0]:
        hist = grown(hist, n, np.int64(16))
    ev = evaluate(law, p, c, md, y, cm, sg, cp, W)
    delta, _a, _b, Fn, Ft, vn, vs, _ar, _ad, _nin = ev
    _d, _a2, _b2, xs, _sl = geometry_llvm(c, y)
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
    row[H_STICK] = 1.0 if any_stuck(cm) else 0.0
    row[H_ENERGY] = total_energy(law, p, c, md, y, cm, cp, W, ev)
    return hist, n + 1


@njit_internal
def dense_rows(hist, nh, t, h, theta, law, p, c, md, y, cm, sg, cp, W, Q, yt):
    """History rows at a quarter, half and three quarters of the step from ``y`` (size ``h``,
    dense-output coefficients ``Q``) that lie before ``theta``; returns (hist, rows)."""
    nact = Y_CELL + n_in(cm)
    for j in range(1, 4):
        if j / 4.0 < theta:
            dense_rows_t(y, h, j / 4.0, Q, yt, nact)
            hist, nh = history_row(hist, nh, t + j * h / 4.0, law, p, c, md, yt, cm, sg, cp, W)
    return hist, nh


@njit(cache=True, error_model="numpy")
def regime(acc, t, vn0):
    """Friction regime code of the finished impact (``status.REGIME_*``)."""
    vtol = 1e-6 * abs(vn0)
    if acc[A_VSPOS] > vtol and acc[A_VSNEG] < -vtol:
        return REGIME_REVERSAL
    if acc[A_STICK] > 1e-9 * t:
        return REGIME_STICK
    return REGIME_SLIP


@njit_internal
def separation(out, c, md, y, acc, t, vx0, vy0, vn0, th0, rod, e0, rtol, diag):
    """Write the results at separation (state ``y`` at time ``t``) into ``out``."""
    _delta, a, b, xs, slide = geometry_llvm(c, y)
    m = c[C_M]
    g = c[C_G]
    vx = y[S_VX]
    vy = y[S_VY]
    w = y[S_SPIN]
    vn = vy - w * a
    w_comp = acc[A_WCOMP]
    out[O_E] = -vn / vn0
    out[O_EE] = math.sqrt(max(0.0, -acc[A_WREST] / w_comp)) if w_comp < 0.0 else math.nan
    out[O_VX] = vx
    out[O_VY] = vy
    out[O_SPIN] = w
    out[O_DP] = md[M_DR]
    out[O_SL] = slide
    out[O_CT] = xs
    pn = m * (vy - vy0) + m * g * t
    out[O_PN] = pn
    out[O_FMEAN] = pn / t
    out[O_PT] = m * (vx - vx0)
    e_kin = 0.5 * m * (vx * vx + vy * vy) + 0.5 * c[C_I] * w * w
    e_pot = m * g * y[S_Y]
    out[O_ED] = e0 - (e_kin + e_pot)
    out[O_FLAGS] = result_flags(e0, e_kin, e_pot, y[S_WORK], rtol, m * g * t, pn)
    out[O_STICK] = acc[A_STICK]
    out[O_REG] = regime(acc, t, vn0)
    out[O_VNOUT] = vn
    out[O_VTOUT] = vx + w * b
    out[O_ANG] = th0 + y[S_PHI] if rod else math.nan
    if diag:
        fmax = acc[A_FMAX]
        out[O_ERISE] = acc[A_ERISE] / e0
        out[O_FEX] = acc[A_FEX] / fmax if fmax > 0.0 else 0.0
