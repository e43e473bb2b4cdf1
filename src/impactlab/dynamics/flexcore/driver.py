"""``drop``: the event loop of the flexible drop, from the first touch of the tip (end 0) until
the rod leaves the flat for good (compiled; docs/flexible.md).

The loop alternates closed-form free-flight jumps (``flight``) and error-controlled
Dormand-Prince steps (``stepper``); an accepted step that crosses an event is cut at the
event, whose action (``contacts``) changes the mode table; simultaneous events at one instant
are resolved in a bounded loop. The work of each branch is in the helpers it calls.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import (
    AT_ACCEPT,
    AT_COAST,
    AT_EVENTS,
    AT_OUTPUTS,
    AT_RECORD,
    AT_STEP,
    call_accept,
    call_coast,
    call_events,
    call_outputs,
    call_record,
    call_step,
)
from impactlab.dynamics.flexcore.cells import step_cap
from impactlab.dynamics.flexcore.coast import complete_jump, refresh_thresholds
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.flexcore.setup import (
    first_touch,
    scales,
    state_size,
    touch_modes,
    workspace,
)
from impactlab.dynamics.flexcore.steps import reject
from impactlab.dynamics.kernels.buffers import copy_into
from impactlab.dynamics.kernels.step_control import power_growth


@njit(cache=True, error_model="numpy")
def drop(mdl, vx0, vy0, w0, rtol, t_max, stop_mode, record_on, out, contacts, dents, yfinal):
    """Simulate the drop from the first touch of end 0 until the rod leaves the flat for good.

    ``mdl``: the model tuple (package docstring); vx0, vy0 [m/s], w0 [rad/s]: rigid-body
    velocities at first touch (end 0 at delta = 0, undeformed, modes at rest); rtol: relative
    tolerance; t_max [s]; stop_mode: 0 the sequence of the tip, 1 through the other end's
    impacts ("flight"); record_on: keep a history. Fills ``out`` (layout.N_DROP_OUT), ``contacts``
    (MAX_CONTACTS, NCR), ``dents`` (MAX_DENTS, NDT) and ``yfinal`` (the state where the end
    criterion was met). Returns (status, n_contacts, n_dents, history, n_history).
    """
    M = mdl[3].shape[0]
    partial = mdl[2][F.FC_FRIC] == F.FR_PARTIAL
    n = state_size(M, mdl[2][F.FC_FRIC])
    nev = F.NFEV + (F.NE * F.NFEVC if partial else 0)
    sv, md, y, sc, Jn, Jt, ek, ev, gold, gnew, K, Q, st, ynew, yt, yev, der, snap = workspace(
        n, M, nev
    )
    cur_con = np.full(F.NE, -1)
    hist = np.empty((1024 if record_on else 1, F.N_DROP_HISTORY))
    nh = np.int64(0)  # not a literal: history_row() is compiled once, for any row count
    scales(mdl, vx0, vy0, w0, sc, sv)  # first: the cell parameters of partial slip
    sv[F.SV_TOL_MISS] = F.MISS_TOL_FACTOR * max(1e-6, rtol) * sv[F.SV_DSTAR]
    first_touch(mdl, md, y, vx0, vy0, w0, sv, contacts, dents, cur_con)
    evaluate_model(mdl, md, y, der, ev, ek, Jn, Jt)
    touch_modes(mdl, md, y, der, ev, ek, Jn, Jt)
    t = 0.0
    h = 0.02 * sv[F.SV_TSTAR] * rtol**0.2
    evaluate_model(mdl, md, y, K[0], gold, ek, Jn, Jt)
    if record_on:
        hist, nh = call_record(mdl[AT_RECORD], hist, nh, t, mdl, y, ek, sv[F.SV_E0])
    y_end = y.copy()  # the state right after the last separation
    while sv[F.SV_NSTEPS] < mdl[2][F.FC_MAX_STEPS]:
        if t > t_max:
            sv[F.SV_STATUS] = F.ST_TMAX
            break
        if md[0, F.MD_IN] == 0.0 and md[1, F.MD_IN] == 0.0:
            code, tau = call_coast(mdl[AT_COAST], mdl, y, t, h, sv, stop_mode, yev, ek)
            if code == 2:
                break
            if code == 1:
                t, hist, nh = complete_jump(mdl, md, y, t, tau, K, gold, sv, dents, record_on,
                                            hist, nh, yev, yt, der, ev, ek, Jn, Jt)  # fmt: skip
                continue
        sv[F.SV_NSTEPS] += 1
        h = min(h, sv[F.SV_HMAX])
        h = step_cap(h, mdl[2], md, ek, sv[F.SV_HMIN])  # partial slip: a cell boundary
        err = call_step(mdl[AT_STEP], mdl, md, y, K, h, rtol, sc, st, ynew, gnew, ek, Jn, Jt)
        if not err <= 1.0:
            h = reject(h, err, sv)
            if h == 0.0:
                break
            continue
        ok, jev, t, hist, nh = call_accept(mdl[AT_ACCEPT], mdl, md, y, t, h, rtol, sc, K, Q,
                                           gold, gnew, ynew, yev, sv, contacts, dents,
                                           cur_con, record_on, hist, nh, yt, der, ev, ek,
                                           Jn, Jt)  # fmt: skip
        if not ok:
            break
        copy_into(y, yev)
        h *= 10.0 if err == 0.0 else min(10.0, power_growth(err))
        if jev < 0:
            copy_into(K[0], K[6])
            copy_into(gold, gnew)
            refresh_thresholds(mdl, md, y, K, gold, sv, dents, ek, Jn, Jt)
        else:
            sv[F.SV_NEVENTS] += 1
            if sv[F.SV_NEVENTS] > F.DROP_MAX_EVENTS:
                sv[F.SV_STATUS] = F.ST_TOO_MANY_EVENTS
                break
            handled = call_events(mdl[AT_EVENTS], jev, mdl, md, y, t, K, gold, sv, sc, contacts,
                                  dents, cur_con, snap, y_end, der, ev, ek, Jn, Jt)  # fmt: skip
            if not handled:
                break
        if record_on:
            hist, nh = call_record(mdl[AT_RECORD], hist, nh, t, mdl, y, ek, sv[F.SV_E0])
    copy_into(yfinal, y[: min(n, yfinal.shape[0])])
    call_outputs(mdl[AT_OUTPUTS], mdl, sv, t, y_end, vx0, vy0, out, contacts, dents)
    return int(sv[F.SV_STATUS]), int(sv[F.SV_NCON]), int(sv[F.SV_ND]), hist[:nh], nh
