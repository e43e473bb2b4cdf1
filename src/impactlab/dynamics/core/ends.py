"""The two ends of the contact in w (``approach.w_integrate``) as the driver runs them: the
opening from first touch (``opening``) and the final approach to separation through the
stick/slip switches it meets (``approach_end``, started where ``near_separation``)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.core.approach import W_EVENT, W_NAN, W_REACHED, w_integrate, w_state
from impactlab.dynamics.core.events import GO_ON, NO_EVENTS, handle_event, on_event
from impactlab.dynamics.core.history import record as record_row
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.layout import (
    C_DLIM,
    C_DSW,
    EV_FRIC,
    EV_SEP,
    EV_SWITCH,
    FR_MINDLIN,
    M_COMP,
    M_DR,
    M_PHASE,
    NS,
)
from impactlab.dynamics.kernels.normal import geometry
from impactlab.dynamics.kernels.rhs import rhs_events_cold
from impactlab.dynamics.kernels.status import ST_NAN
from impactlab.dynamics.kernels.transitions import without_switch
from impactlab.dynamics.kernels.tuples import state_tuple

#: The final approach in w starts when separation is predicted within this many steps.
APPROACH_STEPS = 2.0
#: Stick/slip switches the final approach takes before it hands them to the time integration.
MAX_W_EVENTS = 8
#: The opening in w ends at this fraction of the Hertz interference scale d* (``error_scales``).
OPENING = 0.1
#: First steps of the approach and of the opening, as fractions of their span in w. At 0.5 the
#: approach's first step was rejected in 71 % of 120 random impacts; 0.35 saves 0.47 steps per
#: impact with the same errors (the opening's 0.5 is kept: one step over its whole span cost
#: accuracy, the error estimate being unreliable there).
APPROACH_FIRST = 0.35
OPENING_FIRST = 0.5
#: The opening runs through the switch to the elastic-plastic curve without stopping at it
#: where the switch lies below this fraction of the opening's end (in delta; not with Mindlin
#: friction). Every law's force is continuous there; stopping at the switch cost a w-step and
#: a restart, ~1 us or 18 % of the benchmark impact, for no accuracy: the largest errors of
#: three random samples (400, 1000, 1000 impacts) were unchanged. Mindlin's tangential
#: stiffness follows the contact radius, whose law changes at the switch: there the stop is
#: kept (without it the sample's largest error, a sliding length, doubled).
THROUGH_SWITCH = 0.1


@njit(cache=True, inline="always", error_model="numpy")
def opening(
    law, p, fric, c, md, y, K, gold, rtol, sc, tstar, dstar, fscale, acc, diag, record, hist, nh,
    work,
):  # fmt: skip
    """The start of the contact in w (``w_integrate``) from first touch to OPENING d*, through
    the switch to the elastic-plastic curve where it lies before (stopping at it unless it lies
    below THROUGH_SWITCH of the way). Returns (ST_NAN, a stop
    status, or GO_ON with the derivative at ``y`` in ``K[0]``, t, steps, events, constants,
    mode, event tuple, hist, nh). ``work``: the w-integration's scratch (W_WORK_LEN)."""
    target = min(OPENING * dstar, 0.5 * c[C_DLIM])
    t = 0.0
    n = 0
    nev = 0
    wa = 0.0
    st = W_REACHED
    if c[C_DSW] < target and (fric == FR_MINDLIN or c[C_DSW] >= THROUGH_SWITCH * target):
        wsw = math.sqrt(c[C_DSW])
        st, t, k, hist, nh, evq, _w = w_integrate(
            law, p, fric, c, md, y, t, 0.0, wsw, 1.0, rtol, sc, tstar, acc, diag, record, hist, nh,
            work,
        )  # fmt: skip
        n += k
        if st == W_REACHED:  # the switch at its known interference (the event EV_SWITCH)
            if record:
                hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
            nev += 1
            status, c, md, gold = handle_event(
                np.int64(EV_SWITCH), law, p, fric, c, md, y, evq, acc, K, gold, sc, fscale, dstar
            )
            if status != GO_ON:
                return status, t, n, nev, c, md, gold, hist, nh
            wa = wsw
    if st == W_REACHED:
        wb = math.sqrt(target)
        st, t, k, hist, nh, _q, _w = w_integrate(
            law,
            p,
            fric,
            c,
            md,
            y,
            t,
            wa,
            wb,
            OPENING_FIRST,
            rtol,
            sc,
            tstar,
            acc,
            diag,
            record,
            hist,
            nh,
            work,
        )
        n += k
    if st == W_NAN:
        return ST_NAN, t, n, nev, c, md, gold, hist, nh
    if st == W_REACHED and c[C_DSW] < target:  # through the switch (THROUGH_SWITCH)
        c = without_switch(c)
    r, gold, _q = rhs_events_cold(law, p, fric, c, md, state_tuple(y))
    for i in range(NS):
        K[0, i] = r[i]
    if record and st == W_REACHED and n > 0:
        hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
    return GO_ON, t, n, nev, c, md, gold, hist, nh


