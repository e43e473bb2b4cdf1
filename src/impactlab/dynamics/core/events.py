"""What the driver does at an event: the normal-work bookkeeping, the mode switch and the
restart of the integration (``handle_event``), shared by the time integration (``driver``) and
the w-integrated ends of the contact (``ends``)."""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.dynamics.core.accumulate import A_EEL, stored
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.layout import (
    A_WCOMP,
    A_WMARK,
    A_WREST,
    EV_LIMIT,
    EV_SEP,
    EV_SWITCH,
    EV_VN,
    FR_MINDLIN,
    M_COMP,
    S_Q,
    S_WORK,
)
from impactlab.dynamics.kernels.status import ST_LAW_LIMIT, ST_OK
from impactlab.dynamics.kernels.transitions import restart, switch_mode, without_switch

GO_ON = -1  # internal status: the impact goes on
NO_EVENTS = (-1.0, -1.0, -1.0, -1.0, -1.0, -1.0)  # an event tuple where none can fire


@njit_internal
def on_event(ev, law, p, fric, c, md, y, evq, acc):
    """Stop at the event ``ev`` (separation: ST_OK, law limit, failure) or switch: normal-work
    bookkeeping and mode transition. Returns (status or GO_ON, constants, mode)."""
    if ev == EV_SEP:
        acc[A_WREST] += acc[A_EEL]  # all of it released: F_n = 0 at delta_r
        return ST_OK, c, md
    if ev == EV_LIMIT:
        return ST_LAW_LIMIT, c, md
    if ev == EV_SWITCH:
        c = without_switch(c)
    compressing = md[M_COMP] != 0.0
    if ev == EV_VN:
        if compressing:
            acc[A_WCOMP] += y[S_WORK] - acc[A_WMARK]
        else:
            acc[A_WREST] += acc[A_EEL] - stored(evq, md)
        acc[A_WMARK] = y[S_WORK]
    st, md = switch_mode(ev, law, p, fric, c, md, y, evq)
    if ev == EV_VN and compressing:
        acc[A_EEL] = stored(evq, md)
    return (GO_ON if st == ST_OK else st), c, md


@njit(cache=True, error_model="numpy")
def handle_event(ev, law, p, fric, c, md, y, evq, acc, K, gold, sc, fscale, dstar):
    """Stop at the event ``ev`` or switch and restart the integration at ``y`` (derivative
    into ``K[0]``, error scale of the Mindlin state). Returns (status or GO_ON, constants,
    mode, event tuple). A switch located at the separation itself (a stick that breaks as F_n
    vanishes, with both events within round-off) can leave the restart state just past it
    (delta < delta_r while receding, where no crossing would ever be seen): that is the
    separation, at this instant."""
    st, c, md = on_event(ev, law, p, fric, c, md, y, evq, acc)
    if st != GO_ON:
        return st, c, md, gold
    if fric == FR_MINDLIN:
        sc[S_Q] = fscale if md[M_COMP] != 0.0 else dstar
    md, gold = restart(law, p, fric, c, md, y, K)
    if gold[EV_SEP] > 0.0:
        st, c, md = on_event(np.int64(EV_SEP), law, p, fric, c, md, y, evq, acc)
    return st, c, md, gold
