"""Free flight in closed form and the end-of-sequence test (compiled).

Out of contact the motion is known exactly: ballistic centre of mass, constant spin, damped
harmonic modes (linear model). When the conservative time to contact (clearance over a bound
on the approach speed) exceeds the current step, the state is advanced by that time at once
("conservative advancement").

The rod has left the flat for good (docs/flexible.md) when, with the exact rigid ballistic
motion and the rigorous bound B_k = |sum_j A_j (U_j, W_j)(end k)| on the elastic displacement
of end k (A_j = sqrt(q_j^2 + (q_j'/omega_j)^2); modal energy does not grow in free flight), the
lower bound y_S,k(rigid, tau) - R - B_k of the end that was in contact stays > 0 for all
tau in (0, tau_h], tau_h = min(2 v_Cy / g (C back at its height: a new drop), the time at
which another end can first reach the flat (a new impact, ``next_end``), ``HORIZON_CAP``); or
when that lower bound stays > 0 for at least ``flight_min`` (10 periods of the basis's first
mode) and then may reach the flat within tau_h: the end flies clear and comes back after the rod
turned, a new impact of the same end (``next_end`` that end, ``next_time`` the earliest it can
touch); or when, a period of the lowest mode or more after the separation, the end's rigid path
has risen above the flat and comes down (``falling_back``): its return is the rigid motion's,
a new impact too, even where the bound on the vibration hides the arc.
With ``stop_mode`` 1 ("flight") the other ends are no horizon: every end must stay clear.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.flexcore import layout as F


@njit(cache=True, error_model="numpy")
def flight(mdl, y, tau, out):
    """The exact force-free motion of y over tau [s] into ``out`` (damping work included)."""
    c, om, zeta = mdl[2], mdl[3], mdl[6]
    M = om.shape[0]
    iv = 3 + M
    iq = 6 + 2 * M
    for i in range(out.shape[0]):
        out[i] = y[i]
    g = c[F.FC_G]
    out[0] = y[0] + y[iv] * tau
    out[1] = y[1] + y[iv + 1] * tau - 0.5 * g * tau * tau
    out[2] = y[2] + y[iv + 2] * tau
    out[iv + 1] = y[iv + 1] - g * tau
    de = 0.0
    for j in range(M):
        w = om[j]
        z = zeta[j]
        q0 = y[3 + j]
        v0 = y[iv + 3 + j]
        if z == 0.0:
            cs = math.cos(w * tau)
            sn = math.sin(w * tau)
            out[3 + j] = q0 * cs + v0 / w * sn
            out[iv + 3 + j] = -q0 * w * sn + v0 * cs
        else:
            wd = w * math.sqrt(1.0 - z * z)
            ex = math.exp(-z * w * tau)
            cs = math.cos(wd * tau)
            sn = math.sin(wd * tau)
            b = (v0 + z * w * q0) / wd
            out[3 + j] = ex * (q0 * cs + b * sn)
            out[iv + 3 + j] = ex * ((v0) * cs - (w * w * q0 + z * w * v0) / wd * sn)
            de += 0.5 * (out[iv + 3 + j] ** 2 + w * w * out[3 + j] ** 2) - 0.5 * (
                v0 * v0 + w * w * q0 * q0
            )
    out[iq + 2] = y[iq + 2] + de


@njit(cache=True, error_model="numpy")
def bounds(om, Ue, We, M, y, k):
    """(B_k [m], V_k [m/s]): bounds on |elastic displacement| and |elastic velocity| of end
    k's sphere centre for all future free flight."""
    b = np.zeros(4)  # sum A |U|, sum A |W|, sum omega A |U|, sum omega A |W|
    for j in range(M):
        # amplitude of mode j: A = sqrt(q^2 + (q' / omega)^2)
        A = math.sqrt(y[3 + j] ** 2 + (y[3 + M + 3 + j] / om[j]) ** 2)
        au = A * abs(Ue[k, j])
        aw = A * abs(We[k, j])
        b += np.array((au, aw, om[j] * au, om[j] * aw))
    return math.sqrt(b[0] ** 2 + b[1] ** 2), math.sqrt(b[2] ** 2 + b[3] ** 2)


@njit(cache=True, inline="always", error_model="numpy")
def rigid_clearance(c, y, M, k, tau):
    """Height [m] of end k's lowest point above the original flat in rigid ballistic flight
    from y after tau (undeformed geometry, the elastic part excluded)."""
    iv = 3 + M
    d = c[F.FC_D]
    g = c[F.FC_G]
    Y = y[1] + y[iv + 1] * tau - 0.5 * g * tau * tau
    th = c[F.FC_TH0] + y[2] + y[iv + 2] * tau
    sk = -d if k == 0 else d
    return d * c[F.FC_S0] + Y + sk * math.sin(th)


