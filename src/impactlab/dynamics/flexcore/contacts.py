"""The event actions of the flexible drop: touch, turning point, reload, separation, stick and
slip, and the dents that carry the plastic history from one contact to the next (compiled).

Dents. Each contact leaves (or reloads) a dent on the flat with the unloading curve of its
deepest loading (delta_m, delta_r, R_r). A touch within the footprint of an existing dent of
the same end (the x-range of its contact-point path widened by its largest contact radius)
reloads along that dent's unloading curve until delta_m is passed, then follows the loading
curve; elsewhere the flat is virgin. Out of contact the touch threshold of an end is the
delta_r of the dent under it (0 over virgin flat).

Friction (``friction``: impulse_ratio, coulomb, mindlin as in the rigid engine): the mode is
set at every touch; Coulomb: in slip F_t = -sign(v_t) mu F_n; when v_t reaches 0 the stick
force is computed and the contact sticks while |F_t| <= mu F_n, else it slips against that
force; at F_n = 0 the ratio as F_n -> 0+ decides, as in the rigid engine.
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.contact.kernels import (
    P_ESTAR,
    loading_force,
    residual_depth,
    unloading_radius,
)
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.friction import (
    coulomb_decide,
    initial_mode,
    mindlin_switch,
    radius_factor,
)
from impactlab.dynamics.flexcore.kinematics import section_angle
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.layout import FR_COULOMB, FR_MINDLIN


@njit(cache=True, inline="always", error_model="numpy")
def in_dent(dents, nd, k, x):
    """Index of the deepest dent of end k whose footprint contains x (-1: none)."""
    best = -1
    bd = -1.0
    for i in range(nd):
        if dents[i, F.DT_END] != k:
            continue
        inside = (
            dents[i, F.DT_XLO] - dents[i, F.DT_AM] <= x <= dents[i, F.DT_XHI] + dents[i, F.DT_AM]
        )
        if inside and dents[i, F.DT_DR] > bd:
            bd = dents[i, F.DT_DR]
            best = i
    return best


@njit_internal
def set_threshold(md, dents, nd, k, x, delta):
    """Out of contact: the touch threshold of end k (F.MD_DR) and its dent (F.MD_DENT) at x. The
    threshold is kept where the new one would already be exceeded (the sphere, inside a dent's
    depression, moves sideways out of its footprint: it keeps the dent's threshold until it
    has risen above the surface)."""
    i = in_dent(dents, nd, k, x)
    thr = dents[i, F.DT_DR] if i >= 0 else 0.0
    if delta < thr or i == md[k, F.MD_DENT]:
        md[k, F.MD_DENT] = i
        md[k, F.MD_DR] = thr


@njit(cache=True, inline="always", error_model="numpy")
def pending(g, ek, md, k, kind, fric, tol_v, tol_d, tol_f):
    """Whether event ``kind`` of end k is already past its switch at a restart (several events
    at one instant). The interference events also need the rate that takes them there (touch
    and reload: delta increasing; separation: decreasing). Friction: Coulomb with the
    velocity or force tolerance, Mindlin as the rigid core's restart (any positive value)."""
    v = g[k * F.NFEVK + kind]
    vn = ek[k, F.EK_VN]
    if kind == F.FEV_TOUCH:
        return v > tol_d and vn < 0.0
    if kind == F.FEV_RELOAD:
        return v > tol_d and vn < 0.0
    if kind == F.FEV_SEP:
        return v > tol_d and vn > 0.0
    if kind == F.FEV_VN:
        return v > tol_v
    if kind == F.FEV_FRIC:
        if fric != FR_COULOMB:
            return v > 0.0
        if md[k, F.MD_FM] != 0.0:
            return v > tol_v
        return v > tol_f
    return v > 0.0


@njit_internal
def new_dent(dents, di, k, x, R):
    """Dent ``di`` of end k at x on virgin flat."""
    dents[di, F.DT_END] = k
    dents[di, F.DT_XLO] = x
    dents[di, F.DT_XHI] = x
    dents[di, F.DT_AM] = 0.0
    dents[di, F.DT_DM] = 0.0
    dents[di, F.DT_DR] = 0.0
    dents[di, F.DT_RR] = R
    dents[di, F.DT_FM] = 0.0
    dents[di, F.DT_NC] = 1.0


