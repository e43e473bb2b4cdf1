"""The friction models of the flexible drop (compiled): ``impulse_ratio``, ``coulomb`` and
``mindlin`` with the semantics of the rigid engine (``impactlab.friction``, docs/engine), per
end and per contact.

- ``impulse_ratio`` (the paper's Eq. 7): F_t = s mu F_n over a contact, the sign s fixed at its
  touch against the slip of the contact point (when that is zero, against the slip the normal
  force alone starts: the sign of the stick ratio, as the rigid engine's sign of a b).
- ``coulomb``: slip F_t = -sign(v_t) mu F_n; stick with the force from the mobility system
  (``rhs``); the decisions at v_t = 0 in ``coulomb_decide``.
- ``mindlin``: k_t = 8 G* a on the current branch of the law (the rigid core's ``radius``, with
  the contact-radius factor at the turning point), the tangential state Q_t of the end (the
  force while the contact grows, the elastic displacement while it shrinks), capped by mu F_n;
  the event and the switch are the rigid core's kernels (``mindlin_trial_rate``,
  ``friction_switch``), fed with the end's mode in the rigid layout (``rigid_mode``).

- ``partial_slip``: Mindlin-Deresiewicz cells per end (``cells``, ``cellswitch``).

A re-contact is a new impact for the friction state: the mode (and Q_t = 0, the cells reset)
is set at touch.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.history_kernels import contact_radius as _contact_radius
from impactlab.contact.kernels import P_ESTAR, P_R
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.kinematics import stick_ratio
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.friction import LEVER_ROUNDOFF, friction_switch, mindlin_trial_rate
from impactlab.dynamics.kernels.layout import FR_COULOMB, FR_IMPULSE, FR_MINDLIN
from impactlab.dynamics.kernels.normal import radius


@njit(cache=True, inline="always", error_model="numpy")
def rigid_mode(md, k):
    """End k's mode as the rigid core's mode tuple (``kernels.layout.M_*``: phase, delta_m,
    delta_r, R_r, friction mode, compressing, impulse-ratio sign, radius factor)."""
    return (
        md[k, F.MD_PH],
        md[k, F.MD_DM],
        md[k, F.MD_DR],
        md[k, F.MD_RR],
        md[k, F.MD_FM],
        md[k, F.MD_COMP],
        md[k, F.MD_SIR],
        md[k, F.MD_AF],
    )


@njit(cache=True, inline="always", error_model="numpy")
def stiffness(law, p, c, md, k, delta):
    """Mindlin k_t = 8 G* a of end k on its branch [N/m]."""
    return 8.0 * c[F.FC_GS] * radius(law, p, rigid_mode(md, k), delta)


@njit(cache=True, inline="always", error_model="numpy")
def tangential(law, p, c, md, k, q, delta, fn):
    """(F_t [N], k_t [N/m]) of end k in contact (mu > 0) without the Coulomb stick force (added
    by the mobility system); q: the end's Mindlin state."""
    fric = c[F.FC_FRIC]
    fm = md[k, F.MD_FM]
    mu = c[F.FC_MU]
    if fric == FR_IMPULSE:
        return md[k, F.MD_SIR] * mu * fn, 0.0
    if fric == FR_MINDLIN:
        kt = stiffness(law, p, c, md, k, delta)
        if fm != 0.0:
            return -fm * mu * fn, kt
        if md[k, F.MD_COMP] != 0.0:
            return q, kt
        return -kt * q, kt
    return (-fm * mu * fn if fm != 0.0 else 0.0), 0.0


@njit(cache=True, inline="always", error_model="numpy")
def state_rate(c, md, k, kt, vt):
    """dQ_t/dt of end k (Mindlin without gross slip; 0 otherwise)."""
    if c[F.FC_FRIC] == FR_MINDLIN and md[k, F.MD_FM] == 0.0:
        return -kt * vt if md[k, F.MD_COMP] != 0.0 else vt
    return 0.0


@njit(cache=True, inline="always", error_model="numpy")
def friction_event(law, p, c, md, k, q, ek):
    """The stick/slip event function of end k in contact (as the rigid core's)."""
    fric = c[F.FC_FRIC]
    fm = md[k, F.MD_FM]
    mu = c[F.FC_MU]
    fn = ek[k, F.EK_FN]
    ft = ek[k, F.EK_FT]
    vt = ek[k, F.EK_VT]
    kt = ek[k, F.EK_KT]
    if fric == FR_COULOMB:
        return -fm * vt if fm != 0.0 else abs(ft) - mu * fn
    if fric != FR_MINDLIN:
        return -1.0
    if fm == 0.0:
        if md[k, F.MD_COMP] != 0.0:
            return abs(ft) - mu * fn
        return abs(q) - (mu * fn / kt if kt > 0.0 else 0.0)
    delta = ek[k, F.EK_DELTA]
    dft, dfn = mindlin_trial_rate(
        law, p, rigid_mode(md, k), delta, fn, ft, ek[k, F.EK_VN], vt, kt, c[F.FC_GS]
    )
    return fm * dft + mu * dfn


@njit(cache=True, error_model="numpy")
def coulomb_decide(c, M, Jn, Jt, k, Fn, Ft_stick, mu):
    """Friction mode of end k at v_t = 0: 0 (stick) if |F_stick| <= mu F_n, else the slip
    direction opposite to the needed force; at F_n = 0 the ratio as F_n -> 0+ decides."""
    if Fn > 0.0:
        if abs(Ft_stick) <= mu * Fn:
            return 0.0
        return -1.0 if Ft_stick > 0.0 else 1.0
    r = stick_ratio(c, M, Jn, Jt, k)
    if abs(r) <= mu:
        return 0.0
    return -1.0 if r > 0.0 else 1.0