@njit(cache=True, inline="always", error_model="numpy")
def falling_back(c, y, M, k, since, ring, eps):
    """True when end k, out of contact for ``since`` [s] >= ``ring`` [s], is on the way down
    of a rigid ballistic arc: its rigid clearance (``rigid_clearance``) is above ``eps`` [m]
    and above its value at the separation, and decreases. Its next touch is a return of the
    rod's rigid motion (a new impact), not a re-contact of the ringing, whatever the bound on
    the elastic displacement (docs/flexible.md)."""
    if since < ring:
        return False
    h = rigid_clearance(c, y, M, k, 0.0)
    sk = -c[F.FC_D] if k == 0 else c[F.FC_D]
    rate = y[3 + M + 1] + sk * math.cos(c[F.FC_TH0] + y[2]) * y[3 + M + 2]
    return h > eps and h > rigid_clearance(c, y, M, k, -since) and rate < 0.0


@njit(cache=True, error_model="numpy")
def first_below(c, y, M, k, band, tau_max, eps):
    """First tau in [0, tau_max] where the rigid clearance of end k minus ``band`` may drop to
    <= eps (conservative advancement with the speed bound |v_y - g tau| + |spin| L/2);
    tau_max + 1 if it stays above."""
    iv = 3 + M
    g = c[F.FC_G]
    vy = y[iv + 1]
    w = abs(y[iv + 2]) * c[F.FC_D]
    tau = 0.0
    for _ in range(100000):
        h = rigid_clearance(c, y, M, k, tau) - band
        if h <= eps:
            return tau
        v0 = abs(vy - g * tau) + w
        rhs = 0.9 * (h - 0.5 * eps)  # step dt with dt (v0 + g dt) <= rhs
        if g > 0.0:
            dt = (-v0 + math.sqrt(v0 * v0 + 4.0 * g * rhs)) / (2.0 * g)
        else:
            dt = rhs / v0 if v0 > 0.0 else tau_max + 1.0
        tau += dt
        if tau > tau_max:
            return tau_max + 1.0
    return tau


@njit(cache=True, inline="always", error_model="numpy")
def left_for_good(mdl, y, last_end, stop_mode, cap, eps, flight_min, since, ring):
    """The end-of-sequence test (module docstring), ``since`` [s] after the last separation,
    ``ring`` [s] the period of the lowest mode: (done, next_end, next_time [s])."""
    c, om, Ue, We = mdl[2], mdl[3], mdl[7], mdl[8]
    M = om.shape[0]
    g = c[F.FC_G]
    vy = y[3 + M + 1]
    tau_h = min(2.0 * vy / g if (g > 0.0 and vy > 0.0) else math.inf, cap)
    nxt = -1
    tnx = math.inf
    bands = np.empty(F.NE)
    for k in range(F.NE):
        bands[k] = bounds(om, Ue, We, M, y, k)[0]
    if stop_mode == 0:
        for k in range(F.NE):
            if k == last_end:
                continue
            t1 = first_below(c, y, M, k, bands[k], tau_h, eps)
            if t1 <= tau_h and t1 < tnx:
                tnx = t1
                nxt = k
        if nxt >= 0:
            tau_h = tnx
    for k in range(F.NE):
        if stop_mode == 0 and k != last_end:
            continue
        t_touch = first_below(c, y, M, k, bands[k], tau_h, eps)
        if t_touch <= tau_h:
            if stop_mode == 0 and (
                t_touch >= flight_min or falling_back(c, y, M, k, since, ring, eps)
            ):  # back after a clear flight, or a rigid arc: a new impact
                return True, k, t_touch
            return False, -1, math.inf
    if tau_h == math.inf:
        return False, -1, math.inf
    return True, nxt, tnx


@njit(cache=True, inline="always", error_model="numpy")
def jump_length(mdl, y, ek):
    """A time [s] over which no end can reach the flat: 0.9 of the clearance of each end over
    a bound on its approach speed (0 when an end is at or below the surface)."""
    c, om, Ue, We = mdl[2], mdl[3], mdl[7], mdl[8]
    M = om.shape[0]
    iv = 3 + M
    jump = math.inf
    for k in range(F.NE):
        clear = -ek[k, F.EK_DELTA]  # height of the lowest point above the original surface
        if clear <= 0.0:
            return 0.0
        B, vel = bounds(om, Ue, We, M, y, k)
        v0 = abs(y[iv + 1]) + vel + abs(y[iv + 2]) * (c[F.FC_D] + B)
        rhs = 0.9 * clear
        g = c[F.FC_G]
        if g > 0.0:
            dt = (-v0 + math.sqrt(v0 * v0 + 4.0 * g * rhs)) / (2.0 * g)
        else:
            dt = rhs / v0 if v0 > 0.0 else math.inf
        jump = min(jump, dt)
    return jump
