"""Dormand-Prince 5(4) steps, Shampine's dense output and event location for the flexible
drop (compiled).

The tableau, stage point, error sum, dense-output coefficients, Illinois update, round-off probe
and step-size factor are the shared kernels' (``impactlab.dynamics.kernels``: Dormand & Prince,
J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3; dense output: Shampine,
Math. Comp. 46 (1986) 135, doi:10.1090/S0025-5718-1986-0815836-3); the state length varies
with the number of modes. An event fires when its function goes from <= 0 to > 0; it is located
on the dense output (Illinois regula falsi, with the round-off probe past a root:
``kernels.roots.past_root``) and the state at the event is recomputed by an error-controlled
integration to the located time. The dense output here evaluates the quartic by Horner's rule
(the shared ``kernels.dormand_prince.dense`` by powers of theta: the two differ in the last
bits, and the flexible results were verified with this one).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_RHS, AT_STEP, call_rates, call_step
from impactlab.dynamics.flexcore.cells import n_active
from impactlab.dynamics.flexcore.rhs import rates, rates_cells
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import copy_into
from impactlab.dynamics.kernels.dormand_prince import error_sum, stage_point
from impactlab.dynamics.kernels.roots import G_ROUNDOFF, THETA_TOL, illinois, past_root
from impactlab.dynamics.kernels.step_control import power_growth


@njit(cache=True, error_model="numpy")
def dense(y0, h, theta, Q, out, n):
    """The dense output at y0 + theta h into ``out`` (the quartic in theta by Horner)."""
    for i in range(n):
        poly = Q[i, 0] + theta * (Q[i, 1] + theta * (Q[i, 2] + theta * Q[i, 3]))
        out[i] = y0[i] + h * theta * poly


@njit(cache=True, inline="always", error_model="numpy")
def _error_norm(y, K, h, rtol, sc, st, ynew, md, M):
    """``ynew`` from the last stage point ``st``; the scaled RMS error norm of the step (the
    ends' own works, the state's last entries, left out: their sums are in it)."""
    n = y.shape[0]
    for i in range(n):
        ynew[i] = st[i]
    ne = n - F.N_END_WORKS
    return math.sqrt(error_sum(y, ynew, K, h, rtol, sc, ne) / n_active(md, ne, M))


@njit_internal
def dp_step_rates(mdl, md, y, K, h, rtol, sc, st, ynew, ev, ek, Jn, Jt):
    """One Dormand-Prince step of size h from y (K[0] = f(y)): fills K[1..6], ``ynew`` (5th
    order) and ``ev``/``ek`` at ynew; returns the scaled RMS error norm (error scale of
    component i: rtol (sc[i] + max(|y_i|, |ynew_i|)); partial-slip cells out of contact do
    not count). Every friction model but partial slip (``dp_step_cells``); called through its
    address (``address_call.call_step``), it calls ``rates`` directly (through the address in
    the stage loop, the drop ran 8-10 % slower)."""
    n = y.shape[0]
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl[:13]
    for stage in range(1, 7):
        stage_point(y, K, h, stage, st, n)
        rates(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, st, K[stage], ev, ek, Jn, Jt)
    return _error_norm(y, K, h, rtol, sc, st, ynew, md, om2.shape[0])


@njit_internal
def dp_step_cells(mdl, md, y, K, h, rtol, sc, st, ynew, ev, ek, Jn, Jt):
    """``dp_step_rates`` for partial slip (``rates_cells``)."""
    n = y.shape[0]
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl[:13]
    for stage in range(1, 7):
        stage_point(y, K, h, stage, st, n)
        rates_cells(law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, st, K[stage], ev, ek, Jn, Jt)
    return _error_norm(y, K, h, rtol, sc, st, ynew, md, om2.shape[0])


@njit(cache=True, inline="always", error_model="numpy")
def integrate_to(mdl, md, y, k0, H, rtol, sc, out, ev, ek, Jn, Jt):
    """Integrate from y over exactly H with error control into ``out`` (the state at an
    event); k0 = f(y). Returns the number of steps."""
    Ks = np.empty((7, y.shape[0]))
    st = np.empty(y.shape[0])
    cur = y.copy()
    copy_into(Ks[0], k0)
    done = 0.0
    hh = H
    cnt = 0
    while cnt < 400:
        cnt += 1
        last = hh >= (H - done) * (1.0 - 1e-12)
        if last:
            hh = H - done
        err = call_step(mdl[AT_STEP], mdl, md, cur, Ks, hh, rtol, sc, st, out, ev, ek, Jn, Jt)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, power_growth(err)) if math.isfinite(err) else 0.25
        elif last:
            break
        else:
            done += hh
            copy_into(cur, out)
            copy_into(Ks[0], Ks[6])
            hh *= min(5.0, power_growth(err)) if err > 0.0 else 5.0
    return cnt


@njit(cache=True, inline="always", error_model="numpy")
def locate(jev, g0, g1, mdl, md, y0, h, Q, yt, der, ev, ek, Jn, Jt, shift):
    """theta in (0, 1] where event ``jev`` fires between y0 and y0 + h: the root of
    g - ``shift`` (g the event function; ``shift`` > 0 locates the level a missed touch
    reached, ``steps.first_event``) by Illinois regula falsi on the dense output; g0 <= 0 < g1
    are the values of g - shift at the ends. As the rigid core's ``integrator.locate``: an
    iterate where g - shift is zero to round-off ends the search, on the far side at once, on
    the near side after a probe just past the root (``past_root``)."""
    law, p, c, _om, om2, dmp, _zeta, Ue, We, Pe, Tg, ia, ib = mdl[:13]
    rhs = mdl[AT_RHS]
    a, fa, b, fb, side, prev = 0.0, g0, 1.0, g1, 0, 2.0
    tiny = G_ROUNDOFF * max(-g0, g1)
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        dense(y0, h, th, Q, yt, y0.shape[0])
        call_rates(rhs, law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, yt, der, ev, ek, Jn, Jt)
        f = ev[jev] - shift
        if abs(f) <= tiny:
            if f > 0.0:  # past the root by round-off
                return th
            probe = past_root(th, f, b, fb)  # short of it: probe just past the root
            if probe < b:
                dense(y0, h, probe, Q, yt, y0.shape[0])
                call_rates(
                    rhs, law, p, c, om2, dmp, Ue, We, Pe, Tg, ia, ib, md, yt, der, ev, ek, Jn, Jt
                )
                fp = ev[jev] - shift
                if fp > 0.0:
                    return probe
                th, f = probe, fp
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
        if b - a <= THETA_TOL or abs(th - prev) <= THETA_TOL:
            break
        prev = th
    return b