@njit(cache=True, inline="always", error_model="numpy")
def _reload_mode(mdl, md, dents, k, di):
    """Mode table of end k touching dent di: its unloading curve (loading if it has none)."""
    c = mdl[2]
    md[k, F.MD_PH] = 1.0
    md[k, F.MD_DM] = dents[di, F.DT_DM]
    md[k, F.MD_DR] = dents[di, F.DT_DR]
    md[k, F.MD_RR] = dents[di, F.DT_RR]
    md[k, F.MD_DSW] = c[F.FC_DSW] if dents[di, F.DT_DM] < c[F.FC_DSW] else math.inf
    md[k, F.MD_AF] = radius_factor(
        mdl[0], mdl[1], c, dents[di, F.DT_DM], dents[di, F.DT_DR], dents[di, F.DT_RR]
    )
    dents[di, F.DT_NC] += 1.0
    if dents[di, F.DT_DM] <= 0.0:
        md[k, F.MD_PH] = 0.0


@njit(cache=True, inline="always", error_model="numpy")
def on_touch(mdl, md, y, t, k, sv, contacts, dents, cur_con, snap, ek, Jn, Jt):
    """End k touches the flat at t: a new contact record, on its dent or a new one. Returns
    the status."""
    c, M = mdl[2], mdl[3].shape[0]
    iq = 6 + 2 * M
    if sv[F.SV_NCON] >= F.MAX_CONTACTS:
        return F.ST_TOO_MANY_CONTACTS
    di = int(md[k, F.MD_DENT])
    ci = int(sv[F.SV_NCON])
    sv[F.SV_NCON] += 1
    cur_con[k] = ci
    contacts[ci, F.CR_END] = k
    contacts[ci, F.CR_T0] = t
    contacts[ci, F.CR_X0] = ek[k, F.EK_X]
    contacts[ci, F.CR_DMAX] = ek[k, F.EK_DELTA]
    contacts[ci, F.CR_FMAX] = 0.0
    contacts[ci, F.CR_STICK] = 0.0
    contacts[ci, F.CR_TH0] = contacts[ci, F.CR_TH1] = section_angle(c, mdl[9], y, k)
    contacts[ci, F.CR_PAST] = sv[F.SV_SEQ_PASSED]
    contacts[ci, F.CR_VALONG] = 0.0
    contacts[ci, F.CR_VNIN] = abs(ek[k, F.EK_VN])
    if di >= 0:
        _reload_mode(mdl, md, dents, k, di)
        contacts[ci, F.CR_RELOAD] = 1.0
    else:
        if sv[F.SV_ND] >= F.MAX_DENTS:
            return F.ST_TOO_MANY_CONTACTS
        di = int(sv[F.SV_ND])
        sv[F.SV_ND] += 1
        new_dent(dents, di, k, ek[k, F.EK_X], c[F.FC_R])
        md[k, F.MD_PH] = 0.0
        md[k, F.MD_DM] = 0.0
        md[k, F.MD_DR] = 0.0
        md[k, F.MD_RR] = c[F.FC_R]
        md[k, F.MD_DSW] = c[F.FC_DSW]
        md[k, F.MD_AF] = 1.0
        contacts[ci, F.CR_RELOAD] = 0.0
    contacts[ci, F.CR_DENT] = di
    md[k, F.MD_DENT] = di
    md[k, F.MD_IN] = 1.0
    md[k, F.MD_COMP] = 1.0
    initial_mode(mdl[1], c, M, md, k, ek[k, F.EK_VT], ek[k, F.EK_VN], Jn, Jt)
    b = iq + 3 + 4 * k
    for i in range(4):
        snap[k, i] = y[b + i]
    iw = y.shape[0] - F.N_END_WORKS + 2 * k  # the end's own works
    snap[k, 4] = y[iw]
    snap[k, 5] = y[iw + 1]
    sv[F.SV_LAST_END] = k
    return F.ST_OK


