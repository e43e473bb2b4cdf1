"""The impact driver: one impact from first touch to separation.

``impact`` initialises (``setup``), runs the step loop (``_integrate``: Dormand-Prince steps,
event location, history, mode transitions) and writes the results at separation
(``_separation``). Running extremes and the normal work of compression and restitution are kept
in the accumulator array ``acc`` (``A_*``).

``_integrate`` (the step loop, about 75 lines) is the longest function of the core: it carries
the state between steps (step size, event tuple, mode, history buffer) and its early exits. It
and the opening (``ends.opening``), each called from one place, are inlined into ``impact`` by
numba: a function compiled on its own would have the whole engine below it linked into its
library and its machine code generated again (``docs/engine/first-run.md``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.bodies.layout import BP_KIND, KIND_ROD
from impactlab.dynamics.core.accumulate import NA, track
from impactlab.dynamics.core.approach import W_WORK_LEN
from impactlab.dynamics.core.ends import approach_end, near_separation, opening
from impactlab.dynamics.core.events import GO_ON, handle_event
from impactlab.dynamics.core.history import record as record_row
from impactlab.dynamics.core.history import record_substeps
from impactlab.dynamics.core.integrator import dp_step, first_event, integrate_to
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.dormand_prince import RECOMPUTE_LEN, STEP_LEN, step_views
from impactlab.dynamics.kernels.layout import (
    A_DMAX,
    A_EMIN,
    A_ERISE,
    A_FEX,
    A_FMAX,
    A_STICK,
    A_TMAX,
    A_VSNEG,
    A_VSPOS,
    A_WCOMP,
    A_WREST,
    C_A0,
    C_B0,
    C_G,
    C_I,
    C_M,
    EV_SEP,
    EV_VN,
    FR_IMPULSE,
    FR_NONE,
    M_DM,
    M_DR,
    M_PHASE,
    M_SIR,
    MAX_EVENTS,
    MAX_STEPS,
    MU_NEGLIGIBLE,
    NH,
    NS,
    O_ANG,
    O_CT,
    O_DMAX,
    O_DP,
    O_E,
    O_ED,
    O_EE,
    O_ERISE,
    O_FEX,
    O_FLAGS,
    O_FMAX,
    O_FMEAN,
    O_NST,
    O_PN,
    O_PT,
    O_REG,
    O_SL,
    O_SPIN,
    O_STICK,
    O_T,
    O_TMAX,
    O_VNIN,
    O_VNOUT,
    O_VTIN,
    O_VTOUT,
    O_VX,
    O_VY,
    S_PHI,
    S_SPIN,
    S_VX,
    S_VY,
    S_WORK,
    S_Y,
)
from impactlab.dynamics.kernels.normal import geometry
from impactlab.dynamics.kernels.quality import SLIP_VTOL, result_flags, slid_along_friction
from impactlab.dynamics.kernels.rhs import evaluate_cold, rhs_events_cold
from impactlab.dynamics.kernels.setup import check_inputs, constants, error_scales, initial_mode
from impactlab.dynamics.kernels.status import (
    REGIME_FRICTIONLESS,
    REGIME_REVERSAL,
    REGIME_SLIP,
    REGIME_STICK,
    ST_NAN,
    ST_NO_SEPARATION,
    ST_NOT_APPROACHING,
    ST_OK,
    ST_STEP_UNDERFLOW,
    ST_TOO_MANY_EVENTS,
)
from impactlab.dynamics.kernels.step_control import growth_llvm
from impactlab.dynamics.kernels.tuples import state_tuple
from impactlab.flags import FLAG_ENERGY_GAIN

#: Scratch of the step loop (``_integrate``): its arrays, a recomputation, a w-integration.
INTEGRATE_WORK_LEN = (STEP_LEN + RECOMPUTE_LEN) * NS + W_WORK_LEN
#: Scratch of an impact: state, accumulators, error scales and the step loop's.
IMPACT_WORK_LEN = 2 * NS + NA + INTEGRATE_WORK_LEN


@njit(cache=True, inline="always", error_model="numpy")
def _shrink(err, h, hmin):
    """(smaller step, GO_ON or the failure status) after a rejected step with error ``err``."""
    if not math.isfinite(err):
        # a non-finite force inside the step (law failure or outside its domain)
        h *= 0.25
        return h, (ST_NAN if h < hmin else GO_ON)
    h *= max(0.2, growth_llvm(err))
    return h, (ST_STEP_UNDERFLOW if h < hmin else GO_ON)


@njit(cache=True, inline="always", error_model="numpy")
def _unloading_factor(md):
    """Step-size factor at the turning point onto the unloading branch of mode ``md``.

    The unloading curve F = F_m ((delta - delta_r) / (delta_m - delta_r))^1.5 is stiffer than
    the loading curve it leaves: k_u = 1.5 F_m / (delta_m - delta_r), against at most
    1.5 F_m / delta_m on a loading curve whose local exponent d ln F / d ln delta is at most
    1.5. A step of an explicit method scales with sqrt(m / k) (its error with (h omega)^6),
    so the step carried over from the loading is shortened by sqrt(1 - delta_r / delta_m): no
    force evaluation, and the first unloading step is no longer rejected (it was after ~90 %
    of the elastic-plastic turning points). 1 without a dent (an elastic turning point)."""
    dm = md[M_DM]
    if md[M_PHASE] == 0.0 or not (dm > 0.0):
        return 1.0
    return math.sqrt(max(1.0 - md[M_DR] / dm, 0.04))


@njit(cache=True, inline="always", error_model="numpy")
def _integrate(
    law, p, fric, c, md, y, sc, tstar, dstar, fscale, rtol, record, diag, hist, acc, work
):
    """The step loop from first touch (state ``y``, mode ``md``) to separation, a failure or
    MAX_STEPS; ``work``: scratch (INTEGRATE_WORK_LEN). Returns (status, t, steps, mode,
    history, rows)."""
    hmax = tstar
    hmin = 1e-14 * tstar
    ynew, yt, yev, K, Q = step_views(work, NS)
    rwork = work[STEP_LEN * NS : (STEP_LEN + RECOMPUTE_LEN) * NS]
    wwork = work[(STEP_LEN + RECOMPUTE_LEN) * NS :]
    t = 0.0
    h = 0.02 * tstar * rtol**0.2
    r, gold, evq = rhs_events_cold(law, p, fric, c, md, state_tuple(y))
    for i in range(NS):
        K[0, i] = r[i]
    nh = np.int64(0)  # not a literal: record() is compiled once, for any row count
    if record:
        hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
    status, t, nsteps, nevents, c, md, gold, hist, nh = opening(
        law, p, fric, c, md, y, K, gold, rtol, sc, tstar, dstar, fscale, acc, diag, record,
        hist, nh, wwork,
    )  # fmt: skip
    if status != GO_ON:
        return status, t, nsteps, md, hist, nh
    h = max(h, t)
    may_approach = True
    status = ST_NO_SEPARATION
    while nsteps < MAX_STEPS:
        nsteps += 1
        if h > hmax:
            h = hmax
        err, gnew, evq = dp_step(law, p, fric, c, md, y, K, h, rtol, sc, ynew)
        if not (err <= 1.0):  # rejected
            h, st = _shrink(err, h, hmin)
            if st != GO_ON:
                status = st
                break
            continue
        # ---- accepted: the earliest event in this step, the history inside it
        ev, theta = first_event(gold, gnew, law, p, fric, c, md, y, K, h, Q, yt, record)
        if ev == EV_SEP and may_approach:
            # the step crossed separation: its last part in w from the step's start instead
            st, t, n_a, n_e, c, md, hist, nh, gold = approach_end(
                law, p, fric, c, md, y, K, t, rtol, sc, tstar, dstar, fscale, acc, diag, record,
                hist, nh, wwork,
            )  # fmt: skip
            nsteps += n_a
            nevents += n_e
            may_approach = False
            if st != GO_ON:
                status = st
                break
            continue
        if ev >= 0:
            tend = t + theta * h
        else:
            theta = 1.0
            for i in range(NS):
                yev[i] = ynew[i]
            tend = t + h
        if record:
            hist, nh = record_substeps(hist, nh, t, h, theta, law, p, fric, c, md, y, K, Q, yt)
        if ev >= 0:
            nsteps += integrate_to(law, p, fric, c, md, y, K[0], theta * h, rtol, sc, yev, rwork)
            nsteps -= 1
            evq = evaluate_cold(law, p, fric, c, md, state_tuple(yev))
        if not track(acc, law, p, fric, c, md, state_tuple(yev), evq, t, tend, diag):
            status = ST_NAN
            break
        t = tend
        for i in range(NS):
            y[i] = yev[i]
        h *= 10.0 if err == 0.0 else min(10.0, growth_llvm(err))
        if ev < 0:
            for i in range(NS):
                K[0, i] = K[6, i]
            gold = gnew
            if record:
                hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
            if may_approach and near_separation(md, evq, h):
                st, t, n_a, n_e, c, md, hist, nh, gold = approach_end(
                    law, p, fric, c, md, y, K, t, rtol, sc, tstar, dstar, fscale, acc, diag,
                    record, hist, nh, wwork,
                )  # fmt: skip
                nsteps += n_a
                nevents += n_e
                may_approach = False
                if st != GO_ON:
                    status = st
                    break
            continue
        # ---- the event at (t, y): stop, or switch the mode and restart
        nevents += 1
        if nevents > MAX_EVENTS:
            status = ST_TOO_MANY_EVENTS
            break
        if record:
            hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
        turning = ev == EV_VN and md[M_PHASE] == 0.0
        st, c, md, gold = handle_event(
            ev, law, p, fric, c, md, y, evq, acc, K, gold, sc, fscale, dstar
        )
        if st != GO_ON:
            status = st
            break
        if turning:  # off the loading curve: onto the stiffer unloading branch
            h *= _unloading_factor(md)
        may_approach = True
    return status, t, nsteps, md, hist, nh


@njit(cache=True, error_model="numpy")
def _regime(fric, md, acc, t, vn0):
    """Friction regime code of the finished impact (``status.REGIME_*``)."""
    vs_pos = acc[A_VSPOS]
    vs_neg = acc[A_VSNEG]
    sir = md[M_SIR]
    vtol = SLIP_VTOL * abs(vn0)
    if fric == FR_NONE or (fric == FR_IMPULSE and sir == 0.0):  # no tangential force at all
        return REGIME_FRICTIONLESS
    if vs_pos > vtol and vs_neg < -vtol:
        return REGIME_REVERSAL
    if fric == FR_IMPULSE and slid_along_friction(sir, vs_pos, vs_neg, vtol):
        # the contact point slid along the constant friction force (friction doing work on the
        # body): the paper's Eq. 7 is outside its validity (mu beyond mu_c)
        return REGIME_REVERSAL
    if acc[A_STICK] > 1e-9 * t:
        return REGIME_STICK
    return REGIME_SLIP


@njit_internal
def _separation(out, fric, c, md, y, acc, t, vx0, vy0, vn0, th0, rod, e0, rtol, diag):
    """Write the results at separation (state ``y`` at time ``t``) into ``out``, the result
    flags included."""
    _delta, a, b, xs, slide = geometry(c, state_tuple(y))
    m = c[C_M]
    inertia = c[C_I]
    g = c[C_G]
    vx = y[S_VX]
    vy = y[S_VY]
    w = y[S_SPIN]
    vn = vy - w * a
    vt = vx + w * b
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
    e_kin = 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * w * w
    e_pot = m * g * y[S_Y]
    out[O_ED] = e0 - (e_kin + e_pot)
    flags = result_flags(e0, e_kin, e_pot, y[S_WORK], rtol, m * g * t, pn)
    vtol = SLIP_VTOL * abs(vn0)
    if fric == FR_IMPULSE and slid_along_friction(md[M_SIR], acc[A_VSPOS], acc[A_VSNEG], vtol):
        # Eq. 7's constant force pushed the contact point along its slip: it did positive work
        # and created energy, which the normal contact's losses may hide from the net work
        flags = float(int(flags) | FLAG_ENERGY_GAIN)
    out[O_FLAGS] = flags
    out[O_STICK] = acc[A_STICK]
    out[O_REG] = _regime(fric, md, acc, t, vn0)
    out[O_VNOUT] = vn
    out[O_VTOUT] = vt
    out[O_ANG] = th0 + y[S_PHI] if rod else math.nan
    if diag:
        fmax = acc[A_FMAX]
        out[O_ERISE] = acc[A_ERISE] / e0
        out[O_FEX] = acc[A_FEX] / fmax if fmax > 0.0 else 0.0


@njit(cache=True, error_model="numpy")
def impact(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, record, diag, out):
    """Simulate one impact; fills ``out`` (OUTPUT_FIELDS) and returns (status, history, n).

    law: contact-law id; p: law parameters (NPARAM); fric: friction id; bp: body vector (NB);
    th0 [rad], vx0, vy0 [m/s], w0 [rad/s]: initial state at first touch; mu: friction
    coefficient; g: gravity [m/s^2] (0: off); const_angle: freeze the lever arms at th0;
    rtol: relative tolerance; record: keep the history; diag: compute the energy diagnostics.
    """
    for i in range(out.shape[0]):
        out[i] = math.nan
    # all of the impact's scratch in one allocation: state, accumulators, error scales, the
    # step loops' arrays (CHANGELOG.md, "Performance history"); no history row unless kept
    work = np.empty(IMPACT_WORK_LEN)
    y = work[:NS]
    acc = work[NS : NS + NA]
    sc = work[NS + NA : 2 * NS + NA]
    hist = np.empty((256, NH)) if record else work[:0].reshape((0, NH))
    status = check_inputs(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, rtol)
    if status != ST_OK:
        return status, hist[:0], 0
    if mu < MU_NEGLIGIBLE:
        fric = FR_NONE
    c = constants(p, bp, th0, mu, g, const_angle)
    vn0 = vy0 - w0 * c[C_A0]
    vt0 = vx0 + w0 * c[C_B0]
    out[O_VNIN] = vn0
    out[O_VTIN] = vt0
    if not (vn0 < 0.0):
        return ST_NOT_APPROACHING, hist[:0], 0
    md = initial_mode(fric, p, c, w0, vn0, vt0)
    tstar, dstar, fscale = error_scales(fric, p, c, vn0, sc)
    for i in range(NS):
        y[i] = 0.0
    y[S_VX] = vx0
    y[S_VY] = vy0
    y[S_SPIN] = w0
    e0 = 0.5 * c[C_M] * (vx0 * vx0 + vy0 * vy0) + 0.5 * c[C_I] * w0 * w0
    for i in range(NA):
        acc[i] = 0.0
    acc[A_EMIN] = e0
    status, t, nsteps, md, hist, nh = _integrate(
        law, p, fric, c, md, y, sc, tstar, dstar, fscale, rtol, record, diag, hist, acc,
        work[2 * NS + NA :],
    )  # fmt: skip
    out[O_NST] = nsteps
    out[O_DMAX] = acc[A_DMAX]
    out[O_FMAX] = acc[A_FMAX]
    out[O_TMAX] = acc[A_TMAX]
    out[O_T] = t
    if status != ST_OK:
        return status, hist[:nh], nh
    rod = bp[BP_KIND] == KIND_ROD
    _separation(out, fric, c, md, y, acc, t, vx0, vy0, vn0, th0, rod, e0, rtol, diag)
    return ST_OK, hist[:nh], nh