@njit_internal
def initial_mode(p, c, M, md, k, vt, vn, Jn, Jt):
    """The friction mode of end k at touch (mu > 0): Coulomb the sign of v_t or the F_n -> 0+
    decision; impulse_ratio the sign of F_t; Mindlin gross slip when the Hertzian start ratio
    |F_t| / (mu F_n) -> 4 G* a_f |v_t| / (mu E* |v_n|) exceeds 1."""
    mu = c[F.FC_MU]
    fric = c[F.FC_FRIC]
    md[k, F.MD_FM] = 0.0
    md[k, F.MD_SIR] = 0.0
    if not mu > 0.0:
        return
    if fric == FR_COULOMB:
        if vt != 0.0:
            md[k, F.MD_FM] = 1.0 if vt > 0.0 else -1.0
        else:
            md[k, F.MD_FM] = coulomb_decide(c, M, Jn, Jt, k, 0.0, 0.0, mu)
    elif fric == FR_IMPULSE:
        if vt != 0.0:
            md[k, F.MD_SIR] = -1.0 if vt > 0.0 else 1.0
        else:
            r = stick_ratio(c, M, Jn, Jt, k)  # zero within round-off: a vertical rod
            md[k, F.MD_SIR] = 1.0 if r > LEVER_ROUNDOFF else (-1.0 if r < -LEVER_ROUNDOFF else 0.0)
    elif (
        fric == FR_MINDLIN
        and vt != 0.0
        and 4.0 * c[F.FC_GS] * md[k, F.MD_AF] * abs(vt) > mu * p[P_ESTAR] * abs(vn)
    ):
        md[k, F.MD_FM] = 1.0 if vt > 0.0 else -1.0


@njit_internal
def radius_factor(law, p, c, dm, dr, rr):
    """Mindlin and partial slip: a_loading(delta_m) / a_unloading(delta_m), the factor that
    makes the contact radius continuous at the turning point (as the rigid core's
    ``unloading_branch``; 1 for the other models)."""
    if (c[F.FC_FRIC] != FR_MINDLIN and c[F.FC_FRIC] != F.FR_PARTIAL) or not dm > 0.0:
        return 1.0
    a_unl = _contact_radius(law, p, dm, math.inf, dr, rr)
    a_load = _contact_radius(law, p, dm, dm, 0.0, p[P_R])
    return a_load / a_unl if a_unl > 0.0 else 1.0


@njit(cache=True, inline="always", error_model="numpy")
def mindlin_switch(c, md, k, y, iqt, ek):
    """The Mindlin stick/slip switch of end k (the rigid core's ``friction_switch``)."""
    fm, q = friction_switch(
        np.int64(FR_MINDLIN),  # a value, not a constant: see kernels._jit
        md[k, F.MD_FM],
        md[k, F.MD_COMP],
        0.0,
        y[iqt + k],
        ek[k, F.EK_FN],
        ek[k, F.EK_FT],
        ek[k, F.EK_VT],
        0.0,
        0.0,
        ek[k, F.EK_KT],
        c[F.FC_MU],
        1.0,
        1.0,
        0.0,
    )
    md[k, F.MD_FM] = fm
    y[iqt + k] = q


@njit(cache=True, inline="always", error_model="numpy")
def mindlin_after(mdl, md, k, kind, y, ek, sc, sv):
    """Mindlin: the state Q_t of end k and its error scale after the event ``kind`` (applied
    to ``md``; ``ek`` holds the quantities before it). Touch and separation: Q_t = 0; turning
    point: force -> displacement (k_t jumping with the law's radius: F kept if k_t grows, the
    displacement if it shrinks) or back; reload onto the loading curve: F scaled down if k_t
    drops. The conversions of the rigid core's ``mindlin_state_at_turn`` / ``_at_reload``."""
    law, p, c = mdl[0], mdl[1], mdl[2]
    if c[F.FC_FRIC] != FR_MINDLIN:
        return
    iqt = 6 + 2 * mdl[3].shape[0] + F.Q_TAN
    ft = ek[k, F.EK_FT]
    kt = ek[k, F.EK_KT]
    elastic = md[k, F.MD_FM] == 0.0 and c[F.FC_MU] > 0.0
    if kind == F.FEV_TOUCH or kind == F.FEV_SEP:
        y[iqt + k] = 0.0
    elif kind == F.FEV_VN and elastic:
        if md[k, F.MD_COMP] == 0.0:
            ktn = stiffness(law, p, c, md, k, ek[k, F.EK_DELTA])
            kref = ktn if ktn >= kt else kt
            y[iqt + k] = -ft / kref if kref > 0.0 else 0.0
        else:
            y[iqt + k] = ft
    elif kind == F.FEV_RELOAD and elastic:
        ktn = stiffness(law, p, c, md, k, ek[k, F.EK_DELTA])
        y[iqt + k] = ft if (ktn >= kt or kt <= 0.0) else ft * ktn / kt
    comp = md[k, F.MD_COMP] != 0.0 or md[k, F.MD_IN] == 0.0
    sc[iqt + k] = sv[F.SV_FSCALE] if comp else sv[F.SV_DSTAR]