@njit(cache=True, inline="always", error_model="numpy")
def near_separation(md, evq, h):
    """True when the contact recedes on the unloading branch and separation is predicted (at
    the present normal velocity) within APPROACH_STEPS steps of size ``h``."""
    if md[M_PHASE] == 0.0 or md[M_COMP] != 0.0:
        return False
    vn = evq[5]
    return vn > 0.0 and evq[0] - md[M_DR] < APPROACH_STEPS * h * vn


@njit_internal
def approach_end(
    law, p, fric, c, md, y, K, t, rtol, sc, tstar, dstar, fscale, acc, diag, record, hist, nh,
    work,
):  # fmt: skip
    """The final approach to separation in w (``w_integrate``) from ``y`` at ``t``, through the
    stick/slip switches it meets. Returns (ST_OK at separation, ST_NAN or another stop status,
    or GO_ON where the time integration takes over again from the last accepted state
    (derivative into ``K[0]``), t, steps, events, constants, mode, hist, nh, event tuple).
    ``work``: the w-integration's scratch (W_WORK_LEN)."""
    delta, _a, _b, _xs, _sl = geometry(c, state_tuple(y))
    wa = math.sqrt(max(delta - md[M_DR], 0.0))
    n = 0
    nev = 0
    while True:
        st, t, k, hist, nh, evq, wa = w_integrate(
            law, p, fric, c, md, y, t, wa, 0.0, APPROACH_FIRST, rtol, sc, tstar, acc, diag,
            record, hist, nh, work,
        )  # fmt: skip
        n += k
        if st != W_EVENT:
            break
        nev += 1
        if nev > MAX_W_EVENTS:  # switches without progress: the time integration decides
            status, c, md, gold = handle_event(
                np.int64(EV_FRIC), law, p, fric, c, md, y, evq, acc, K, NO_EVENTS, sc, fscale, dstar
            )
            return status, t, n, nev, c, md, hist, nh, gold
        if record:
            hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
        for _ in range(3):  # switch; a state found outside its new domain switches at once
            status, c, md = on_event(np.int64(EV_FRIC), law, p, fric, c, md, y, evq, acc)
            if status != GO_ON:
                return status, t, n, nev, c, md, hist, nh, NO_EVENTS
            evq, g = w_state(law, p, fric, c, md, y, wa)
            if not g[EV_FRIC] > 0.0:
                break
    r, gold, evq = rhs_events_cold(law, p, fric, c, md, state_tuple(y))
    if st == W_REACHED:
        if record:
            hist, nh = record_row(hist, nh, t, law, p, fric, c, md, state_tuple(y))
        status, c, md = on_event(np.int64(EV_SEP), law, p, fric, c, md, y, evq, acc)
        return status, t, n, nev + 1, c, md, hist, nh, gold
    if st == W_NAN:
        return ST_NAN, t, n, nev, c, md, hist, nh, gold
    for i in range(NS):
        K[0, i] = r[i]
    return GO_ON, t, n, nev, c, md, hist, nh, gold
