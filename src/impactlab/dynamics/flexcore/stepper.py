"""Dormand-Prince 5(4) steps, Shampine's dense output and event location for the flexible
drop (compiled).

The tableau is the rigid engine's (``impactlab.dynamics.core.integrator``: Dormand & Prince,
J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3; dense output: Shampine,
Math. Comp. 46 (1986) 135, doi:10.1090/S0025-5718-1986-0815836-3); the state length varies
with the number of modes, so the steps here loop over it. An event fires when its function
goes from <= 0 to > 0; it is located on the dense output (Illinois regula falsi, with the rigid
core's round-off probe past a root: ``core.integrator.past_root``) and the state at the event is
recomputed by an error-controlled integration to the located time.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.core.integrator import (
    DENSE_P,
    DP_A,
    DP_E,
    G_ROUNDOFF,
    THETA_TOL,
    past_root,
)
from impactlab.dynamics.flexcore.cells import n_active
from impactlab.dynamics.flexcore.rhs import rates


@njit(cache=True, error_model="numpy")
def dense_coeffs(K, Q, n):
    """Coefficients Q (n, 4) of the dense-output polynomial: Q = K^T DENSE_P (stage by stage,
    so each entry sums its 7 terms in stage order)."""
    Q[:n, :] = 0.0
    for st in range(7):
        for i in range(n):
            for j in range(4):
                Q[i, j] += K[st, i] * DENSE_P[st, j]


@njit(cache=True, error_model="numpy")
def dense(y0, h, theta, Q, out, n):
    """The dense output at y0 + theta h into ``out`` (the quartic in theta by Horner)."""
    for i in range(n):
        poly = Q[i, 0] + theta * (Q[i, 1] + theta * (Q[i, 2] + theta * Q[i, 3]))
        out[i] = y0[i] + h * theta * poly


@njit(cache=True, error_model="numpy")
def dp_step(mdl, md, y, K, h, rtol, sc, st, ynew, ev, ek, Jn, Jt):
    """One Dormand-Prince step of size h from y (K[0] = f(y)): fills K[1..6], ``ynew`` (5th
    order) and ``ev``/``ek`` at ynew; returns the scaled RMS error norm (error scale of
    component i: rtol (sc[i] + max(|y_i|, |ynew_i|)); partial-slip cells out of contact do
    not count)."""
    n = y.shape[0]
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl
    for stage in range(1, 7):
        for i in range(n):
            acc = 0.0
            for j in range(stage):
                acc += DP_A[stage, j] * K[j, i]
            st[i] = y[i] + h * acc
        rates(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, st, K[stage], ev, ek, Jn, Jt)
    err = 0.0
    for i in range(n):
        e = 0.0
        for j in range(7):
            e += DP_E[j] * K[j, i]
        ynew[i] = st[i]
        q = h * e / (rtol * (sc[i] + max(abs(y[i]), abs(st[i]))))
        err += q * q
    return math.sqrt(err / n_active(md, n, om2.shape[0]))


@njit(cache=True, error_model="numpy")
def integrate_to(mdl, md, y, k0, H, rtol, sc, out, ev, ek, Jn, Jt):
    """Integrate from y over exactly H with error control into ``out`` (the state at an
    event); k0 = f(y). Returns the number of steps."""
    Ks = np.empty((7, y.shape[0]))
    st = np.empty(y.shape[0])
    cur = y.copy()
    Ks[0, :] = k0
    done = 0.0
    hh = H
    cnt = 0
    while cnt < 400:
        cnt += 1
        last = hh >= (H - done) * (1.0 - 1e-12)
        if last:
            hh = H - done
        err = dp_step(mdl, md, cur, Ks, hh, rtol, sc, st, out, ev, ek, Jn, Jt)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, 0.9 * err**-0.2) if math.isfinite(err) else 0.25
        elif last:
            break
        else:
            done += hh
            cur[:] = out
            Ks[0, :] = Ks[6, :]
            hh *= min(5.0, 0.9 * err**-0.2) if err > 0.0 else 5.0
    return cnt


@njit(cache=True, inline="always", error_model="numpy")
def illinois(a, fa, b, fb, side, th, f):
    """One Illinois update of the bracket [a, b] (fa <= 0 < fb) with the value f at th: the
    new (a, fa, b, fb, side), the stale end's value halved when the same side moves twice."""
    if f > 0.0:
        return a, (0.5 * fa if side == 1 else fa), th, f, 1
    return th, f, b, (0.5 * fb if side == -1 else fb), -1


@njit(cache=True, error_model="numpy")
def locate(jev, g0, g1, mdl, md, y0, h, Q, yt, der, ev, ek, Jn, Jt, shift=0.0):
    """theta in (0, 1] where event ``jev`` fires between y0 and y0 + h: the root of
    g - ``shift`` (g the event function; ``shift`` > 0 locates the level a missed touch
    reached, ``steps.first_event``) by Illinois regula falsi on the dense output; g0 <= 0 < g1
    are the values of g - shift at the ends. As the rigid core's ``integrator.locate``: an
    iterate where g - shift is zero to round-off ends the search, on the far side at once, on
    the near side after a probe just past the root (``past_root``)."""
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl
    a, fa, b, fb, side, prev = 0.0, g0, 1.0, g1, 0, 2.0
    tiny = G_ROUNDOFF * max(-g0, g1)
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        dense(y0, h, th, Q, yt, y0.shape[0])
        rates(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, yt, der, ev, ek, Jn, Jt)
        f = ev[jev] - shift
        if abs(f) <= tiny:
            if f > 0.0:  # past the root by round-off
                return th
            probe = past_root(th, f, b, fb)  # short of it: probe just past the root
            if probe < b:
                dense(y0, h, probe, Q, yt, y0.shape[0])
                rates(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, yt, der, ev, ek, Jn, Jt)
                fp = ev[jev] - shift
                if fp > 0.0:
                    return probe
                th, f = probe, fp
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
        if b - a <= THETA_TOL or abs(th - prev) <= THETA_TOL:
            break
        prev = th
    return b
