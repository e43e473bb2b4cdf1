"""Dormand-Prince 5(4) on the partial-slip state array: one step, the dense output, event
location and the error-controlled integration over an exact interval.

The tableau, the stage point, the error sum, Shampine's dense output, the Illinois update and
the step-size factor are the shared kernels' (``impactlab.dynamics.kernels``: Dormand & Prince
1980, doi:10.1016/0771-050X(80)90013-3; Shampine 1986, doi:10.1090/S0025-5718-1986-0815836-3);
the state here is an array whose length depends on the number of cells. The event search
stops at a bracket of 1e-13 without the round-off probe of the other engines (the partial-slip
results were verified with it; the probe moves event times by up to the bracket width).
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.buffers import copy_into
from impactlab.dynamics.kernels.cells import SLIP
from impactlab.dynamics.kernels.dormand_prince import DP_E, dense, dense_coeffs, stage_point
from impactlab.dynamics.kernels.roots import illinois
from impactlab.dynamics.kernels.step_control import power_growth
from impactlab.dynamics.slipcore.layout import Y_CELL
from impactlab.dynamics.slipcore.model import derivative, evaluate, event_value, events, n_in


@njit(cache=True, error_model="numpy")
def rhs(law, p, c, md, y, cm, sg, cp, W, dy):
    """Derivative of ``y`` into ``dy``; returns the evaluated quantities."""
    ev = evaluate(law, p, c, md, y, cm, sg, cp, W)
    derivative(c, y, cm, sg, cp, W, ev, dy)
    return ev


@njit(cache=True, inline="always", error_model="numpy")
def error_sum(y, ynew, K, h, rtol, sc, cm):
    """(sum of the squared scaled local errors, their count) over the rigid-body state and the
    cells that are not slipping: a slipping cell's force is s_i L_i, a function of the normal
    contact, and its state entry is never read (its error is no error of the solution). Error
    scale of component i: rtol (sc[i] + max(|y_i|, |ynew_i|))."""
    err = 0.0
    count = 0
    for i in range(Y_CELL + n_in(cm)):
        if i >= Y_CELL and cm[i - Y_CELL] == SLIP:
            continue
        ei = 0.0
        for j in range(7):
            ei += DP_E[j] * K[j, i]
        q = h * ei / (rtol * (sc[i] + max(abs(y[i]), abs(ynew[i]))))
        err += q * q
        count += 1
    return err, count


@njit(cache=True, error_model="numpy")
def step(law, p, c, md, y, cm, sg, cp, W, K, h, rtol, sc, ynew):
    """One step of size ``h`` from ``y`` (``K[0]``: the derivative at ``y``); fills ``K[1:7]``
    and ``ynew`` (FSAL). Returns (RMS error norm over the rigid state and the cells in contact,
    quantities at ``ynew``); the norm leaves out the slipping cells (``error_sum``)."""
    nact = Y_CELL + n_in(cm)
    for stage in range(1, 6):
        stage_point(y, K, h, stage, ynew, nact)  # the cells out of contact stay at 0
        rhs(law, p, c, md, ynew, cm, sg, cp, W, K[stage])
    stage_point(y, K, h, 6, ynew, nact)
    ev = rhs(law, p, c, md, ynew, cm, sg, cp, W, K[6])
    err, count = error_sum(y, ynew, K, h, rtol, sc, cm)
    return math.sqrt(err / count), ev


@njit_internal
def event_at(k, law, p, c, md, y, cm, sg, cp, W, g):
    """Event function ``k`` at state ``y`` (``model.event_value``: that function alone, the
    value ``events`` gives it; ``W`` and ``g`` are left as they are)."""
    return event_value(k, law, p, c, md, y, cm, sg, cp)


@njit(cache=True, error_model="numpy")
def locate(k, lo, g0, hi, g1, law, p, c, md, y0, Q, h, cm, sg, cp, W, g, yt):
    """theta in (lo, hi] where event ``k`` fires (g(lo) = g0 <= 0 < g(hi) = g1): Illinois regula
    falsi on the dense output; returns the bracket end where g > 0."""
    a, fa, b, fb = lo, g0, hi, g1
    side = 0
    for _ in range(60):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        dense(y0, h, th, Q, yt)
        f = event_at(k, law, p, c, md, yt, cm, sg, cp, W, g)
        a, fa, b, fb, side = illinois(a, fa, b, fb, side, th, f)
        if b - a <= 1e-13:
            break
    return b


@njit(cache=True, error_model="numpy")
def first_event(gold, gnew, gmid, law, p, c, md, y0, K, Q, h, cm, sg, cp, Wm, yt):
    """(event, theta) of the earliest event inside the accepted step (-1, 2.0: none). The
    event functions are also evaluated at the step's midpoint (dense output, into ``gmid``;
    ``Wm``: scratch): one that rises above zero and falls back within a step, a cell that
    sticks for less than a step, is found there. Events within 1e-10 of the earliest count as
    simultaneous: the lowest index wins (normal events, then birth and release, then the
    cells). Leaves the dense-output coefficients in ``Q``."""
    dense_coeffs(K, Q)
    dense(y0, h, 0.5, Q, yt)
    events(c, md, cm, sg, cp, Wm, evaluate(law, p, c, md, yt, cm, sg, cp, Wm), gmid)
    best = -1
    theta = 2.0
    # the first half, then (if nothing fired there) the second: later events need no location
    for half in range(2):
        lo = 0.5 * half
        ga = gold if half == 0 else gmid
        gb = gmid if half == 0 else gnew
        for k in range(gold.shape[0]):
            if ga[k] <= 0.0 and gb[k] > 0.0:
                th = locate(
                    k, lo, ga[k], lo + 0.5, gb[k], law, p, c, md, y0, Q, h, cm, sg, cp, Wm, gmid, yt
                )
                if th < theta - 1e-10:
                    theta = th
                    best = k
        if best >= 0:
            break
    return best, theta


@njit(cache=True, error_model="numpy")
def integrate_to(law, p, c, md, y, cm, sg, cp, W, k0, H, rtol, sc, out, R):
    """Integrate from ``y`` over exactly ``H`` with error control into ``out`` (the state at an
    event is recomputed this way, not taken from the dense output; ``R``: 9 x len(y) scratch).
    Returns the steps taken."""
    Ks = R[:7]
    cur = R[7]
    kc = R[8]
    copy_into(cur, y)
    copy_into(kc, k0)
    done = 0.0
    hh = H
    steps = 0
    while steps < 200:
        steps += 1
        rem = H - done
        last = hh >= rem * (1.0 - 1e-12)
        if last:
            hh = rem
        copy_into(Ks[0], kc)
        err, _ev = step(law, p, c, md, cur, cm, sg, cp, W, Ks, hh, rtol, sc, out)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, power_growth(err)) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        copy_into(cur, out)
        copy_into(kc, Ks[6])
        hh *= min(5.0, power_growth(err)) if err > 0.0 else 5.0
    return steps
