"""Kinematics of the rod's ends, the normal force, mobilities and energies (compiled).

Floating frame: the rigid motion (X, Y, phi) of the centre of mass C and the frame rotation,
plus the elastic displacement u(s) e_a + w(s) e_t = sum_j q_j (U_j(s) e_a + W_j(s) e_t) of the
free-free modes, with e_a = (cos th, sin th) from the tip (end 0, s = -L/2) to C,
e_t = (-sin th, cos th), th = angle + phi. Each end carries a hemisphere of radius R centred on
the end section and rotating with it; its lowest point P touches the flat y = 0, the
interference is delta = R - y_S (S: the sphere's centre). The slip velocity is that of the
sphere's material point at P: v_t = v_Sx + R (phi' + psi'(end)). J_n, J_t are the rows of
d v_P / d z' (z = (X, Y, phi, q)), so that the generalised contact forces J^T F do exactly the
contact's work (SI units).
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.kernels import P_ESTAR, loading_force, unloading_force
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.kernels._jit import njit_internal, njit_llvm_inline


@njit(cache=True, inline="always", error_model="numpy")
def end_kinematics(c, Ue, We, Pe, y, k, Jn, Jt):
    """(delta [m], x_S [m], v_n [m/s], v_t [m/s], jdot [m/s^2]) of end k at state y; fills
    the rows Jn[k], Jt[k] (length 3 + M). c: constants; Ue, We, Pe: modal end values (the
    arrays are passed one by one: unpacking the model tuple in this hot function would cost
    reference counting)."""
    M = Ue.shape[1]
    d = c[F.FC_D]
    R = c[F.FC_R]
    phi = y[2]
    th = c[F.FC_TH0] + phi
    s = math.sin(th)
    co = math.cos(th)
    iv = 3 + M
    vx = y[iv]
    vy = y[iv + 1]
    w_ = y[iv + 2]
    u = 0.0
    w = 0.0
    ud = 0.0
    wd = 0.0
    pd = 0.0
    for j in range(M):
        q = y[3 + j]
        qd = y[iv + 3 + j]
        u += Ue[k, j] * q
        w += We[k, j] * q
        ud += Ue[k, j] * qd
        wd += We[k, j] * qd
        pd += Pe[k, j] * qd
    sk = -d if k == 0 else d
    # exact differences from the initial pose (no cancellation for small phi)
    hs = math.sin(0.5 * phi)
    mid = c[F.FC_TH0] + 0.5 * phi
    dsin = 2.0 * math.cos(mid) * hs  # sin th - sin th0
    dcos = -2.0 * math.sin(mid) * hs  # cos th - cos th0
    el_y = u * s + w * co
    el_x = u * co - w * s
    if k == 0:
        delta = -y[1] + d * dsin - el_y
        xS = y[0] - d * dcos + el_x
    else:
        delta = -y[1] - d * (s + c[F.FC_S0]) - el_y
        xS = y[0] + d * (c[F.FC_C0] + co) + el_x
    lx = (sk + u) * co - w * s
    ly = (sk + u) * s + w * co
    vn = vy + w_ * lx + ud * s + wd * co
    vt = vx - w_ * ly + ud * co - wd * s + R * (w_ + pd)
    Jn[k, 0] = 0.0
    Jn[k, 1] = 1.0
    Jn[k, 2] = lx
    Jt[k, 0] = 1.0
    Jt[k, 1] = 0.0
    Jt[k, 2] = -ly + R
    for j in range(M):
        Jn[k, 3 + j] = Ue[k, j] * s + We[k, j] * co
        Jt[k, 3 + j] = Ue[k, j] * co - We[k, j] * s + R * Pe[k, j]
    jdot = -2.0 * w_ * (ud * s + wd * co) - w_ * w_ * lx
    return delta, xS, vn, vt, jdot


@njit(cache=True, inline="always", error_model="numpy")
def section_angle(c, Pe, y, k):
    """The angle of end k's section to the flat [rad]: the rod's, angle + phi, plus the
    section's elastic rotation psi(end) = sum Pe[k, j] q_j, with which its hemisphere turns
    (the rotation whose rate ``end_kinematics`` adds to the slip velocity)."""
    psi = 0.0
    for j in range(Pe.shape[1]):
        psi += Pe[k, j] * y[3 + j]
    return c[F.FC_TH0] + y[2] + psi


@njit(cache=True, inline="always", error_model="numpy")
def normal_force(law, p, md, k, delta):
    """Normal force [N] of end k at interference delta in its mode (0 out of contact)."""
    if md[k, F.MD_IN] == 0.0:
        return 0.0
    if md[k, F.MD_PH] == 0.0:
        return loading_force(law, p, delta)
    return unloading_force(p[P_ESTAR], md[k, F.MD_RR], md[k, F.MD_DR], delta)


@njit_llvm_inline
def mobility(c, M, Ja, Jb, ka, kb):
    """J_a M^-1 J_b^T for row ka of Ja and row kb of Jb [1/kg] (compiled once, inlined by LLVM
    at its five call sites: ``kernels._jit``)."""
    r = Ja[ka, 0] * Jb[kb, 0] / c[F.FC_M] + Ja[ka, 1] * Jb[kb, 1] / c[F.FC_M]
    r += Ja[ka, 2] * Jb[kb, 2] / c[F.FC_I]
    for j in range(M):
        r += Ja[ka, 3 + j] * Jb[kb, 3 + j]
    return r


@njit(cache=True, error_model="numpy")
def stick_ratio(c, M, Jn, Jt, k):
    """F_t / F_n that keeps end k sticking as F_n -> 0+ with no other force:
    -(J_t M^-1 J_n^T) / (J_t M^-1 J_t^T)."""
    return -mobility(c, M, Jt, Jn, k, k) / mobility(c, M, Jt, Jt, k, k)


@njit_internal
def geometric_energy(Tg, ia, ib, y):
    """The cubic geometric-stiffness potential 1/2 sum T_abc q_a q_b q_c [J]."""
    E = 0.0
    nbg = Tg.shape[1]
    for a in range(Tg.shape[0]):
        for b in range(nbg):
            sb = 0.0
            for cc in range(nbg):
                sb += Tg[a, b, cc] * y[3 + ib[cc]]
            E += 0.5 * y[3 + ia[a]] * y[3 + ib[b]] * sb
    return E


@njit_internal
def mechanical_energy(mdl, y):
    """T + V [J]: kinetic, modal strain (with the geometric term) and gravity from the
    first-touch pose."""
    _law, _p, c, om, om2, _dmp, _zeta, _Ue, _We, _Pe, Tg, ia, ib = mdl[:13]
    M = om.shape[0]
    iv = 3 + M
    m = c[F.FC_M]
    E = 0.5 * m * (y[iv] ** 2 + y[iv + 1] ** 2) + 0.5 * c[F.FC_I] * y[iv + 2] ** 2
    for j in range(M):
        E += 0.5 * (y[iv + 3 + j] ** 2 + om2[j] * y[3 + j] ** 2)
    E += m * c[F.FC_G] * y[1]
    if Tg.shape[0] > 0:
        E += geometric_energy(Tg, ia, ib, y)
    return E


@njit(cache=True, inline="always", error_model="numpy")
def vibration_energy(om2, M, y):
    """Modal (vibration) energy sum 1/2 (q'^2 + omega^2 q^2) [J] (linear part)."""
    iv = 3 + M
    E = 0.0
    for j in range(M):
        E += 0.5 * (y[iv + 3 + j] ** 2 + om2[j] * y[3 + j] ** 2)
    return E
