"""Dormand-Prince 5(4) on the partial-slip state array: one step, the dense output, event
location and the error-controlled integration over an exact interval.

The tableau, the stage point, Shampine's dense output and the step-size factor are the shared
kernels' (``impactlab.dynamics.kernels``: Dormand & Prince 1980,
doi:10.1016/0771-050X(80)90013-3; Shampine 1986, doi:10.1090/S0025-5718-1986-0815836-3); the
state here is an array whose length depends on the number of cells, and the dense output is
formed for the entries in use only (the rigid-body state and the cells in contact; for an
event function, the entries it reads). Events are located by ``bracket`` (Anderson-Bjorck
regula falsi with a closing step) to a bracket of EVENT_BRACKET, in one pass over the events
with a sign change in the step (``_first_in``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.kernels._jit import njit_leaf, njit_llvm_inline, njit_no_refcount
from impactlab.dynamics.kernels.cells import SLIP
from impactlab.dynamics.kernels.roots import anderson_bjorck, anderson_bjorck_point
from impactlab.dynamics.kernels.step_control import power_growth
from impactlab.dynamics.slipcore.address_call import call_step
from impactlab.dynamics.slipcore.layout import G_CELL, Y_CELL
from impactlab.dynamics.slipcore.model import (
    evaluate,
    evaluate_rates,
    event_value,
    events_llvm,
    n_in,
)
from impactlab.dynamics.slipcore.sums import (
    dense_coeffs_t,
    dense_entry_t,
    dense_rows_t,
    error_terms,
    stage_sum,
)

#: Closed bracket width of an event's location, in theta (a fraction of the step).
EVENT_BRACKET = 1e-13
#: Events this close (in theta) count as simultaneous: the lowest index is applied first.
SIMULTANEOUS = 1e-10


@njit_llvm_inline
def slip_rhs(law, p, c, md, y, cm, sg, cp, W, dy, nin, limits):
    """Derivative of ``y`` into ``dy`` (``nin`` cells in contact); returns the evaluated
    quantities, and fills ``W`` (its limits W[0] and W[1] only if ``limits``: the event
    functions read them at a step's end, not inside it)."""
    return evaluate_rates(law, p, c, md, y, cm, sg, cp, W, dy, nin, limits)


@njit(cache=True, inline="always", error_model="numpy")
def error_sum(q, cm):
    """(sum of the squared scaled local errors ``q`` (``sums.error_terms``), their count) over
    the rigid-body state and the cells that are not slipping: a slipping cell's force is
    s_i L_i, a function of the normal contact, and its state entry is never read (its error is
    no error of the solution)."""
    err = 0.0
    count = 0
    for i in range(Y_CELL + n_in(cm)):
        if i >= Y_CELL and cm[i - Y_CELL] == SLIP:
            continue
        err += q[i] * q[i]
        count += 1
    return err, count


@njit_leaf
def dp_step_slip(law, p, c, md, y, cm, sg, cp, W, K, h, rtol, sc, ynew, q):
    """One step of size ``h`` from ``y`` (``K[0]``: the derivative at ``y``); fills ``K[1:7]``
    and ``ynew`` (FSAL), and ``q`` with the scaled local errors. Returns (RMS error norm over
    the rigid state and the cells in contact, quantities at ``ynew``); the norm leaves out the
    slipping cells (``error_sum``)."""
    nin = n_in(cm)
    nact = Y_CELL + nin
    for stage in range(1, 7):
        stage_sum(y, K, h, stage, ynew, nact)  # the cells out of contact stay at 0
        # the limits at the last stage only (the step's end, FSAL: its event functions)
        ev = slip_rhs(law, p, c, md, ynew, cm, sg, cp, W, K[stage], nin, stage == 6)
    error_terms(y, ynew, K, h, rtol, sc, q, nact)
    err, count = error_sum(q, cm)
    return math.sqrt(err / count), ev


@njit_llvm_inline
def event_at(k, theta, law, p, c, md, y0, Q, h, cm, sg, cp, yt):
    """Event function ``k`` on the dense output at ``theta`` (``model.event_value``): only the
    entries it reads are interpolated (the rigid-body state and, for a cell's event, that
    cell's force)."""
    t2 = theta * theta
    t3 = t2 * theta
    t4 = t3 * theta
    for i in range(Y_CELL):
        dense_entry_t(y0, h, i, theta, t2, t3, t4, Q, yt)
    if k >= G_CELL:
        dense_entry_t(y0, h, Y_CELL + k - G_CELL, theta, t2, t3, t4, Q, yt)
    return event_value(k, law, p, c, md, yt, cm, sg, cp)


@njit_no_refcount
def locate(k, lo, g0, hi, g1, law, p, c, md, y0, Q, h, cm, sg, cp, yt):
    """theta in (lo, hi] where event ``k`` fires (g(lo) = g0 <= 0 < g(hi) = g1), to a bracket
    of EVENT_BRACKET (``bracket``: regula falsi from the linear estimate with the
    Anderson-Bjorck scaling and a closing step); returns the bracket end where g > 0."""
    a, fa, b, fb = lo, g0, hi, g1
    side = 0  # +1: the g > 0 end moved last, -1: the other end, 0: neither yet
    for _ in range(60):
        th = anderson_bjorck_point(a, fa, b, fb, side, 0.5 * EVENT_BRACKET)
        f = event_at(k, th, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
        a, fa, b, fb, side = anderson_bjorck(a, fa, b, fb, side, th, f)
        if b - a <= EVENT_BRACKET:
            break
    return b


@njit_no_refcount
def _first_in(lo, ga, gb, law, p, c, md, y0, Q, h, cm, sg, cp, yt):
    """(event, theta) of the earliest event with a sign change over [lo, lo + 1/2] (``ga``,
    ``gb``: the event functions at its ends; -1, 2.0: none). One search: the event with the
    earliest linear estimate is located first; every other event with a sign change is then
    evaluated at that root, and located only where it has already fired there (or, for a
    lower index, fires within SIMULTANEOUS after it: simultaneous events go to the lowest
    index, normal events before birth and release before the cells)."""
    # a typed value, not the constant -1: numba types a call first with the constant (before
    # the loop's int64 reaches it) and compiled locate and the event functions for it as well
    best = int(np.int64(-1))
    est = 2.0
    for k in range(ga.shape[0]):
        if ga[k] <= 0.0 and gb[k] > 0.0:
            e = lo + 0.5 * ga[k] / (ga[k] - gb[k])
            if e < est:
                est = e
                best = k
    if best < 0:
        return best, 2.0
    hi = lo + 0.5
    theta = locate(best, lo, ga[best], hi, gb[best], law, p, c, md, y0, Q, h, cm, sg, cp, yt)
    for k in range(ga.shape[0]):
        if k == best or not (ga[k] <= 0.0 and gb[k] > 0.0):
            continue
        f = event_at(k, theta, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
        if f > 0.0:  # fired at or before theta
            th = locate(k, lo, ga[k], theta, f, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
            if th < theta - SIMULTANEOUS or k < best:
                theta, best = th, k
        elif k < best:
            t1 = min(theta + SIMULTANEOUS, hi)
            f1 = event_at(k, t1, law, p, c, md, y0, Q, h, cm, sg, cp, yt) if t1 < hi else gb[k]
            if f1 > 0.0:  # fires within SIMULTANEOUS after theta: the lower index wins
                theta = locate(k, theta, f, t1, f1, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
                best = k
    return best, theta


@njit(cache=True, inline="always", error_model="numpy")
def crosses(ga, gb):
    """True if an event function goes from <= 0 (``ga``) to > 0 (``gb``): a search is due."""
    hits = 0
    for k in range(ga.shape[0]):
        hits += 1 if ga[k] <= 0.0 and gb[k] > 0.0 else 0
    return hits > 0


@njit_leaf
def slip_first_event(gold, gnew, gmid, law, p, c, md, y0, K, Q, h, cm, sg, cp, W, ev, Wm, yt):
    """(event, theta) of the earliest event inside the accepted step (-1, 2.0: none). The
    event functions at the step's end go into ``gnew`` (from ``W`` and ``ev`` there). They
    are also evaluated at the step's midpoint (dense output, into ``gmid``;
    ``Wm``: scratch): one that rises above zero and falls back within a step, a cell that
    sticks for less than a step, is found there. Events within SIMULTANEOUS of the earliest
    count as simultaneous: the lowest index wins (normal events, then birth and release, then
    the cells). Leaves the dense-output coefficients of the active components in ``Q``."""
    events_llvm(c, md, cm, sg, cp, W, ev, gnew)  # at the step's end (``W``, ``ev``: there)
    nact = Y_CELL + n_in(cm)
    dense_coeffs_t(K, Q, nact)
    dense_rows_t(y0, h, 0.5, Q, yt, nact)
    events_llvm(c, md, cm, sg, cp, Wm, evaluate(law, p, c, md, yt, cm, sg, cp, Wm), gmid)
    # the first half, then (if nothing fired there) the second: later events need no location
    best, theta = np.int64(-1), 2.0
    if crosses(gold, gmid):
        best, theta = _first_in(0.0, gold, gmid, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
    if best < 0 and crosses(gmid, gnew):
        best, theta = _first_in(0.5, gmid, gnew, law, p, c, md, y0, Q, h, cm, sg, cp, yt)
    return best, theta


@njit_leaf
def slip_integrate_to(step_at, law, p, c, md, y, cm, sg, cp, W, k0, H, rtol, sc, out, R):
    """Integrate from ``y`` over exactly ``H`` with error control into ``out`` (the state at an
    event is recomputed this way, not taken from the dense output; ``R``: 10 x len(y) scratch),
    in steps of ``dp_step_slip`` called at its address ``step_at`` (``address_call``). Returns (the
    steps taken, the quantities of ``model.evaluate`` at ``out``, ``W`` filled there but for its
    rates W[3]: the last stage of the last step, FSAL). Only the entries in use are copied (the
    rigid-body state and the cells in contact: the others are never read)."""
    nact = Y_CELL + n_in(cm)
    Ks = R[:7]
    cur = R[7]
    kc = R[8]
    q = R[9]
    for i in range(nact):
        cur[i] = y[i]
        kc[i] = k0[i]
    done = 0.0
    hh = H
    steps = 0
    while steps < 200:
        steps += 1
        rem = H - done
        last = hh >= rem * (1.0 - 1e-12)
        if last:
            hh = rem
        for i in range(nact):
            Ks[0, i] = kc[i]
        err, ev = call_step(step_at, law, p, c, md, cur, cm, sg, cp, W, Ks, hh, rtol, sc, out, q)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, power_growth(err)) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        for i in range(nact):
            cur[i] = out[i]
            kc[i] = Ks[6, i]
        hh *= min(5.0, power_growth(err)) if err > 0.0 else 5.0
    return steps, ev
