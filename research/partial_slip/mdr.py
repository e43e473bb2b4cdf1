"""Reference solution: Mindlin-Deresiewicz partial slip with arbitrary normal/tangential history,
solved exactly (up to discretisation) with the method of dimensionality reduction (MDR).

For an axisymmetric contact under the Cattaneo-Mindlin assumptions (no normal-tangential
coupling, tangential traction along one direction, local Coulomb law |q| <= mu p), the 3-D
contact is equivalent to a row of independent 1-D springs on |x| < a(t) with normal stiffness
E* dx and tangential stiffness G_1 dx, G_1 = 4 G* (G* = [(2-nu1)/G1 + (2-nu2)/G2]^-1, so that
the full-stick stiffness is 2 a G_1 = 8 G* a). Each tangential spring is an elastic-perfectly
plastic element with a time-varying limit mu q_n(x, t) (q_n the 1-D normal line load); it is
born unstressed when the contact radius passes its position and released when the radius
recedes past it. This reproduces Cattaneo-Mindlin and every Mindlin-Deresiewicz loading case
exactly for arbitrary histories (Popov & Hess, Method of Dimensionality Reduction in Contact
Mechanics and Friction, Springer 2015, doi:10.1007/978-3-642-53876-6, ch. 5 and 7; Jaeger,
Wear 2001 / Ciavarella IJSS 1998 for the superposition argument).

Normal line load: q_n(x) = (3 F_n / 4a) (1 - x^2/a^2) -- exact (= E*(delta - x^2/R)) for
Hertz and for the Hertzian unloading branch of every law (radius R_r); for the elastic-plastic
loading branch it is the assumption that the *shape* of the limiting traction stays Hertzian
while F_n and a come from the law (the assumption behind Thornton's M-D treatment of
elastic-plastic impacts).

The sphere's impact is integrated with velocity Verlet at a fixed step; the springs are updated
by the exact play-operator projection (clamp) once per step. This is the *reference*, not the
engine model: it carries N_springs history variables.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.kernels import (
    P_ESTAR,
    P_R,
    contact_radius,
    loading_force,
    turning_point,
    unloading_force,
)


@njit(cache=True)
def _normal(law, p, delta, dm, dr, Rr, af):
    """(F_n, a) on the branch given (delta_m, delta_r, R_r, radius factor)."""
    if delta <= 0.0:
        return 0.0, 0.0
    if delta >= dm:
        return loading_force(law, p, delta), contact_radius(law, p, delta, delta, 0.0, p[P_R])
    d = delta - dr
    if d <= 0.0:
        return 0.0, 0.0
    return unloading_force(p[P_ESTAR], Rr, dr, delta), af * math.sqrt(Rr * d)


@njit(cache=True)
def _branch(law, p, dm):
    """(delta_r, R_r, radius factor) of the unloading branch from delta_m."""
    Fm, dr, Rr = turning_point(law, p, dm)
    am = contact_radius(law, p, dm, dm, 0.0, p[P_R])
    ah = math.sqrt(Rr * (dm - dr)) if dm > dr else 0.0
    af = am / ah if ah > 0.0 else 1.0
    return dr, Rr, af


@njit(cache=True)
def normal_max(law, p, m, vn0, dt):
    """delta_max and contact radius at delta_max of a frictionless normal impact (sphere)."""
    y = 0.0
    v = -abs(vn0)
    F = 0.0
    dmax = 0.0
    for _ in range(10_000_000):
        vh = v + 0.5 * dt * F / m
        y += dt * vh
        d = -y
        F = loading_force(law, p, d) if d > 0.0 else 0.0
        v = vh + 0.5 * dt * F / m
        if d > dmax:
            dmax = d
        if v > 0.0:
            break
    return dmax, contact_radius(law, p, dmax, dmax, 0.0, p[P_R])


@njit(cache=True)
def impact(law, p, R, m, I, Gs, mu, vt0, vn0, w0, nspr, xmax, dt, nhist, hstride):
    """Oblique impact of a sphere (radius R, mass m, inertia I) on a flat.

    vt0: initial tangential velocity of the centre [m/s]; vn0 (< 0): normal velocity; w0: spin.
    Returns (out, hist): out = [vx, vy, w, e, duration, delta_max, energy_rise_max/KE0,
    final_stored_t, dissipated_friction, n_steps]; hist (nhist x 9) sampled rows
    [t, delta, Fn, Ft, v_slip, a, slip_fraction(of contact length), E_total, E_t].
    """
    G1 = 4.0 * Gs
    dx = xmax / nspr
    xs = (np.arange(nspr) + 0.5) * dx
    wsp = np.zeros(nspr)  # elastic tangential displacement of each spring [m]
    inc = np.zeros(nspr, dtype=np.bool_)
    y = 0.0
    u = 0.0
    vx = vt0
    vy = -abs(vn0)
    w = w0
    dm = 0.0
    dr = 0.0
    Rr = p[P_R]
    af = 1.0
    dm_branch = -1.0
    Fn = 0.0
    Ft = 0.0
    E0 = 0.5 * m * (vx * vx + vy * vy) + 0.5 * I * w * w
    erise = 0.0
    hist = np.zeros((nhist, 9))
    nh = 0
    t = 0.0
    nstep = 0
    dmax = 0.0
    diss = 0.0
    started = False
    kskip = max(1, hstride)
    for it in range(50_000_000):
        vxh = vx + 0.5 * dt * Ft / m
        vyh = vy + 0.5 * dt * Fn / m
        wh = w + 0.5 * dt * R * Ft / I
        y += dt * vyh
        du = dt * (vxh + wh * R)
        u += du
        t += dt
        nstep += 1
        delta = -y
        if delta > dm:
            dm = delta
        if delta < dm and dm != dm_branch:
            dr, Rr, af = _branch(law, p, dm)
            dm_branch = dm
        Fn, a = _normal(law, p, delta, dm, dr, Rr, af)
        if delta > dmax:
            dmax = delta
        Ft = 0.0
        nslip = 0
        if a > 0.0:
            started = True
            q0 = 0.75 * Fn / a
            for i in range(nspr):
                x = xs[i]
                if x < a:
                    lim = mu * q0 * (1.0 - (x / a) ** 2) / G1
                    if inc[i]:
                        wt = wsp[i] + du
                    else:
                        wt = 0.0
                        inc[i] = True
                    if wt > lim:
                        diss += G1 * (wt - lim) * lim * 2.0 * dx  # work of the slipping spring
                        wt = lim
                        nslip += 1
                    elif wt < -lim:
                        diss += G1 * (-lim - wt) * lim * 2.0 * dx
                        wt = -lim
                        nslip += 1
                    wsp[i] = wt
                    Ft -= 2.0 * dx * G1 * wt
                else:
                    if inc[i]:
                        inc[i] = False
                        wsp[i] = 0.0
        else:
            for i in range(nspr):
                inc[i] = False
                wsp[i] = 0.0
        vx = vxh + 0.5 * dt * Ft / m
        vy = vyh + 0.5 * dt * Fn / m
        w = wh + 0.5 * dt * R * Ft / I
        # energies
        Et = 0.0
        for i in range(nspr):
            if inc[i]:
                Et += G1 * wsp[i] * wsp[i] * dx  # 2 sides x 1/2 G w^2 dx
        if delta > 0.0 and Fn > 0.0:
            if delta >= dm:
                Fm_, drl, Rrl = turning_point(law, p, delta)
                En = 0.4 * Fn * (delta - drl)
            else:
                En = 0.4 * Fn * (delta - dr)
        else:
            En = 0.0
        Ek = 0.5 * m * (vx * vx + vy * vy) + 0.5 * I * w * w
        Etot = Ek + En + Et
        if Etot - E0 > erise:
            erise = Etot - E0
        if nstep % kskip == 0 and nh < nhist:
            row = hist[nh]
            row[0] = t
            row[1] = delta
            row[2] = Fn
            row[3] = Ft
            row[4] = vx + w * R
            row[5] = a
            row[6] = (nslip * dx / a) if a > 0.0 else 0.0
            row[7] = Etot
            row[8] = Et
            nh += 1
        if started and (a <= 0.0 or Fn <= 0.0) and vy > 0.0:
            break
    out = np.empty(10)
    out[0] = vx
    out[1] = vy
    out[2] = w
    out[3] = -vy / (-abs(vn0))
    out[4] = t
    out[5] = dmax
    out[6] = erise / E0
    Et = 0.0
    for i in range(nspr):
        Et += G1 * wsp[i] * wsp[i] * dx
    out[7] = Et
    out[8] = diss
    out[9] = nstep
    return out, hist[:nh]


@njit(cache=True)
def quasistatic(N_of_t, u_of_t, a_of_t, Gs, mu, nspr, xmax):
    """Tangential force for prescribed histories of F_n, tangential displacement u and contact
    radius a (arrays on the same time grid), with the Hertzian line-load shape. Returns F_t
    (force the flat exerts on the body, = -G1 sum w) and the stored energy."""
    G1 = 4.0 * Gs
    dx = xmax / nspr
    xs = (np.arange(nspr) + 0.5) * dx
    wsp = np.zeros(nspr)
    inc = np.zeros(nspr, dtype=np.bool_)
    n = N_of_t.size
    F = np.zeros(n)
    E = np.zeros(n)
    for k in range(n):
        du = u_of_t[k] - (u_of_t[k - 1] if k > 0 else 0.0)
        a = a_of_t[k]
        Fn = N_of_t[k]
        s = 0.0
        e = 0.0
        for i in range(nspr):
            x = xs[i]
            if a > 0.0 and x < a:
                lim = mu * 0.75 * Fn / a * (1.0 - (x / a) ** 2) / G1
                wt = wsp[i] + du if inc[i] else 0.0
                inc[i] = True
                if wt > lim:
                    wt = lim
                elif wt < -lim:
                    wt = -lim
                wsp[i] = wt
                s += wt
                e += wt * wt
            else:
                inc[i] = False
                wsp[i] = 0.0
        F[k] = -2.0 * dx * G1 * s
        E[k] = G1 * dx * e
    return F, E
