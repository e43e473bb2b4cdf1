"""Start of the flexible drop: the state and mode table at the first touch of the tip, the
error scales and the tolerances of the run (compiled)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_CELLS, call_cells
from impactlab.dynamics.flexcore.cellswitch import CELL_TOUCH
from impactlab.dynamics.flexcore.contacts import new_dent
from impactlab.dynamics.flexcore.friction import initial_mode
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.cells import CP_FTOL, CP_G1, CP_VTOL, N_CELLS


@njit(cache=True, inline="always", error_model="numpy")
def state_size(M, fric):
    """Length of the state with M modes and friction model ``fric`` (layout module docstring:
    partial slip adds the cells of both ends; last, the ends' own works)."""
    cells = F.NE * F.NCS if fric == F.FR_PARTIAL else 0
    return 6 + 2 * M + F.NQUAD + cells + F.N_END_WORKS


@njit(cache=True, inline="always", error_model="numpy")
def cell_scales(c, vn0, fscale, sc, o):
    """Partial slip: the cells' error scales (state from ``o``) and their parameters (as the
    slipcore's: G_1 = 4 G*, the slip-rate and force hystereses; the width is set in Python)."""
    for i in range(o, sc.shape[0]):
        sc[i] = fscale / N_CELLS
    for k in range(F.NE):
        b = F.FC_CP + k * F.NFCP
        c[b + CP_G1] = 4.0 * c[F.FC_GS]
        c[b + CP_VTOL] = 1e-9 * abs(vn0)
        c[b + CP_FTOL] = 1e-13 * fscale


@njit(cache=True, inline="always", error_model="numpy")
def scales(mdl, vx0, vy0, w0, sc, sv):
    """Error scales of the state components (as the rigid engine: Hertzian depth, time and
    velocity scales) and the tolerances of the run."""
    p, c, om, Ue, We, Pe = mdl[1], mdl[2], mdl[3], mdl[7], mdl[8], mdl[9]
    M = om.shape[0]
    iv = 3 + M
    iq = 6 + 2 * M
    m = c[F.FC_M]
    R = c[F.FC_R]
    d = c[F.FC_D]
    a0 = d * math.cos(c[F.FC_TH0])
    vn0 = vy0 - w0 * a0
    meff = 1.0 / (1.0 / m + a0 * a0 / c[F.FC_I])
    dstar = (15.0 * meff * vn0 * vn0 / (16.0 * p[P_ESTAR] * math.sqrt(R))) ** 0.4
    tstar = dstar / abs(vn0)
    vstar = abs(vn0)
    sc[0] = dstar
    sc[1] = dstar
    sc[2] = dstar / (d + R)
    sc[iv] = vstar
    sc[iv + 1] = vstar
    sc[iv + 2] = vstar / (d + R)
    for j in range(M):
        phimax = 1e-300
        for k in range(F.NE):
            phimax = max(phimax, abs(Ue[k, j]), abs(We[k, j]), R * abs(Pe[k, j]))
        sc[3 + j] = dstar / phimax
        sc[iv + 3 + j] = vstar / phimax
    e0 = 0.5 * m * (vx0 * vx0 + vy0 * vy0) + 0.5 * c[F.FC_I] * w0 * w0
    for i in range(F.NQUAD):
        sc[iq + i] = e0
    for i in range(sc.shape[0] - F.N_END_WORKS, sc.shape[0]):
        sc[i] = e0  # the ends' own works (outside the error norm)
    for k in range(F.NE):
        b = iq + 3 + 4 * k
        sc[b] = meff * vstar
        sc[b + 1] = meff * vstar
        sc[b + 2] = dstar
        sc[b + 3] = dstar
    fscale = meff * vstar / tstar
    for k in range(F.NE):
        sc[iq + F.Q_TAN + k] = fscale  # the Mindlin state starts as a force
    sv[F.SV_FSCALE] = fscale
    if c[F.FC_FRIC] == F.FR_PARTIAL:
        cell_scales(c, vn0, fscale, sc, iq + F.NQUAD)
    sv[F.SV_DSTAR] = dstar
    sv[F.SV_TOL_V] = 1e-9 * vstar
    sv[F.SV_TOL_D] = 1e-12 * dstar
    sv[F.SV_TOL_F] = 1e-9 * meff * vstar / tstar
    sv[F.SV_HMAX] = tstar if M == 0 else min(tstar, 2.0 / om[M - 1] * 4.0)
    sv[F.SV_HMIN] = 1e-14 * tstar
    sv[F.SV_TSTAR] = tstar
    sv[F.SV_E0] = e0
    sv[F.SV_VN0] = vn0
    sv[F.SV_CHECK_DT] = 2.0 * math.pi / om[0] * 0.1 if M > 0 else 10.0 * tstar
    sv[F.SV_EPS_CLEAR] = 1e-3 * dstar
    sv[F.SV_T_RING] = (2.0 * math.pi / om.min() if M > 0
                       else F.NEW_IMPACT_CHECKS * sv[F.SV_CHECK_DT])  # fmt: skip


@njit_internal
def first_touch(mdl, md, y, vx0, vy0, w0, sv, contacts, dents, cur_con):
    """The state and the mode table at the first touch of end 0 (on virgin flat), before its
    friction mode (``touch_modes``, after the first evaluation: this function calls none, so
    that the right-hand side is not compiled into it once more)."""
    c = mdl[2]
    M = mdl[3].shape[0]
    iv = 3 + M
    for k in range(F.NE):
        md[k, F.MD_RR] = c[F.FC_R]
        md[k, F.MD_DSW] = c[F.FC_DSW]
        md[k, F.MD_DENT] = -1.0
        md[k, F.MD_AF] = 1.0
    y[iv] = vx0
    y[iv + 1] = vy0
    y[iv + 2] = w0
    # the tip (end 0) as a run-time integer, not a literal: numba would compile a separate copy
    # of every function it is passed to
    tip = np.int64(0)
    new_dent(dents, tip, tip, 0.0, c[F.FC_R])
    sv[F.SV_ND] = 1
    md[0, F.MD_IN] = 1.0
    md[0, F.MD_PH] = 0.0
    md[0, F.MD_COMP] = 1.0
    md[0, F.MD_DENT] = 0.0
    for f in (F.CR_END, F.CR_T0, F.CR_X0, F.CR_DENT, F.CR_RELOAD, F.CR_DMAX, F.CR_FMAX, F.CR_STICK):
        contacts[0, f] = 0.0
    contacts[0, F.CR_TH0] = contacts[0, F.CR_TH1] = c[F.FC_TH0]  # phi = q = 0 at first touch
    contacts[0, F.CR_VALONG] = 0.0
    contacts[0, F.CR_VNIN] = abs(sv[F.SV_VN0])  # set by ``scales``
    cur_con[0] = 0
    sv[F.SV_NCON] = 1


@njit(cache=True, inline="always", error_model="numpy")
def touch_modes(mdl, md, y, der, ev, ek, Jn, Jt):
    """The friction mode (and the partial-slip cells, through ``cellswitch.cell_action``'s
    address) of end 0 at its first touch; ``ek``, ``Jn``, ``Jt``: evaluated at the state of
    ``first_touch``; ``der``, ``ev``: work arrays."""
    c = mdl[2]
    tip = np.int64(0)  # a run-time integer (``first_touch``)
    initial_mode(mdl[1], c, mdl[3].shape[0], md, tip, ek[0, F.EK_VT], ek[0, F.EK_VN], Jn, Jt)
    if c[F.FC_FRIC] == F.FR_PARTIAL:
        call_cells(mdl[AT_CELLS], np.int64(CELL_TOUCH), tip, mdl, md, y, der, ev, ek, Jn, Jt)


@njit(cache=True, inline="always", error_model="numpy")
def workspace(n, M, nev):
    """The run state ``sv`` (layout.SV_*, with the initial status and horizon), the mode table,
    the state, the error scales and the work arrays of a state of length n (M modes, nev
    events): (sv, md, y, sc, Jn, Jt, ek, ev, gold, gnew, K, Q, st, ynew, yt, yev, der, snap)."""
    m3 = 3 + M  # the generalised coordinates
    sv = np.zeros(F.NSV)
    sv[F.SV_STATUS] = F.ST_MAX_STEPS
    sv[F.SV_T_CHECK] = -1.0
    sv[F.SV_NEXT_END] = -1.0
    sv[F.SV_NEXT_TIME] = math.inf
    return (sv, np.zeros((F.NE, F.NMD)), np.zeros(n), np.empty(n), np.zeros((F.NE, m3)),
            np.zeros((F.NE, m3)), np.zeros((F.NE, F.NEK)), np.empty(nev), np.empty(nev),
            np.empty(nev), np.empty((7, n)), np.empty((n, 4)), np.empty(n), np.empty(n),
            np.empty(n), np.empty(n), np.empty(n), np.zeros((F.NE, 6)))  # fmt: skip
