"""The partial-slip impact driver: one impact from first touch to separation.

``impact_slip`` initialises (the core's input checks, constants and error scales; the cell
vector), runs the step loop (``_integrate``: Dormand-Prince steps, event location, history, the
switches of the normal contact and of the cells) and writes the results at separation.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.bodies.layout import BP_KIND, KIND_ROD
from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.cells import (
    CP_DX,
    CP_FTOL,
    CP_G1,
    CP_VTOL,
    STEP_PAST,
    birth,
    n_in,
)
from impactlab.dynamics.kernels.layout import (
    A_DMAX,
    A_EMIN,
    A_FMAX,
    A_TMAX,
    C_A0,
    C_B0,
    C_GS,
    C_I,
    C_M,
    C_R,
    FR_COULOMB,
    FR_MINDLIN,
    MAX_EVENTS,
    MAX_STEPS,
    NH,
    NS,
    O_DMAX,
    O_FMAX,
    O_NST,
    O_T,
    O_TMAX,
    O_VNIN,
    O_VTIN,
    S_SPIN,
    S_VX,
    S_VY,
)
from impactlab.dynamics.kernels.setup import check_inputs, constants, error_scales
from impactlab.dynamics.kernels.status import (
    ST_BAD_INPUT,
    ST_NAN,
    ST_NO_SEPARATION,
    ST_NOT_APPROACHING,
    ST_OK,
    ST_STEP_UNDERFLOW,
    ST_TOO_MANY_EVENTS,
)
from impactlab.dynamics.kernels.step_control import power_growth
from impactlab.dynamics.slipcore.address_call import (
    SA_FIRST_EVENT,
    SA_INTEGRATE_TO,
    SA_RECORD,
    SA_ROWS,
    SA_STEP,
    SA_SWITCH,
    call_first_event,
    call_integrate_to,
    call_record,
    call_rows,
    call_step,
    call_switch,
)
from impactlab.dynamics.slipcore.layout import CP_FSC, EXTRA, G_CELL, NCP, Y_CELL
from impactlab.dynamics.slipcore.model import (
    BOUNDARY_PAST,
    boundary_horizon,
    evaluate,
    events,
)
from impactlab.dynamics.slipcore.outputs import A_JUMP, NA, separation, track
from impactlab.dynamics.slipcore.restart import GO_ON
from impactlab.dynamics.slipcore.stepper import slip_rhs
from impactlab.dynamics.slipcore.switches import release_passed


@njit(cache=True, inline="always", error_model="numpy")
def copy_active(dst, src, n):
    """The first ``n`` entries of ``src`` into ``dst`` (the rigid-body state and the cells in
    contact; the entries of the cells out of contact are never read, and a cell is born with
    its entry set)."""
    for i in range(n):
        dst[i] = src[i]


@njit(cache=True, inline="always", error_model="numpy")
def _integrate(at, law, p, c, md, y, cm, sg, cp, sc, tstar, rtol, rec, diag, hist, acc):
    """The step loop from first touch to separation, a failure or MAX_STEPS.
    Returns (status, t, steps, mode, history, rows)."""
    n = y.shape[0]
    ng = G_CELL + cm.shape[0]
    ynew, yt, yev = np.zeros(n), np.zeros(n), np.zeros(n)
    K, Q, W = np.zeros((7, n)), np.zeros((4, n)), np.zeros((4, cm.shape[0]))
    R = np.empty((10, n))  # scratch of the recomputation at an event
    q = np.empty(n)  # the scaled local errors of a step
    gold, gnew, gmid = np.empty(ng), np.empty(ng), np.empty(ng)
    Wm = np.zeros((4, cm.shape[0]))
    # hc: the controller's step; h: the step taken (hc cut at a cell boundary or at t*)
    t, hc, hmin = 0.0, 0.02 * tstar * rtol**0.2, 1e-14 * tstar
    nin0 = n_in(cm)
    ev = slip_rhs(law, p, c, md, y, cm, sg, cp, W, K[0], nin0, nin0 >= 0)  # limits: a value
    events(c, md, cm, sg, cp, W, ev, gold)
    nh = np.int64(0)  # not a literal: history_row() is compiled once, for any row count
    if rec:
        hist, nh = call_record(at[SA_RECORD], hist, nh, t, law, p, c, md, y, cm, sg, cp, W)
    nsteps, nevents, status = 0, 0, ST_NO_SEPARATION
    ar0, ad0 = ev[7], ev[8]  # contact radius [m] and its rate [m/s] at t
    t_last, ad_last = -1.0, 0.0  # the last accepted step's start and the radius rate there
    rejected = False  # the last step tried was rejected
    while nsteps < MAX_STEPS:
        nsteps += 1
        # end the step just past the next cell boundary: its kink then lies at the step's end
        add = (ad0 - ad_last) / (t - t_last) if 0.0 <= t_last < t else 0.0
        hz = boundary_horizon(cm, cp, ar0, ad0, add)
        past = BOUNDARY_PAST if ad0 > 0.0 else STEP_PAST  # a birth ahead, or a release
        h = min(hc, tstar, past * hz + hmin) if hz > 0.0 else min(hc, tstar)
        err, ev = call_step(at[SA_STEP], law, p, c, md, y, cm, sg, cp, W, K, h, rtol, sc, ynew, q)
        nact = Y_CELL + n_in(cm)  # the entries in use: the rigid-body state, the cells in contact
        if not (err <= 1.0):
            rejected = True
            hc = h * (max(0.2, power_growth(err)) if math.isfinite(err) else 0.25)
            if hc < hmin:
                status = ST_NAN if not math.isfinite(err) else ST_STEP_UNDERFLOW
                break
            continue
        k, theta = call_first_event(
            at[SA_FIRST_EVENT],
            gold,
            gnew,
            gmid,
            law,
            p,
            c,
            md,
            y,
            K,
            Q,
            h,
            cm,
            sg,
            cp,
            W,
            ev,
            Wm,
            yt,
        )
        if rec:
            hist, nh = call_rows(
                at[SA_ROWS], hist, nh, t, h, theta, law, p, c, md, y, cm, sg, cp, W, Q, yt
            )
        if k >= 0:  # the state at the event, integrated anew (the dense output is 4th order)
            # ev and W: the quantities at yev, from the last stage of the last step (FSAL)
            n_re, ev = call_integrate_to(
                at[SA_INTEGRATE_TO],
                at[SA_STEP],
                law,
                p,
                c,
                md,
                y,
                cm,
                sg,
                cp,
                W,
                K[0],
                theta * h,
                rtol,
                sc,
                yev,
                R,
            )
            nsteps += n_re
            tend = t + theta * h
        else:
            copy_active(yev, ynew, nact)
            tend = t + h
            if rec:  # else W and ev still hold the step's last stage, at ynew
                ev = evaluate(law, p, c, md, yev, cm, sg, cp, W)
        if not track(acc, law, p, c, md, yev, cm, cp, W, ev, t, tend, diag):
            status = ST_NAN
            break
        t_last, ad_last = t, ad0
        ar0, ad0 = ev[7], ev[8]
        t = tend
        copy_active(y, yev, nact)
        # no growth right after a rejection (Hairer, Norsett & Wanner I, Sec. II.4,
        # doi:10.1007/978-3-540-78862-1): the rejected step's size is known to be too long
        grow = 1.0 if rejected else 10.0
        hc = h * (grow if err == 0.0 else min(grow, power_growth(err)))
        rejected = False
        if rec and k < 0:
            hist, nh = call_record(at[SA_RECORD], hist, nh, t, law, p, c, md, y, cm, sg, cp, W)
        if k < 0:
            copy_active(K[0], K[6], nact)
            if release_passed(y, cm, cp, ev[7], K[0]):
                ev = evaluate(law, p, c, md, y, cm, sg, cp, W)
                events(c, md, cm, sg, cp, W, ev, gold)
            else:
                gold, gnew = gnew, gold
            continue
        nevents += 1
        if nevents > MAX_EVENTS:
            status = ST_TOO_MANY_EVENTS
            break
        st, c, md = call_switch(at[SA_SWITCH], k, law, p, c, md, y, cm, sg, cp, W, ev, acc, K, gold)
        if rec:  # the row at an event holds the state after the switch (F_t is continuous)
            hist, nh = call_record(at[SA_RECORD], hist, nh, t, law, p, c, md, y, cm, sg, cp, W)
        if st != GO_ON:
            status = st
            break
    return status, t, nsteps, md, hist, nh


@njit_internal
def _setup(p, c, vn0, n_cells, a_est):
    """(cell parameters, error scales of the state, t*) of an impact with ``n_cells`` cells over
    the estimated largest contact radius ``a_est`` [m]."""
    m = EXTRA * n_cells
    sc = np.empty(NS + m)
    # np.int64(...): a value, not a constant, so that numba reuses the rigid core's compile of
    # the shared kernel (a constant argument, Literal[int], is a signature of its own)
    tstar, _dstar, fscale = error_scales(np.int64(FR_COULOMB), p, c, vn0, sc[:NS])
    sc[NS:] = fscale / n_cells
    cp = np.empty(NCP)
    cp[CP_G1] = 4.0 * c[C_GS]
    cp[CP_DX] = a_est / n_cells
    cp[CP_VTOL] = 1e-9 * abs(vn0)
    cp[CP_FTOL] = 1e-13 * fscale
    cp[CP_FSC] = fscale / n_cells
    return cp, sc, tstar


@njit(cache=True, error_model="numpy")
def impact_slip(
    law, p, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, record_, diag, n_cells, a_est, out, at
):
    """Simulate one impact with partial-slip friction (``mu`` > 0, ``n_cells`` >= 1 cells over
    ``a_est`` [m], the estimated largest contact radius; ``at``: the addresses of
    ``indirect.addresses``); the other arguments and the outputs are those of
    ``impactlab.dynamics.core.impact``. Returns (status, history, rows, the largest change of
    F_t across a switch over mu F_max)."""
    for i in range(out.shape[0]):
        out[i] = math.nan
    hist = np.empty((256 if record_ else 0, NH))
    status = check_inputs(law, p, np.int64(FR_MINDLIN), bp, th0, vx0, vy0, w0, mu, g, rtol)
    if status == ST_OK and not (mu > 0.0 and n_cells >= 1 and a_est > 0.0):
        status = ST_BAD_INPUT
    if status != ST_OK:
        return status, hist[:0], 0, 0.0
    c = constants(p, bp, th0, mu, g, const_angle)
    vn0 = vy0 - w0 * c[C_A0]
    out[O_VNIN] = vn0
    out[O_VTIN] = vx0 + w0 * c[C_B0]
    if not (vn0 < 0.0):
        return ST_NOT_APPROACHING, hist[:0], 0, 0.0
    md = (0.0, 0.0, 0.0, c[C_R], 0.0, 1.0, 0.0, 1.0)  # loading, compressing, radius factor 1
    cp, sc, tstar = _setup(p, c, vn0, n_cells, a_est)
    y = np.zeros(sc.shape[0])
    y[S_VX], y[S_VY], y[S_SPIN] = vx0, vy0, w0
    cm = np.zeros(EXTRA * n_cells, dtype=np.int64)
    sg = np.zeros(EXTRA * n_cells)
    # the first cell is born at first touch (a = 0)
    birth(
        np.int64(0),
        y,
        np.int64(Y_CELL),
        cm,
        sg,
        cp,
        mu,
        p[P_ESTAR],
        0.0,
        vn0,
        out[O_VTIN],
        0.0,
        0.0,
    )
    e0 = 0.5 * c[C_M] * (vx0 * vx0 + vy0 * vy0) + 0.5 * c[C_I] * w0 * w0
    acc = np.zeros(NA)
    acc[A_EMIN] = e0
    status, t, nsteps, md, hist, nh = _integrate(
        at, law, p, c, md, y, cm, sg, cp, sc, tstar, rtol, record_, diag, hist, acc
    )
    out[O_NST] = nsteps
    out[O_DMAX] = acc[A_DMAX]
    out[O_FMAX] = acc[A_FMAX]
    out[O_TMAX] = acc[A_TMAX]
    out[O_T] = t
    jump = acc[A_JUMP] / (mu * acc[A_FMAX]) if acc[A_FMAX] > 0.0 else 0.0
    if status != ST_OK:
        return status, hist[:nh], nh, jump
    rod = bp[BP_KIND] == KIND_ROD
    separation(out, c, md, y, acc, t, vx0, vy0, vn0, th0, rod, e0, rtol, diag)
    return ST_OK, hist[:nh], nh, jump
