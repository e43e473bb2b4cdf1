"""The partial-slip engine at an event: stop, or switch and restart.

``switch_at_event`` applies the event located in a step (a normal event of the core's rules, or a
cell's birth, release or stick/slip switch), settles every switch already due, and restarts
the step loop at the event's state (derivative and event functions there); ``normal_event``
keeps the bookkeeping of the normal work of compression and restitution.
"""

from __future__ import annotations

import numpy as np

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.kernels._jit import njit_internal, njit_leaf
from impactlab.dynamics.kernels.layout import (
    A_WCOMP,
    A_WMARK,
    A_WREST,
    C_MU,
    EV_LIMIT,
    EV_SEP,
    EV_SWITCH,
    EV_VN,
    M_COMP,
    S_WORK,
)
from impactlab.dynamics.kernels.status import ST_LAW_LIMIT, ST_OK, ST_TOO_MANY_EVENTS
from impactlab.dynamics.kernels.transitions import without_switch
from impactlab.dynamics.slipcore.model import derivative, events
from impactlab.dynamics.slipcore.outputs import A_JUMP
from impactlab.dynamics.slipcore.switches import apply_cell_event, normal_switch, settle

#: The status of a switch after which the step loop goes on.
GO_ON = -1


@njit_internal
def normal_event(k, law, p, c, md, y, ev, acc):
    """(status or GO_ON, constants, mode) after the normal event ``k``, with the bookkeeping of
    the normal work of compression and restitution."""
    if k == EV_SEP:
        acc[A_WREST] += y[S_WORK] - acc[A_WMARK]
        return ST_OK, c, md
    if k == EV_LIMIT:
        return ST_LAW_LIMIT, c, md
    if k == EV_SWITCH:
        return GO_ON, without_switch(c), md
    if k == EV_VN:
        if md[M_COMP] != 0.0:
            acc[A_WCOMP] += y[S_WORK] - acc[A_WMARK]
        else:
            acc[A_WREST] += y[S_WORK] - acc[A_WMARK]
        acc[A_WMARK] = y[S_WORK]
    st, md = normal_switch(k, law, p, md, ev[0])
    return (GO_ON if st == ST_OK else st), c, md


@njit_leaf
def switch_at_event(k, law, p, c, md, y, cm, sg, cp, W, ev, acc, K, gold):
    """Stop at the event ``k`` or switch and restart at ``y`` (its quantities ``ev``, ``W``
    filled there; derivative into ``K[0]``, event functions into ``gold``). Returns (status or
    GO_ON, constants, mode)."""
    ft_before = ev[4]
    if k <= EV_SWITCH:
        st, c, md = normal_event(k, law, p, c, md, y, ev, acc)
        if st != GO_ON:
            return st, c, md
    else:
        apply_cell_event(k, y, cm, sg, cp, c[C_MU], p[P_ESTAR], W, ev)
    settled, ev = settle(law, p, c, md, y, cm, sg, cp, W, c[C_MU])
    if not settled:
        return ST_TOO_MANY_EVENTS, c, md
    derivative(c, y, W, ev, K[0])  # rhs at y: ev and W are those at y
    acc[A_JUMP] = max(acc[A_JUMP], abs(ev[4] - ft_before))
    events(c, md, cm, sg, cp, W, ev, gold)
    if gold[EV_SEP] > 0.0:  # a switch located at the separation itself: that is the end
        return normal_event(np.int64(EV_SEP), law, p, c, md, y, ev, acc)
    return GO_ON, c, md
