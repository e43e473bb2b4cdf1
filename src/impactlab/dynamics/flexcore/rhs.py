"""Right-hand side and event functions of the flexible drop (compiled).

Equations of motion (mass-normalised modes, floating frame; docs/flexible.md):
m X'' = sum F_t,   m Y'' = sum F_n - m g,   I_C phi'' = sum (J_n,phi F_n + J_t,phi F_t),
q_j'' = -omega_j^2 q_j - 2 zeta_j omega_j q_j' - dV_g/dq_j + sum (J_n,j F_n + J_t,j F_t),
with F_n from the contact law and F_t from the friction model (``friction``): Coulomb
F_t = -sign(v_t) mu F_n in slip and, in stick, the force that keeps v_t = 0 (from the tangential
mobility J_t M^-1 J_t^T; a 2x2 system when both ends stick); impulse_ratio s mu F_n; Mindlin
from the end's tangential state Q_t (its rate is a state derivative); partial slip from the
end's cells (``cells``: their forces are state components after the quadratures, their
switches events after the ends'). Quadratures: the works of
the normal forces, of friction and of the damping, and per end the impulses and slip integrals.
An event fires when its function goes from <= 0 to > 0.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_RHS, call_rates
from impactlab.dynamics.flexcore.cells import cell_events, cell_forces, cell_rates
from impactlab.dynamics.flexcore.friction import friction_event, state_rate, tangential
from impactlab.dynamics.flexcore.kinematics import end_kinematics, mobility, normal_force
from impactlab.dynamics.kernels._jit import njit_internal, njit_llvm_inline
from impactlab.dynamics.kernels.layout import FR_COULOMB


@njit(cache=True, inline="always", error_model="numpy")
def _end_state(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt, k):
    """Kinematics and normal force of end k into ``ek`` (F_t, k_t zero); returns delta [m]."""
    delta, xS, vn, vt, jdot = end_kinematics(c, Ue, We, Pe, y, k, Jn, Jt)
    ek[k, F.EK_DELTA] = delta
    ek[k, F.EK_X] = xS
    ek[k, F.EK_VN] = vn
    ek[k, F.EK_VT] = vt
    ek[k, F.EK_FN] = normal_force(law, p, md, k, delta)
    ek[k, F.EK_JDOT] = jdot
    ek[k, F.EK_FT] = 0.0
    ek[k, F.EK_KT] = 0.0
    return delta


@njit(cache=True, inline="always", error_model="numpy")
def _end_forces(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt):
    """Kinematics of both ends and the contact forces without stick forces into ``ek``
    (every friction model but partial slip)."""
    mu = c[F.FC_MU]
    iqt = 6 + 2 * Ue.shape[1] + F.Q_TAN
    for k in range(F.NE):
        delta = _end_state(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt, k)
        if md[k, F.MD_IN] != 0.0 and mu > 0.0:
            ft, kt = tangential(law, p, c, md, k, y[iqt + k], delta, ek[k, F.EK_FN])
            ek[k, F.EK_FT] = ft
            ek[k, F.EK_KT] = kt


@njit(cache=True, inline="always", error_model="numpy")
def _end_forces_cells(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt):
    """``_end_forces`` for partial slip: the friction force of an end from its cells."""
    mu = c[F.FC_MU]
    o = 6 + 2 * Ue.shape[1] + F.NQUAD
    for k in range(F.NE):
        _end_state(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt, k)
        if md[k, F.MD_IN] != 0.0 and mu > 0.0:
            ek[k, F.EK_FT] = cell_forces(law, p, c, md, k, y, o + k * F.NCS, ek)


@njit(cache=True, inline="always", error_model="numpy")
def _geometric_forces(Tg, ia, ib, y, der, iv):
    """Subtract the geometric-stiffness forces dV_g/dq from the modal accelerations."""
    nbg = Tg.shape[1]
    for a in range(Tg.shape[0]):
        qa = y[3 + ia[a]]
        for b in range(nbg):
            sb = 0.0
            for cc in range(nbg):
                sb += Tg[a, b, cc] * y[3 + ib[cc]]
            der[iv + 3 + ib[b]] -= qa * sb
            der[iv + 3 + ia[a]] -= 0.5 * y[3 + ib[b]] * sb


@njit(cache=True, inline="always", error_model="numpy")
def _accelerations(c, om2, dmp, Tg, ia, ib, md, y, der, ek, Jn, Jt):
    """Velocities and accelerations without the stick forces."""
    M = om2.shape[0]
    iv = 3 + M
    m = c[F.FC_M]
    for i in range(3):
        der[i] = y[iv + i]
    for j in range(M):
        der[3 + j] = y[iv + 3 + j]
    ax = 0.0
    ay = -c[F.FC_G] * m
    aw = 0.0
    for j in range(M):
        der[iv + 3 + j] = -om2[j] * y[3 + j] - dmp[j] * y[iv + 3 + j]
    if Tg.shape[0] > 0:
        _geometric_forces(Tg, ia, ib, y, der, iv)
    for k in range(F.NE):
        if md[k, F.MD_IN] == 0.0:
            continue
        Fn = ek[k, F.EK_FN]
        Ft = ek[k, F.EK_FT]
        ax += Ft
        ay += Fn
        aw += Jn[k, 2] * Fn + Jt[k, 2] * Ft
        for j in range(M):
            der[iv + 3 + j] += Jn[k, 3 + j] * Fn + Jt[k, 3 + j] * Ft
    der[iv] = ax / m
    der[iv + 1] = ay / m
    der[iv + 2] = aw / c[F.FC_I]


@njit(cache=True, inline="always", error_model="numpy")
def _tangential_acceleration(ek, Jt, der, iv, M, k):
    """J_t z'' + jdot of end k (without its stick force)."""
    a = ek[k, F.EK_JDOT] + Jt[k, 0] * der[iv] + Jt[k, 1] * der[iv + 1] + Jt[k, 2] * der[iv + 2]
    for j in range(M):
        a += Jt[k, 3 + j] * der[iv + 3 + j]
    return a


@njit(cache=True, inline="always", error_model="numpy")
def _stick_forces(c, M, md, der, ek, Jt):
    """Add the stick forces of the sticking ends (a 1x1 or 2x2 system) to ``der`` and
    ``ek``. Two sticking ends whose tangential constraints are redundant (singular 2x2
    mobility: a rigid rod lying flat) share the least-norm forces."""
    iv = 3 + M
    m = c[F.FC_M]
    ns = 0
    # run-time integers: a literal -1 had numba compile ``mobility`` for it as well, while it
    # typed the loop below (a signature of its own, never called)
    sk0 = np.int64(-1)
    sk1 = np.int64(-1)
    for k in range(F.NE):
        if md[k, F.MD_IN] != 0.0 and md[k, F.MD_FM] == 0.0:
            if ns == 0:
                sk0 = np.int64(k)
            else:
                sk1 = np.int64(k)
            ns += 1
    if ns == 0:
        return
    a0 = _tangential_acceleration(ek, Jt, der, iv, M, sk0)
    A00 = mobility(c, M, Jt, Jt, sk0, sk0)
    if ns == 1:
        f0 = -a0 / A00
        f1 = 0.0
    else:
        a1 = _tangential_acceleration(ek, Jt, der, iv, M, sk1)
        A11 = mobility(c, M, Jt, Jt, sk1, sk1)
        A01 = mobility(c, M, Jt, Jt, sk0, sk1)
        det = A00 * A11 - A01 * A01
        if det > 1e-12 * A00 * A11:
            f0 = (-a0 * A11 + a1 * A01) / det
            f1 = (-a1 * A00 + a0 * A01) / det
        else:  # redundant constraints (a rigid rod flat on the flat): the least-norm forces
            tr2 = (A00 + A11) * (A00 + A11)  # A rank 1: its pseudo-inverse is A / tr(A)^2
            f0 = -(A00 * a0 + A01 * a1) / tr2
            f1 = -(A01 * a0 + A11 * a1) / tr2
    for t in range(ns):
        ks = sk0 if t == 0 else sk1
        f = f0 if t == 0 else f1
        ek[ks, F.EK_FT] = f
        der[iv] += f / m
        der[iv + 2] += Jt[ks, 2] * f / c[F.FC_I]
        for j in range(M):
            der[iv + 3 + j] += Jt[ks, 3 + j] * f


@njit(cache=True, inline="always", error_model="numpy")
def _quadratures(c, dmp, md, y, der, ek):
    """Derivatives of the works (the drop's and each end's own) and of the per-end impulses
    and slip integrals."""
    M = dmp.shape[0]
    iv = 3 + M
    iq = 6 + 2 * M
    iw = y.shape[0] - F.N_END_WORKS
    mu = c[F.FC_MU]
    wn = 0.0
    wt = 0.0
    for k in range(F.NE):
        b = iq + 3 + 4 * k
        if md[k, F.MD_IN] != 0.0:
            pn = ek[k, F.EK_FN] * ek[k, F.EK_VN]
            pt = ek[k, F.EK_FT] * ek[k, F.EK_VT]
            wn += pn
            wt += pt
            der[iw + 2 * k] = pn
            der[iw + 2 * k + 1] = pt
            der[b] = ek[k, F.EK_FN]
            der[b + 1] = ek[k, F.EK_FT]
            der[b + 2] = ek[k, F.EK_VT]
            if mu > 0.0 and c[F.FC_FRIC] == FR_COULOMB:
                der[b + 3] = md[k, F.MD_FM] * ek[k, F.EK_VT]
            else:
                der[b + 3] = abs(ek[k, F.EK_VT])
            der[iq + F.Q_TAN + k] = state_rate(c, md, k, ek[k, F.EK_KT], ek[k, F.EK_VT])
        else:
            der[b] = 0.0
            der[b + 1] = 0.0
            der[b + 2] = 0.0
            der[b + 3] = 0.0
            der[iq + F.Q_TAN + k] = 0.0
            der[iw + 2 * k] = 0.0
            der[iw + 2 * k + 1] = 0.0
    wd = 0.0
    for j in range(M):
        wd -= dmp[j] * y[iv + 3 + j] * y[iv + 3 + j]
    der[iq] = wn
    der[iq + 1] = wt
    der[iq + 2] = wd


@njit(cache=True, inline="always", error_model="numpy")
def _events(law, p, c, md, y, ev, ek, M):
    """The event functions of both ends (-1 where an event cannot fire in the mode)."""
    mu = c[F.FC_MU]
    iqt = 6 + 2 * M + F.Q_TAN
    for k in range(F.NE):
        e0 = k * F.NFEVK
        for i in range(F.NFEVK):
            ev[e0 + i] = -1.0
        delta = ek[k, F.EK_DELTA]
        if md[k, F.MD_IN] == 0.0:
            ev[e0 + F.FEV_TOUCH] = delta - md[k, F.MD_DR]  # out of contact F.MD_DR is the threshold
            continue
        comp = md[k, F.MD_COMP] != 0.0
        vn = ek[k, F.EK_VN]
        ev[e0 + F.FEV_VN] = vn if comp else -vn
        if md[k, F.MD_PH] == 0.0:
            ev[e0 + F.FEV_LIMIT] = delta - c[F.FC_DLIM]
            ev[e0 + F.FEV_SWITCH] = delta - md[k, F.MD_DSW]
        elif comp:
            ev[e0 + F.FEV_RELOAD] = delta - md[k, F.MD_DM]
        else:
            ev[e0 + F.FEV_SEP] = md[k, F.MD_DR] - delta
        if mu > 0.0:
            ev[e0 + F.FEV_FRIC] = friction_event(law, p, c, md, k, y[iqt + k], ek)


@njit_internal
def rates(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, y, der, ev, ek, Jn, Jt):
    """Derivative ``der`` and event values ``ev`` at state y in the mode table md; ``ek``
    (F.NE, NEK) receives per end the evaluated quantities (``layout.EK_*``), Jn and Jt the
    Jacobian rows. The model's arrays one by one (the hot path: see ``evaluate_model``). Every
    friction model but partial slip (``rates_cells``)."""
    _end_forces(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt)
    _accelerations(c, om2, dmp, Tg, ia, ib, md, y, der, ek, Jn, Jt)
    if c[F.FC_MU] > 0.0 and c[F.FC_FRIC] == FR_COULOMB:
        _stick_forces(c, om2.shape[0], md, der, ek, Jt)
    _quadratures(c, dmp, md, y, der, ek)
    _events(law, p, c, md, y, ev, ek, om2.shape[0])


@njit_internal
def rates_cells(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, y, der, ev, ek, Jn, Jt):
    """``rates`` for partial slip: the friction forces, rates and events of the cells."""
    _end_forces_cells(law, p, c, Ue, We, Pe, md, y, ek, Jn, Jt)
    _accelerations(c, om2, dmp, Tg, ia, ib, md, y, der, ek, Jn, Jt)
    _quadratures(c, dmp, md, y, der, ek)
    _events(law, p, c, md, y, ev, ek, om2.shape[0])
    o = 6 + 2 * om2.shape[0] + F.NQUAD
    for k in range(F.NE):
        cell_rates(c, md, k, o + k * F.NCS, ek, der)
        cell_events(c, md, k, ek, ev)


@njit_llvm_inline
def evaluate_model(mdl, md, y, der, ev, ek, Jn, Jt):
    """The right-hand side with the model tuple ``mdl`` (package docstring), through its
    address. Compiled once and inlined by LLVM into its 11 callers (``kernels._jit``): numba
    inlining it would unpack the model tuple again at each of them."""
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl[:13]
    rhs = mdl[AT_RHS]
    call_rates(rhs, law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, y, der, ev, ek, Jn, Jt)