@njit(cache=True, inline="always", error_model="numpy")
def on_turn(mdl, md, k, delta, dents):
    """Turning point of delta at end k: on the loading curve, the unloading branch of
    delta_m = delta is set and stored in its dent. Returns the status."""
    law, p = mdl[0], mdl[1]
    if md[k, F.MD_COMP] == 0.0:
        md[k, F.MD_COMP] = 1.0
        return F.ST_OK
    if md[k, F.MD_PH] == 0.0:
        Fm = loading_force(law, p, delta)
        dri = residual_depth(law, p, delta, Fm)
        if not (math.isfinite(Fm) and math.isfinite(dri) and 0.0 <= dri < delta):
            return F.ST_NAN
        md[k, F.MD_DM] = delta
        md[k, F.MD_DR] = dri
        md[k, F.MD_RR] = unloading_radius(p[P_ESTAR], delta, Fm, dri)
        md[k, F.MD_AF] = radius_factor(law, p, mdl[2], delta, dri, md[k, F.MD_RR])
        md[k, F.MD_PH] = 1.0
        di = int(md[k, F.MD_DENT])
        dents[di, F.DT_DM] = delta
        dents[di, F.DT_DR] = dri
        dents[di, F.DT_RR] = md[k, F.MD_RR]
        dents[di, F.DT_FM] = Fm
        am = loading_contact_radius(law, p, delta)
        if am > dents[di, F.DT_AM]:
            dents[di, F.DT_AM] = am
    md[k, F.MD_COMP] = 0.0
    return F.ST_OK


@njit(cache=True, inline="always", error_model="numpy")
def on_separation(mdl, md, y, t, k, sv, contacts, dents, cur_con, snap, y_end, ek):
    """End k leaves the flat at t: close its contact record, keep the state (``y_end``) and
    ask for an end-of-sequence test."""
    M = mdl[3].shape[0]
    iq = 6 + 2 * M
    ci = cur_con[k]
    b = iq + 3 + 4 * k
    contacts[ci, F.CR_DUR] = t - contacts[ci, F.CR_T0]
    contacts[ci, F.CR_PN] = y[b] - snap[k, 0]
    contacts[ci, F.CR_PT] = y[b + 1] - snap[k, 1]
    contacts[ci, F.CR_SLIP] = y[b + 2] - snap[k, 2]
    contacts[ci, F.CR_ASLIP] = y[b + 3] - snap[k, 3]
    contacts[ci, F.CR_X1] = ek[k, F.EK_X]
    contacts[ci, F.CR_DR] = md[k, F.MD_DR]
    iw = y.shape[0] - F.N_END_WORKS + 2 * k
    contacts[ci, F.CR_WN] = y[iw] - snap[k, 4]
    contacts[ci, F.CR_WT] = y[iw + 1] - snap[k, 5]
    contacts[ci, F.CR_TH1] = section_angle(mdl[2], mdl[9], y, k)
    cur_con[k] = -1
    md[k, F.MD_IN] = 0.0
    md[k, F.MD_FM] = 0.0
    md[k, F.MD_COMP] = 0.0
    sv[F.SV_LAST_END] = k
    sv[F.SV_T_LAST_SEP] = t
    for i in range(y.shape[0]):
        y_end[i] = y[i]
    sv[F.SV_T_CHECK] = -1.0  # test at once
    set_threshold(md, dents, int(sv[F.SV_ND]), k, ek[k, F.EK_X], ek[k, F.EK_DELTA])


@njit(cache=True, inline="always", error_model="numpy")
def on_friction(mdl, md, y, k, der, ev, ek, Jn, Jt):
    """Stick/slip switch of end k. Coulomb: from slip at v_t = 0, stick or reverse (decided
    with the stick force); from stick, slip against the needed force. Mindlin: the rigid
    core's switch (``friction.mindlin_switch``)."""
    c, M = mdl[2], mdl[3].shape[0]
    if c[F.FC_FRIC] == FR_MINDLIN:
        mindlin_switch(c, md, k, y, 6 + 2 * M + F.Q_TAN, ek)
    elif md[k, F.MD_FM] != 0.0:
        md[k, F.MD_FM] = 0.0
        evaluate_model(mdl, md, y, der, ev, ek, Jn, Jt)
        md[k, F.MD_FM] = coulomb_decide(c, M, Jn, Jt, k, ek[k, F.EK_FN], ek[k, F.EK_FT], c[F.FC_MU])
    else:
        md[k, F.MD_FM] = -1.0 if ek[k, F.EK_FT] > 0.0 else 1.0
