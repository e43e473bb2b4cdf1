"""Accepted and rejected Dormand-Prince steps of the event loop: the first event a step crosses,
the state at it, the recorded dense points, the statistics and the energy error (compiled)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_RECORD, call_record
from impactlab.dynamics.flexcore.kinematics import mechanical_energy
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.flexcore.stepper import dense, integrate_to, locate
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import copy_into
from impactlab.dynamics.kernels.cells import any_stuck
from impactlab.dynamics.kernels.dormand_prince import dense_coeffs
from impactlab.dynamics.kernels.layout import FR_COULOMB, FR_IMPULSE
from impactlab.dynamics.kernels.step_control import power_growth


@njit(cache=True, inline="always", error_model="numpy")
def _missed_touch(md, sv, gold, gnew, k):
    """The touch of end k (out of contact) that started the step on the wrong side of zero
    (0 < g <= the invariant's tolerance, e.g. after a grazing event recomputed a hair inside
    its dent) and ends it beyond the tolerance: located where g reaches the tolerance."""
    j = k * F.NFEVK + F.FEV_TOUCH
    tol = sv[F.SV_TOL_MISS]
    return md[k, F.MD_IN] == 0.0 and 0.0 < gold[j] <= tol < gnew[j]


@njit(cache=True, inline="always", error_model="numpy")
def _reversed_slip(mdl, md, gold, gnew, k):
    """The Coulomb slip of end k that started the step with its event function -fm v_t
    already positive (the state of a slip reversal recomputed a hair short of v_t = 0, within
    the integration tolerance, leaves the new direction against that v_t) and ends it larger:
    v_t went the new way and came back within the step, a sign change that the test from
    g <= 0 misses. Located where g climbs back through its start value."""
    j = k * F.NFEVK + F.FEV_FRIC
    slip = md[k, F.MD_IN] != 0.0 and md[k, F.MD_FM] != 0.0
    return slip and mdl[2][F.FC_FRIC] == FR_COULOMB and 0.0 < gold[j] < gnew[j]


@njit(cache=True, inline="always", error_model="numpy")
def first_event(mdl, md, y, h, K, Q, gold, gnew, sv, record_on, yt, der, ev, ek, Jn, Jt):
    """(jev, theta, fired): the earliest event crossed in the step (-1: none) and where; a
    touch that began the step within the invariant's tolerance past zero fires where it
    reaches the tolerance (``_missed_touch``), a Coulomb slip that began it against v_t where
    its event function climbs back through its start value (``_reversed_slip``)."""
    fired = False
    for j in range(gold.shape[0]):
        if gold[j] <= 0.0 and gnew[j] > 0.0:
            fired = True
    for k in range(F.NE):
        if _missed_touch(md, sv, gold, gnew, k) or _reversed_slip(mdl, md, gold, gnew, k):
            fired = True
    if fired or record_on:
        dense_coeffs(K, Q)
    jev = -1
    theta = 2.0
    if fired:
        nev = gold.shape[0]
        for i in range(nev + 2 * F.NE):  # the sign changes, missed touches, reversed slips
            if i < nev:
                if not (gold[i] <= 0.0 and gnew[i] > 0.0):
                    continue
                j = i
                shift = 0.0
            elif i < nev + F.NE:
                if not _missed_touch(md, sv, gold, gnew, i - nev):
                    continue
                j = (i - nev) * F.NFEVK + F.FEV_TOUCH
                shift = sv[F.SV_TOL_MISS]
            else:
                if not _reversed_slip(mdl, md, gold, gnew, i - nev - F.NE):
                    continue
                j = (i - nev - F.NE) * F.NFEVK + F.FEV_FRIC
                shift = gold[j]
            # one call site: locate is inlined here once (g - 0.0 is g, bit for bit)
            thj = locate(j, gold[j] - shift, gnew[j] - shift, mdl, md, y, h, Q, yt, der, ev, ek,
                         Jn, Jt, shift)  # fmt: skip
            if thj < theta:
                theta = thj
                jev = j
    return jev, theta, fired


@njit(cache=True, inline="always", error_model="numpy")
def missed_contact(md, sv, ek, jev):
    """The contact invariant after a step ending at event ``jev``: True when an end out of
    contact (other than one touching at ``jev``) lies below its touch threshold (its dent's
    surface, or the flat) by more than ``SV_TOL_MISS``: a touch the event search missed,
    which the drop refuses (``ST_MISSED_CONTACT``)."""
    for k in range(F.NE):
        if jev == k * F.NFEVK + F.FEV_TOUCH:
            continue
        if md[k, F.MD_IN] == 0.0 and ek[k, F.EK_DELTA] - md[k, F.MD_DR] > sv[F.SV_TOL_MISS]:
            return True
    return False


@njit(cache=True, inline="always", error_model="numpy")
def step_stats(mdl, md, t, tend, sv, contacts, dents, cur_con, ek):
    """Per-contact and run maxima (impulse_ratio: the slip velocity along the friction force),
    stick time and dent extents after a step to ``tend``; False on a non-finite force."""
    mu = mdl[2][F.FC_MU]
    sticks = mu > 0.0 and mdl[2][F.FC_FRIC] != FR_IMPULSE  # the models with a stick state
    partial = mdl[2][F.FC_FRIC] == F.FR_PARTIAL  # partial slip: a cell sticks
    ok = True
    for k in range(F.NE):
        if md[k, F.MD_IN] != 0.0:
            ci = cur_con[k]
            cells = md[k, F.MD_CM : F.MD_CM + F.NCS]
            if sticks and (any_stuck(cells) if partial else md[k, F.MD_FM] == 0.0):
                contacts[ci, F.CR_STICK] += tend - t
                sv[F.SV_STICK] += tend - t
            contacts[ci, F.CR_DMAX] = max(contacts[ci, F.CR_DMAX], ek[k, F.EK_DELTA])
            contacts[ci, F.CR_FMAX] = max(contacts[ci, F.CR_FMAX], ek[k, F.EK_FN])
            if mdl[2][F.FC_FRIC] == FR_IMPULSE:  # slip along the fixed force: positive work
                along = md[k, F.MD_SIR] * ek[k, F.EK_VT]
                contacts[ci, F.CR_VALONG] = max(contacts[ci, F.CR_VALONG], along)
            di = int(md[k, F.MD_DENT])
            dents[di, F.DT_XLO] = min(dents[di, F.DT_XLO], ek[k, F.EK_X])
            dents[di, F.DT_XHI] = max(dents[di, F.DT_XHI], ek[k, F.EK_X])
            sv[F.SV_FMAX] = max(sv[F.SV_FMAX], ek[k, F.EK_FN])
            sv[F.SV_DMAX] = max(sv[F.SV_DMAX], ek[k, F.EK_DELTA])
        if not (math.isfinite(ek[k, F.EK_FN]) and math.isfinite(ek[k, F.EK_FT])):
            ok = False
    return ok


@njit(cache=True, inline="always", error_model="numpy")
def record_inside(mdl, md, y, t, h, theta, Q, sv, hist, nh, yt, der, ev, ek, Jn, Jt):
    """Record the dense points at 1/4, 1/2, 3/4 of the step that lie before ``theta``."""
    for jj in range(1, 4):
        thj = jj / 4.0
        if thj >= theta:
            break
        dense(y, h, thj, Q, yt, y.shape[0])
        evaluate_model(mdl, md, yt, der, ev, ek, Jn, Jt)
        hist, nh = call_record(mdl[AT_RECORD], hist, nh, t + thj * h, mdl, yt, ek, sv[F.SV_E0])
    return hist, nh


@njit(cache=True, inline="always", error_model="numpy")
def reject(h, err, sv):
    """The step size after a rejected step (error norm ``err``); 0 with ``sv[F.SV_STATUS]`` set
    when it underflows."""
    h *= 0.25 if not math.isfinite(err) else max(0.2, power_growth(err))
    if h < sv[F.SV_HMIN]:
        sv[F.SV_STATUS] = F.ST_NAN if not math.isfinite(err) else F.ST_STEP_UNDERFLOW
        return 0.0
    return h


@njit_internal
def accept(mdl, md, y, t, h, rtol, sc, K, Q, gold, gnew, ynew, yev, sv, contacts, dents, cur_con,
           record_on, hist, nh, yt, der, ev, ek, Jn, Jt):  # fmt: skip
    """An accepted step from (t, y): cut at the first event it crosses (the state there into
    ``yev``), record, update the statistics and the energy error. Returns
    (ok, jev, tend, hist, nh); ok False on a non-finite force or a missed contact (the
    contact invariant, ``missed_contact``)."""
    jev, theta, fired = first_event(
        mdl, md, y, h, K, Q, gold, gnew, sv, record_on, yt, der, ev, ek, Jn, Jt
    )
    if jev >= 0:
        tend = t + theta * h
        steps = integrate_to(mdl, md, y, K[0], theta * h, rtol, sc, yev, ev, ek, Jn, Jt)
        sv[F.SV_NSTEPS] += steps - 1
    else:
        tend = t + h
        theta = 1.0
        copy_into(yev, ynew)
    if record_on:
        hist, nh = record_inside(mdl, md, y, t, h, theta, Q, sv, hist, nh, yt, der, ev, ek, Jn, Jt)
    if fired or record_on:
        evaluate_model(mdl, md, yev, der, ev, ek, Jn, Jt)
    if not step_stats(mdl, md, t, tend, sv, contacts, dents, cur_con, ek):
        sv[F.SV_STATUS] = F.ST_NAN
        return False, jev, tend, hist, nh
    if missed_contact(md, sv, ek, jev):
        sv[F.SV_STATUS] = F.ST_MISSED_CONTACT
        return False, jev, tend, hist, nh
    iq = 6 + 2 * mdl[3].shape[0]
    en = abs(mechanical_energy(mdl, yev) - sv[F.SV_E0] - yev[iq] - yev[iq + 1] - yev[iq + 2])
    sv[F.SV_EERR] = max(sv[F.SV_EERR], en)
    return True, jev, tend, hist, nh
