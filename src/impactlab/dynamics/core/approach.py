"""The two ends of the contact integrated in w = sqrt(delta - delta_0) instead of time.

At both ends of the contact the normal force varies like (delta - delta_0)^1.5: at first touch
(delta_0 = 0, the Hertzian start of every loading curve) and at separation (delta_0 = delta_r,
the Hertzian unloading branch). Its second time derivative is unbounded there: the time steps
must be small, and the Dormand-Prince error estimate is not reliable for a step that ends close
to separation (such a step carried most of the error of the rebound velocity e at loose
tolerances). With w = sqrt(delta - delta_0) as independent variable the force is smooth in w
(4/3 E* sqrt(R) w^3 on a Hertzian curve), and d delta/dt = -v_n (exactly, see
``normal.geometry``) gives dt/dw = 2 w / |v_n|, smooth while |v_n| stays away from 0.

``w_integrate`` integrates the state and the time t from w_a to w_b: the *opening* (from first
touch to a fixed fraction of the Hertz interference scale, with the switch to the
elastic-plastic curve at its known interference in between) and the *final approach* (from
separation predicted within a few steps to w = 0, which *is* the separation: no event location).
The same Dormand-Prince 5(4) pair and error norm as the time integration (``integrator``), with
the time as a ninth component (error scale ``rtol (t* + |t|)``). If any other event fires
inside (the normal velocity turns, stick/slip, the law's limit), the driver goes back to the time
integration from the last accepted state (``W_FALLBACK``).
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.core.accumulate import track
from impactlab.dynamics.core.history import record as record_row
from impactlab.dynamics.kernels._jit import njit_internal, njit_llvm_inline, njit_no_refcount
from impactlab.dynamics.kernels.dormand_prince import (
    A21,
    A31,
    A32,
    A41,
    A42,
    A43,
    A51,
    A52,
    A53,
    A54,
    A61,
    A62,
    A63,
    A64,
    A65,
    B1,
    B3,
    B4,
    B5,
    B6,
    E1,
    E3,
    E4,
    E5,
    E6,
    E7,
    RECOMPUTE_LEN,
    STEP_LEN,
    dense_coeffs,
    dense_llvm,
    recompute_views,
    step_views,
)
from impactlab.dynamics.kernels.layout import (
    EV_FRIC,
    EV_SEP,
    EV_SWITCH,
    FR_COULOMB,
    HISTORY_SUBSTEPS,
    M_DR,
    M_RR,
    NEV,
    NS,
    S_Q,
    S_SPIN,
    S_VX,
    S_VY,
)
from impactlab.dynamics.kernels.rhs import (
    derivative,
    events_cold,
    geometry_llvm,
    normal_force_llvm,
    tangential_force_llvm,
)
from impactlab.dynamics.kernels.roots import G_ROUNDOFF, THETA_TOL, illinois, past_root
from impactlab.dynamics.kernels.step_control import growth_llvm
from impactlab.dynamics.kernels.tuples import state_tuple

#: Components of the approach state: the state ``y`` and the time.
NY = NS + 1
#: Scratch of a w-integration (``w_integrate``): its step loop and a recomputation.
W_WORK_LEN = (STEP_LEN + RECOMPUTE_LEN) * NY
Y_T = NS
#: Outcomes of ``w_integrate``: ``wb`` reached, back to the time integration, non-finite force,
#: a stick/slip switch reached (the final approach: the driver switches and goes on in w).
W_REACHED = 0
W_FALLBACK = 1
W_NAN = 2
W_EVENT = 3
#: Steps the approach may take before it gives up (back to the time integration).
MAX_APPROACH_STEPS = 60
#: Where the last step of the final approach reads its events (fraction of the step).
END_THETA = 0.999
#: Dormand-Prince nodes c_s of stages 1..5 (the right-hand side depends on w here).
_C = (0.0, 0.2, 0.3, 0.8, 8.0 / 9.0, 1.0, 1.0)


@njit(cache=True, inline="always", error_model="numpy")
def _rhs_w(law, p, fric, c, md, Y, w, sgn):
    """(dY/du as a tuple of NY, evaluated quantities) at w; u grows, w = w_a + sgn u.

    sgn = -1: the restitution, delta = delta_r + w^2 on the Hertzian unloading branch
    (F = 4/3 E* sqrt(R_r) w^3), dt/du = 2 w / v_n; sgn = +1: the opening, delta = w^2 on the
    loading curve, dt/du = 2 w / (-v_n)."""
    y = state_tuple(Y)
    _delta, a, b, _xs, _sl = geometry_llvm(c, y)
    w = max(w, 0.0)
    if sgn < 0.0:
        delta = md[M_DR] + w * w
        Fn = 4.0 / 3.0 * p[P_ESTAR] * math.sqrt(md[M_RR]) * (w * w * w)
    else:
        delta = w * w
        Fn = normal_force_llvm(law, p, md, delta)
    spin = y[S_SPIN]
    vn = y[S_VY] - spin * a
    vs = y[S_VX] + spin * b
    Ft, kt = tangential_force_llvm(law, p, fric, c, md, delta, Fn, spin, a, b, y[S_Q])
    evq = (delta, a, b, Fn, Ft, vn, vs, kt)
    d = derivative(fric, c, md, y, evq)
    rate = -sgn * vn
    s = 2.0 * w / rate if rate > 0.0 else math.nan  # dt/du
    return (d[0] * s, d[1] * s, d[2] * s, d[3] * s, d[4] * s, d[5] * s, d[6] * s, d[7] * s, s), evq


@njit_llvm_inline
def _rhs_w_stage(law, p, fric, c, md, Y, w, sgn):
    """``_rhs_w`` for the stage loop of ``_step`` and for ``_rhs_w_cold``: compiled once by
    numba and inlined into both by LLVM (``kernels._jit.njit_llvm_inline``)."""
    return _rhs_w(law, p, fric, c, md, Y, w, sgn)


@njit_no_refcount
def _rhs_w_cold(law, p, fric, c, md, Y, w, sgn):
    """``_rhs_w`` as a call, for the callers off the steps (see ``rhs.rhs_events_cold``):
    ``_rhs_w_stage`` inlined by LLVM, so that numba compiles the body once."""
    return _rhs_w_stage(law, p, fric, c, md, Y, w, sgn)


@njit(cache=True, inline="always", error_model="numpy")
def _point(Y, K, h, stage, out):
    """The stage point ``Y + h sum_j a_{stage,j} K[j]`` (stage 6: the 5th-order result)."""
    for i in range(NY):
        if stage == 1:
            acc = A21 * K[0, i]
        elif stage == 2:
            acc = A31 * K[0, i] + A32 * K[1, i]
        elif stage == 3:
            acc = A41 * K[0, i] + A42 * K[1, i] + A43 * K[2, i]
        elif stage == 4:
            acc = A51 * K[0, i] + A52 * K[1, i] + A53 * K[2, i] + A54 * K[3, i]
        elif stage == 5:
            acc = A61 * K[0, i] + A62 * K[1, i] + A63 * K[2, i] + A64 * K[3, i] + A65 * K[4, i]
        else:
            acc = B1 * K[0, i] + B3 * K[2, i] + B4 * K[3, i] + B5 * K[4, i] + B6 * K[5, i]
        out[i] = Y[i] + h * acc


@njit(cache=True, inline="always", error_model="numpy")
def _put(K, stage, r):
    for i in range(NY):
        K[stage, i] = r[i]


@njit_no_refcount
def _step(law, p, fric, c, md, Y, K, w, sgn, h, rtol, sc, tscale, Yn):
    """One Dormand-Prince step from w to w + sgn h (``K[0]``: dY/du at Y); the result into
    ``Yn``; returns (error norm, quantities at ``Yn``)."""
    # the stages in a loop, so that the force evaluation is compiled once; stage 6 is the new
    # point (its node is 1: w + sgn h)
    for stage in range(1, 7):
        _point(Y, K, h, stage, Yn)
        r, evq = _rhs_w_stage(law, p, fric, c, md, Yn, w + sgn * _C[stage] * h, sgn)
        _put(K, stage, r)
    err = 0.0
    for i in range(NY):
        ei = E1 * K[0, i] + E3 * K[2, i] + E4 * K[3, i] + E5 * K[4, i] + E6 * K[5, i]
        ei += E7 * K[6, i]
        s = tscale if i == Y_T else sc[i]
        q = h * ei / (rtol * (s + max(abs(Y[i]), abs(Yn[i]))))
        err += q * q
    return math.sqrt(err / NY), evq


@njit(cache=True, inline="always", error_model="numpy")
def _fired(gold, gnew):
    """The first event (index) that fires in the step, -1 for none (the switch to the
    elastic-plastic curve, which the opening reaches exactly at ``w_b``, and the separation,
    which is ``w = 0``, are not events here)."""
    for j in range(NEV):
        if j == EV_SWITCH or j == EV_SEP:
            continue
        if gold[j] <= 0.0 < gnew[j]:
            return j
    return -1


@njit_internal
def w_state(law, p, fric, c, md, y, w):
    """(quantities, event tuple) at state ``y`` (length NS) with the interference delta_r + w^2
    of the final approach."""
    _r, evq = _rhs_w_cold(law, p, fric, c, md, y, w, -1.0)
    return evq, events_cold(law, p, fric, c, md, evq, y[S_Q])


@njit_internal
def _g_friction(law, p, fric, c, md, Y, w, sgn):
    """The stick/slip event function at (Y, w)."""
    _r, evq = _rhs_w_cold(law, p, fric, c, md, Y, w, sgn)
    return events_cold(law, p, fric, c, md, evq, Y[S_Q])[EV_FRIC]


@njit(cache=True, error_model="numpy")
def _locate(law, p, fric, c, md, Y, K, w, sgn, h, Q, Yt, g0, b, g1):
    """theta in (0, b] of the step where the stick/slip event fires (g(b) = g1 > 0): Illinois
    method on the dense output (as ``integrator.locate``); returns the bracket end where
    g > 0."""
    a, fa, fb = 0.0, g0, g1
    tiny = G_ROUNDOFF * max(-g0, g1)
    side = 0
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        dense_llvm(Y, h, th, Q, Yt)
        f = _g_friction(law, p, fric, c, md, Yt, w + sgn * th * h, sgn)
        if abs(f) <= tiny:  # zero to round-off: as integrator.locate
            if f > 0.0:
                return th
            probe = past_root(th, f, b, fb)
            if probe < b:
                dense_llvm(Y, h, probe, Q, Yt)
                fp = _g_friction(law, p, fric, c, md, Yt, w + sgn * probe * h, sgn)
                if fp > 0.0:
                    return probe
                th, f = probe, fp
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
        if b - a <= THETA_TOL:
            break
    return b


@njit_internal
def _to(law, p, fric, c, md, Y, k0, w, sgn, H, rtol, sc, tscale, out, work):
    """Integrate from (Y, w) over exactly H in u with error control into ``out`` (the state at
    an event is recomputed, as ``integrator.integrate_to``); returns (steps, quantities)."""
    Ks, cur, kc = recompute_views(work, Y, k0)
    done = 0.0
    hh = H
    n = 0
    _r, evq = _rhs_w_cold(law, p, fric, c, md, Y, w, sgn)
    while n < MAX_APPROACH_STEPS:
        n += 1
        rem = H - done
        last = hh >= rem * (1.0 - 1e-12)
        if last:
            hh = rem
        for i in range(NY):
            Ks[0, i] = kc[i]
        err, evq = _step(
            law, p, fric, c, md, cur, Ks, w + sgn * done, sgn, hh, rtol, sc, tscale, out
        )
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, growth_llvm(err)) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        for i in range(NY):
            cur[i] = out[i]
            kc[i] = Ks[6, i]
        hh *= min(5.0, growth_llvm(err)) if err > 0.0 else 5.0
    return n, evq


@njit_internal
def w_integrate(
    law, p, fric, c, md, y, t, wa, wb, first, rtol, sc, tscale, acc, diag, record, hist, nh, work
):
    """Integrate from state ``y`` at time ``t`` in w from ``wa`` to ``wb``: the restitution to
    separation (``wb < wa``, normally ``wb = 0``) or the opening (``wb > wa``); ``first``: the
    first step as a fraction of the span; ``work``: W_WORK_LEN values of scratch.

    Returns (outcome ``W_*``, time, steps, hist, nh, quantities at the end, w at the end).
    ``y`` is updated in place: the state at ``wb``, at a Coulomb stick/slip switch of the final
    approach (located and recomputed: ``W_EVENT``), or the last accepted state where the
    integration gave up (fallback: another event fired; the time integration takes over)."""
    sgn = 1.0 if wb > wa else -1.0
    span = abs(wb - wa)
    Y, Yn, Yt, K, Q = step_views(work, NY)
    for i in range(NS):
        Y[i] = y[i]
    Y[Y_T] = t
    w = wa
    r, evq = _rhs_w_cold(law, p, fric, c, md, Y, w, sgn)
    _put(K, 0, r)
    if not (span > 0.0 and math.isfinite(r[Y_T])):
        return W_FALLBACK, t, 0, hist, nh, evq, w
    gold = events_cold(law, p, fric, c, md, evq, y[S_Q])
    done = 0.0
    h = first * span
    n = 0
    while n < MAX_APPROACH_STEPS:
        n += 1
        last = h >= (span - done) * (1.0 - 1e-12)
        if last:
            h = span - done
        err, evq_new = _step(law, p, fric, c, md, Y, K, w, sgn, h, rtol, sc, tscale, Yn)
        if not (err <= 1.0):
            if h < 1e-6 * span or (not math.isfinite(err) and h < 1e-3 * span):
                break
            h *= max(0.2, growth_llvm(err)) if math.isfinite(err) else 0.25
            continue
        gnew = events_cold(law, p, fric, c, md, evq_new, Yn[S_Q])
        b = 1.0
        if last and sgn < 0.0:
            # at w = 0 every force vanishes and so does the stick/slip function (0/0 as a
            # ratio): the step's events are read just before, where the forces are ~1e-9 of
            # the step's but their ratio is well defined
            b = END_THETA
            dense_coeffs(K, Q)
            dense_llvm(Y, h, b, Q, Yt)
            _r, evq_b = _rhs_w_cold(law, p, fric, c, md, Yt, w + sgn * b * h, sgn)
            gnew = events_cold(law, p, fric, c, md, evq_b, Yt[S_Q])
        ev = _fired(gold, gnew)
        if ev >= 0 and (ev != EV_FRIC or sgn > 0.0 or fric != FR_COULOMB):
            break  # back to the time integration
        theta = 1.0
        if ev >= 0 or record:
            dense_coeffs(K, Q)
        if ev >= 0:
            theta = _locate(
                law, p, fric, c, md, Y, K, w, sgn, h, Q, Yt, gold[ev], b, gnew[ev]
            )  # fmt: skip
        if record:
            for j in range(1, HISTORY_SUBSTEPS):
                if j / HISTORY_SUBSTEPS >= theta:
                    break
                dense_llvm(Y, h, j / HISTORY_SUBSTEPS, Q, Yt)
                hist, nh = record_row(hist, nh, Yt[Y_T], law, p, fric, c, md, state_tuple(Yt))
        if ev >= 0:  # the stick/slip switch: its state recomputed, then the driver switches
            k, evq_new = _to(
                law, p, fric, c, md, Y, K[0], w, sgn, theta * h, rtol, sc, tscale, Yn,
                work[STEP_LEN * NY :],
            )  # fmt: skip
            n += k
            if not track(acc, law, p, fric, c, md, state_tuple(Yn), evq_new, Y[Y_T], Yn[Y_T], diag):
                return W_NAN, Yn[Y_T], n, hist, nh, evq_new, w
            for i in range(NS):
                y[i] = Yn[i]
            return W_EVENT, Yn[Y_T], n, hist, nh, evq_new, w + sgn * theta * h
        if not track(acc, law, p, fric, c, md, state_tuple(Yn), evq_new, Y[Y_T], Yn[Y_T], diag):
            return W_NAN, Y[Y_T], n, hist, nh, evq_new, w
        evq = evq_new
        for i in range(NY):
            Y[i] = Yn[i]
            K[0, i] = K[6, i]
        for i in range(NS):
            y[i] = Y[i]
        gold = gnew
        if last:
            return W_REACHED, Y[Y_T], n, hist, nh, evq, wb
        done += h
        w = wa + sgn * done
        if record:
            hist, nh = record_row(hist, nh, Y[Y_T], law, p, fric, c, md, state_tuple(Y))
        h *= min(5.0, growth_llvm(err)) if err > 0.0 else 5.0
    return W_FALLBACK, Y[Y_T], n, hist, nh, evq, w
