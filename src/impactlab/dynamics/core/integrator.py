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

from numba import njit

from impactlab.dynamics.kernels._jit import njit_no_refcount
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
    dense_coeffs,
    dense_llvm,
    recompute_views,
)
from impactlab.dynamics.kernels.layout import NEV, NS, S_Q
from impactlab.dynamics.kernels.rhs import derivative, evaluate_stage, event_value, events_from
from impactlab.dynamics.kernels.roots import G_ROUNDOFF, THETA_TOL, illinois, past_root
from impactlab.dynamics.kernels.step_control import growth_llvm
from impactlab.dynamics.kernels.tuples import state_tuple


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
    # new point, whose evaluated quantities also give the events. The force evaluation is
    # inlined by LLVM, not by numba (``kernels._jit.njit_llvm_inline``): numba's type inference
    # of this loop took about three times as long with it inside
    for stage in range(1, 7):
        _stage_point(y, K, h, stage, ynew)
        ys = state_tuple(ynew)
        evq = evaluate_stage(law, p, fric, c, md, ys)
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
        dense_llvm(y0, h, th, Q, yt)
        f = event_value(ev, law, p, fric, c, md, state_tuple(yt))
        if abs(f) <= tiny:
            if f > 0.0:  # past the root by round-off
                return th
            # short of it by round-off: probe just past the root (secant slope to b)
            probe = past_root(th, f, b, fb)
            if probe < b:
                dense_llvm(y0, h, probe, Q, yt)
                fp = event_value(ev, law, p, fric, c, md, state_tuple(yt))
                if fp > 0.0:
                    return probe
                th = probe
                f = fp
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
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
            hh *= max(0.2, growth_llvm(err)) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        for i in range(NS):
            cur[i] = out[i]
            kc[i] = Ks[6, i]
        hh *= min(5.0, growth_llvm(err)) if err > 0.0 else 5.0
    return n
