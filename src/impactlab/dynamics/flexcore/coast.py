"""The event loop out of contact: the end-of-sequence test, closed-form free-flight jumps and
the touch thresholds of the ends moving over the flat (compiled)."""

from __future__ import annotations

from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_RECORD, call_record
from impactlab.dynamics.flexcore.contacts import (
    set_threshold,
)
from impactlab.dynamics.flexcore.flight import flight, jump_length, left_for_good
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.kernels._jit import njit_internal


@njit(cache=True, inline="always", error_model="numpy")
def refresh_thresholds(mdl, md, y, K, gold, sv, dents, ek, Jn, Jt):
    """Out of contact the end moves over the flat: update its touch threshold (dent)."""
    for k in range(F.NE):
        if md[k, F.MD_IN] == 0.0:
            old = md[k, F.MD_DENT]
            set_threshold(md, dents, int(sv[F.SV_ND]), k, ek[k, F.EK_X], ek[k, F.EK_DELTA])
            if md[k, F.MD_DENT] != old:
                evaluate_model(mdl, md, y, K[0], gold, ek, Jn, Jt)


@njit(cache=True, inline="always", error_model="numpy")
def jump_time(mdl, y, h, sv, ek):
    """Free flight without contact: the time [s] to advance in closed form when no end can
    touch within two steps (0: integrate a step instead)."""
    Tg = mdl[10]
    if Tg.shape[0] > 0:
        return 0.0  # the closed-form flight is linear: integrate instead
    jump = jump_length(mdl, y, ek)
    if not jump > 2.0 * h:
        return 0.0
    return min(jump, max(sv[F.SV_CHECK_DT], 2.0 * h))


@njit_internal
def out_of_contact(mdl, y, t, h, sv, stop_mode, yev, ek):
    """No end in contact: the end-of-sequence test (every ``F.SV_CHECK_DT``; with ``stop_mode``
    1 also stop="sequence"'s, until it passes: ``F.SV_SEQ_PASSED``), then a free-flight jump if
    one is possible, its end state into ``yev``. Returns (code, tau): code 0 integrate a
    step, 1 jump by tau [s] (``complete_jump``), 2 the sequence is over. It evaluates no
    right-hand side (which would be compiled into it once more: ``docs/engine/first-run.md``)."""
    if t - sv[F.SV_T_CHECK] >= sv[F.SV_CHECK_DT]:
        sv[F.SV_T_CHECK] = t
        last = int(sv[F.SV_LAST_END])
        flight_min = F.NEW_IMPACT_CHECKS * sv[F.SV_CHECK_DT]
        eps = sv[F.SV_EPS_CLEAR]
        since = t - sv[F.SV_T_LAST_SEP]
        ring = sv[F.SV_T_RING]
        done, nx, tn = left_for_good(mdl, y, last, stop_mode, F.HORIZON_CAP, eps, flight_min,
                                     since, ring)  # fmt: skip
        if done:
            sv[F.SV_FINISHED] = 1.0
            sv[F.SV_NEXT_END] = nx
            sv[F.SV_NEXT_TIME] = tn
            sv[F.SV_STATUS] = F.ST_OK
            return 2, 0.0
        follow = stop_mode == 1 and sv[F.SV_SEQ_PASSED] == 0.0  # stop="sequence" would end?
        if follow and left_for_good(mdl, y, last, 0, F.HORIZON_CAP, eps, flight_min, since,
                                    ring)[0]:  # fmt: skip
            sv[F.SV_SEQ_PASSED] = 1.0
    tau = jump_time(mdl, y, h, sv, ek)
    if tau == 0.0:
        return 0, 0.0
    flight(mdl, y, tau, yev)
    return 1, tau


@njit(cache=True, inline="always", error_model="numpy")
def complete_jump(mdl, md, y, t, tau, K, gold, sv, dents, record_on, hist, nh, yev, yt, der, ev,
                  ek, Jn, Jt):  # fmt: skip
    """The free-flight jump by tau from (t, y) to ``yev`` (``out_of_contact``): the recorded
    points inside it, the state, the thresholds and the evaluations there. Returns
    (t, hist, nh)."""
    if record_on:
        for jj in range(1, 4):
            flight(mdl, y, tau * jj / 4.0, yt)
            evaluate_model(mdl, md, yt, der, ev, ek, Jn, Jt)
            hist, nh = call_record(
                mdl[AT_RECORD], hist, nh, t + tau * jj / 4.0, mdl, yt, ek, sv[F.SV_E0]
            )
    for i in range(y.shape[0]):
        y[i] = yev[i]
    t += tau
    sv[F.SV_NJUMPS] += 1
    evaluate_model(mdl, md, y, K[0], gold, ek, Jn, Jt)
    for k in range(F.NE):
        set_threshold(md, dents, int(sv[F.SV_ND]), k, ek[k, F.EK_X], ek[k, F.EK_DELTA])
    evaluate_model(mdl, md, y, K[0], gold, ek, Jn, Jt)
    if record_on:
        hist, nh = call_record(mdl[AT_RECORD], hist, nh, t, mdl, y, ek, sv[F.SV_E0])
    return t, hist, nh
