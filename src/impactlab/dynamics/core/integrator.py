"""Embedded Dormand-Prince 5(4) pair with FSAL, Shampine's 4th-order dense output, event
location on the dense output (Illinois regula falsi), and the error-controlled integration over
an exact interval.

Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3;
dense output: Shampine, Math. Comp. 46 (1986) 135, doi:10.1090/S0025-5718-1986-0815836-3.
``dp_step`` is the one step function of the core: the driver's steps and ``integrate_to`` use it.

``dp_step``, ``first_event`` and ``locate`` are compiled without reference counting
(``_nrt=False``; they allocate nothing): inlined into the driver, the array arguments of their
inlined helpers left ~40 atomic reference-count updates per step (gdb count: 1664 per impact),
each a serialising ``lock`` instruction in the stages' dependency chain.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab._floatbits import significand_exponent
from impactlab.dynamics.core._jit import njit_no_refcount
from impactlab.dynamics.core.layout import NEV, NS, S_Q
from impactlab.dynamics.core.rhs import derivative, evaluate, event_value, events_from
from impactlab.dynamics.core.tuples import state_tuple

# --- Dormand-Prince 5(4) tableau (Dormand & Prince 1980) and Shampine's dense output -------------
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = (
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
)
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (
    -71.0 / 57600.0,
    71.0 / 16695.0,
    -71.0 / 1920.0,
    17253.0 / 339200.0,
    -22.0 / 525.0,
    1.0 / 40.0,
)
#: Dormand-Prince stage coefficients: row s holds a_{s,j} (row 6 = the 5th-order weights b_j,
#: so stage 6 is evaluated at the new point: FSAL).
DP_A = np.array(
    [
        [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        [A21, 0.0, 0.0, 0.0, 0.0, 0.0],
        [A31, A32, 0.0, 0.0, 0.0, 0.0],
        [A41, A42, A43, 0.0, 0.0, 0.0],
        [A51, A52, A53, A54, 0.0, 0.0],
        [A61, A62, A63, A64, A65, 0.0],
        [B1, 0.0, B3, B4, B5, B6],
    ]
)
#: Error weights (5th- minus 4th-order weights).
DP_E = np.array([E1, 0.0, E3, E4, E5, E6, E7])
#: Shampine's dense-output polynomial coefficients (theta^1 ... theta^4 per stage).
DENSE_P = np.array(
    [
        [
            1.0,
            -8048581381.0 / 2820520608.0,
            8663915743.0 / 2820520608.0,
            -12715105075.0 / 11282082432.0,
        ],
        [0.0, 0.0, 0.0, 0.0],
        [
            0.0,
            131558114200.0 / 32700410799.0,
            -68118460800.0 / 10900136933.0,
            87487479700.0 / 32700410799.0,
        ],
        [
            0.0,
            -1754552775.0 / 470086768.0,
            14199869525.0 / 1410260304.0,
            -10690763975.0 / 1880347072.0,
        ],
        [
            0.0,
            127303824393.0 / 49829197408.0,
            -318862633887.0 / 49829197408.0,
            701980252875.0 / 199316789632.0,
        ],
        [0.0, -282668133.0 / 205662961.0, 2019193451.0 / 616988883.0, -1453857185.0 / 822651844.0],
        [0.0, 40617522.0 / 29380423.0, -110615467.0 / 29380423.0, 69997945.0 / 29380423.0],
    ]
)


#: m^-0.2 on [0.5, 1) as a cubic in t = 4 m - 3 (Chebyshev interpolant, relative error 1.5e-4).
_G0, _G1, _G2, _G3 = (
    1.0590986723409181,
    -0.0705797147103878,
    0.015114128135519066,
    -0.0037309280809643985,
)
#: 2^(-(e + 1)/5) for the binary exponents e = -65 ... 63 of err = s 2^e, s in [1, 2).
_POW2_FIFTH = np.array([2.0 ** (-0.2 * e) for e in range(-64, 65)])


@njit(cache=True, inline="always", error_model="numpy")
def growth(err):
    """The step-size factor 0.9 err^-0.2 of the controller (err > 0, finite), within 2e-4 and
    without ``pow`` or ``frexp``: err = s 2^e with s in [1, 2) read from the float's bits,
    (s/2)^-0.2 from a cubic, 2^(-(e+1)/5) from a table. The factor is needed before the next
    step can start: ``pow`` (~25 ns) sat in the dependency chain of every step. Beyond the table
    (err < 2^-65 or >= 2^64, subnormals included) it returns 1e30 or 0, which the callers'
    bounds clip."""
    s, e = significand_exponent(err)
    if e < -65:
        return 1e30
    if e > 63:
        return 0.0
    t = 2.0 * s - 3.0
    return 0.9 * (_G0 + t * (_G1 + t * (_G2 + t * _G3))) * _POW2_FIFTH[e + 65]


@njit(cache=True, inline="always", error_model="numpy")
def _stage_point(y, K, h, stage, out):
    """The point ``y + h sum_j a_{stage,j} K[j]`` where stage ``stage`` is evaluated (the
    sums written out with the nonzero coefficients, in the order of the tableau, one loop over
    the components per stage: the compiler unrolls and vectorises them)."""
    if stage == 1:
        for i in range(NS):
            out[i] = y[i] + h * (A21 * K[0, i])
    elif stage == 2:
        for i in range(NS):
            out[i] = y[i] + h * (A31 * K[0, i] + A32 * K[1, i])
    elif stage == 3:
        for i in range(NS):
            out[i] = y[i] + h * (A41 * K[0, i] + A42 * K[1, i] + A43 * K[2, i])
    elif stage == 4:
        for i in range(NS):
            out[i] = y[i] + h * (A51 * K[0, i] + A52 * K[1, i] + A53 * K[2, i] + A54 * K[3, i])
    elif stage == 5:
        for i in range(NS):
            acc = A61 * K[0, i] + A62 * K[1, i] + A63 * K[2, i] + A64 * K[3, i]
            out[i] = y[i] + h * (acc + A65 * K[4, i])
    else:
        for i in range(NS):
            acc = B1 * K[0, i] + B3 * K[2, i] + B4 * K[3, i] + B5 * K[4, i]
            out[i] = y[i] + h * (acc + B6 * K[5, i])


@njit_no_refcount
def dp_step(law, p, fric, c, md, y, K, h, rtol, sc, ynew):
    """One Dormand-Prince step of size ``h`` from ``y``; ``K[0]`` holds the derivative at ``y``.

    Fills the stages ``K[1:7]`` and the 5th-order result ``ynew`` (stage 6 is the new point:
    FSAL) and returns (scaled RMS error norm, event tuple at ``ynew``, evaluated quantities at
    ``ynew``). Error scale of component i: ``rtol (sc[i] + max(|y_i|, |ynew_i|))``.
    """
    # the stages in a loop, so that the force evaluation is compiled once (written out per
    # stage, it made this function the costliest of the engine to compile); stage 6 is the
    # new point, whose evaluated quantities also give the events
    for stage in range(1, 7):
        _stage_point(y, K, h, stage, ynew)
        ys = state_tuple(ynew)
        evq = evaluate(law, p, fric, c, md, ys)
        r = derivative(fric, c, md, ys, evq)
        for i in range(NS):
            K[stage, i] = r[i]
    delta, _a, _b, Fn, Ft, vn, vs, kt = evq
    gnew = events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, ynew[S_Q])
    err = 0.0
    for i in range(NS):
        ei = E1 * K[0, i] + E3 * K[2, i] + E4 * K[3, i] + E5 * K[4, i] + E6 * K[5, i]
        ei += E7 * K[6, i]
        scale = rtol * (sc[i] + max(abs(y[i]), abs(ynew[i])))
        q = h * ei / scale
        err += q * q
    return math.sqrt(err / NS), gnew, evq


@njit(cache=True, inline="always", error_model="numpy")
def dense(y0, K, h, theta, Q, out):
    """Dense output at t0 + theta h (Q = K^T P, computed by ``dense_coeffs``; any state
    length)."""
    t2 = theta * theta
    t3 = t2 * theta
    t4 = t3 * theta
    for i in range(out.shape[0]):
        out[i] = y0[i] + h * (Q[i, 0] * theta + Q[i, 1] * t2 + Q[i, 2] * t3 + Q[i, 3] * t4)


@njit(cache=True, inline="always", error_model="numpy")
def dense_coeffs(K, Q):
    """The dense-output coefficients Q = K^T DENSE_P of the last step (any state length)."""
    for i in range(Q.shape[0]):
        for j in range(4):
            s = 0.0
            for st in range(7):
                s += K[st, i] * DENSE_P[st, j]
            Q[i, j] = s


#: Scratch lengths, per state component, of a step loop (``step_views``) and of a
#: recomputation (``recompute_views``): an impact's scratch is one allocation (driver.impact).
STEP_LEN = 14
RECOMPUTE_LEN = 9
#: |g| at or below this fraction of the bracket's initial |g| is zero to round-off (the event
#: functions are sums of terms of their own scale, evaluated to ~1e-15 of it).
G_ROUNDOFF = 1e-13
#: Closed bracket width in theta (a fraction of the step).
THETA_TOL = 1e-14


@njit(cache=True, inline="always", error_model="numpy")
def past_root(th, f, b, fb):
    """Where to probe just past a root at ``th`` (g(th) = f <= 0, zero to round-off; bracket
    end ``b`` with g = fb > 0): twice the distance to the secant root, at least THETA_TOL."""
    return th + max(THETA_TOL, 2.0 * (-f) * (b - th) / (fb - f))


@njit_no_refcount
def locate(ev, g0, g1, law, p, fric, c, md, y0, K, h, Q, yt):
    """theta in (0, 1] where event ``ev`` fires (g goes from <= 0 to > 0): Illinois method on
    the dense output. Returns the bracket end where g > 0.

    An iterate where g is zero to round-off (``G_ROUNDOFF`` of the initial bracket's scale)
    ends the search: on the g > 0 side it is returned; on the g <= 0 side a probe just past it
    (twice the distance to the secant root, at least ``THETA_TOL``) closes the bracket. The
    Illinois iterates would otherwise creep on from that side, and an exact zero made them
    bisect towards the far end (up to 42 evaluations; CHANGELOG.md, "Performance history")."""
    a = 0.0
    fa = g0
    b = 1.0
    fb = g1
    tiny = G_ROUNDOFF * max(-g0, g1)
    side = 0
    prev = 2.0
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        dense(y0, K, h, th, Q, yt)
        f = event_value(ev, law, p, fric, c, md, state_tuple(yt))
        if abs(f) <= tiny:
            if f > 0.0:  # past the root by round-off
                return th
            # short of it by round-off: probe just past the root (secant slope to b)
            probe = past_root(th, f, b, fb)
            if probe < b:
                dense(y0, K, h, probe, Q, yt)
                fp = event_value(ev, law, p, fric, c, md, state_tuple(yt))
                if fp > 0.0:
                    return probe
                th = probe
                f = fp
        if f > 0.0:
            b = th
            fb = f
            if side == 1:
                fa *= 0.5
            side = 1
        else:
            a = th
            fa = f
            if side == -1:
                fb *= 0.5
            side = -1
        # converged: the bracket is closed, or the iterates stalled on the g > 0 side
        if b - a <= THETA_TOL or (b == th and abs(th - prev) <= THETA_TOL):
            break
        prev = th
    return b


@njit_no_refcount
def first_event(gold, gnew, law, p, fric, c, md, y, K, h, Q, yt, record):
    """(event, theta) of the earliest event in the accepted step from ``y`` (event -1, theta
    2.0: none). Fills the dense-output coefficients ``Q`` when an event fired or ``record``."""
    ev = -1
    theta = 2.0
    fired = False
    for j in range(NEV):
        if gold[j] <= 0.0 and gnew[j] > 0.0:
            fired = True
    if fired or record:
        dense_coeffs(K, Q)
    if fired:
        for j in range(NEV):
            if gold[j] <= 0.0 and gnew[j] > 0.0:
                thj = locate(j, gold[j], gnew[j], law, p, fric, c, md, y, K, h, Q, yt)
                if thj < theta:
                    theta = thj
                    ev = j
    return ev, theta


@njit(cache=True, inline="always", error_model="numpy")
def step_views(buf, n):
    """The work arrays of a step loop over a state of length ``n``, views of ``buf`` (at least
    STEP_LEN n long): (new state, trial state, event state, stages K (7 x n), dense-output
    coefficients Q (n x 4))."""
    K = buf[3 * n : 10 * n].reshape((7, n))
    return buf[:n], buf[n : 2 * n], buf[2 * n : 3 * n], K, buf[10 * n : 14 * n].reshape((n, 4))


@njit(cache=True, inline="always", error_model="numpy")
def recompute_views(buf, y, k0):
    """The work arrays of a recomputation from ``y`` with derivative ``k0`` (any length n),
    views of ``buf`` (at least RECOMPUTE_LEN n long): (stages K (7 x n), current state = y,
    current derivative = k0)."""
    n = y.shape[0]
    cur = buf[7 * n : 8 * n]
    kc = buf[8 * n : 9 * n]
    for i in range(n):
        cur[i] = y[i]
        kc[i] = k0[i]
    return buf[: 7 * n].reshape((7, n)), cur, kc


@njit(cache=True, error_model="numpy")
def integrate_to(law, p, fric, c, md, y, k0, H, rtol, sc, out, work):
    """Integrate from ``y`` over exactly ``H`` with error control (the state at an event is
    recomputed this way, not taken from the 4th-order dense output; near a separation the force
    vanishes like (delta - delta_r)^1.5 and the step size adapts to it); ``work``: RECOMPUTE_LEN
    NS values of scratch. Returns the number of steps taken."""
    Ks, cur, kc = recompute_views(work, y, k0)
    done = 0.0
    hh = H
    n = 0
    while n < 200:
        n += 1
        rem = H - done
        last = hh >= rem * (1.0 - 1e-12)
        if last:
            hh = rem
        for i in range(NS):
            Ks[0, i] = kc[i]
        err, _g, _ev = dp_step(law, p, fric, c, md, cur, Ks, hh, rtol, sc, out)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, growth(err)) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        for i in range(NS):
            cur[i] = out[i]
            kc[i] = Ks[6, i]
        hh *= min(5.0, growth(err)) if err > 0.0 else 5.0
    return n
