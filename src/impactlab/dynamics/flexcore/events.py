"""Apply the events of the flexible drop at one instant, including the simultaneous ones
(compiled)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import AT_CELLS, call_cells
from impactlab.dynamics.flexcore.cellswitch import CELL_EVENT, CELL_RESET, CELL_SETTLE, CELL_TOUCH
from impactlab.dynamics.flexcore.contacts import (
    on_friction,
    on_separation,
    on_touch,
    on_turn,
    pending,
)
from impactlab.dynamics.flexcore.friction import mindlin_after
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.kernels._jit import njit_internal

#: The order in which simultaneous events are handled at a restart.
_PENDING_ORDER = (
    F.FEV_SEP,
    F.FEV_TOUCH,
    F.FEV_VN,
    F.FEV_RELOAD,
    F.FEV_SWITCH,
    F.FEV_LIMIT,
    F.FEV_FRIC,
)


@njit(cache=True, inline="always", error_model="numpy")
def _apply(jev, mdl, md, y, t, sv, contacts, dents, cur_con, snap, y_end, der, ev, ek, Jn, Jt):
    """The action of event ``jev`` (an end's, or a partial-slip cell's: ``jev`` >= NEV);
    returns (status, end, kind: -1 for a cell event). Partial slip's cells (a cell event, an
    end's cells at its touch and separation) through their address (``cellswitch.cell_action``):
    a drop without partial slip compiles none of their code."""
    k = jev // F.NFEVK
    kind = jev % F.NFEVK
    st = F.ST_OK
    partial = mdl[2][F.FC_FRIC] == F.FR_PARTIAL
    if jev >= F.NFEV:  # a partial-slip cell: birth, release or stick/slip
        call_cells(mdl[AT_CELLS], np.int64(CELL_EVENT), jev, mdl, md, y, der, ev, ek, Jn, Jt)
        return st, 0, -1
    if kind == F.FEV_LIMIT:
        st = F.ST_LAW_LIMIT
    elif kind == F.FEV_TOUCH:
        st = on_touch(mdl, md, y, t, k, sv, contacts, dents, cur_con, snap, ek, Jn, Jt)
        if partial and st == F.ST_OK:  # the cells reset, the first born (independent of the rest)
            call_cells(mdl[AT_CELLS], np.int64(CELL_TOUCH), k, mdl, md, y, der, ev, ek, Jn, Jt)
    elif kind == F.FEV_VN:
        st = on_turn(mdl, md, k, ek[k, F.EK_DELTA], dents)
    elif kind == F.FEV_RELOAD:
        md[k, F.MD_PH] = 0.0
    elif kind == F.FEV_SWITCH:
        md[k, F.MD_DSW] = math.inf
    elif kind == F.FEV_SEP:
        if partial:  # the cells out of contact first (on_separation keeps the state after it)
            call_cells(mdl[AT_CELLS], np.int64(CELL_RESET), k, mdl, md, y, der, ev, ek, Jn, Jt)
        on_separation(mdl, md, y, t, k, sv, contacts, dents, cur_con, snap, y_end, ek)
    elif kind == F.FEV_FRIC:
        on_friction(mdl, md, y, k, der, ev, ek, Jn, Jt)
    return st, k, kind


@njit_internal
def handle_events(
    jev, mdl, md, y, t, K, gold, sv, sc, contacts, dents, cur_con, snap, y_end, der, ev, ek, Jn, Jt
):
    """Apply event ``jev`` at (t, y) and every event already past its switch at the same
    instant (at most 8), after each (partial slip) every cell switch due
    (``cellswitch.settle``, through ``cell_action``'s address); ``sc``: the error scales (the
    Mindlin state's changes with its meaning). False (with ``sv[F.SV_STATUS]`` set) on a
    failure. Called through its address (``address_call.call_events``): its code is not
    generated again in ``drop``'s library."""
    fric = mdl[2][F.FC_FRIC]
    for _it in range(8):
        st, k, kind = _apply(jev, mdl, md, y, t, sv, contacts, dents, cur_con, snap, y_end, der,
                             ev, ek, Jn, Jt)  # fmt: skip
        if st != F.ST_OK:
            sv[F.SV_STATUS] = st
            return False
        mindlin_after(mdl, md, k, kind, y, ek, sc, sv)
        if fric == F.FR_PARTIAL and not call_cells(
            mdl[AT_CELLS], np.int64(CELL_SETTLE), np.int64(0), mdl, md, y, K[0], gold, ek, Jn, Jt
        ):
            sv[F.SV_STATUS] = F.ST_TOO_MANY_EVENTS
            return False
        evaluate_model(mdl, md, y, K[0], gold, ek, Jn, Jt)
        jev = -1
        for kk in range(F.NE):
            for kind2 in _PENDING_ORDER:
                if jev < 0 and pending(
                    gold, ek, md, kk, kind2, fric, sv[F.SV_TOL_V], sv[F.SV_TOL_D], sv[F.SV_TOL_F]
                ):
                    jev = kk * F.NFEVK + kind2
        if jev < 0:
            break
    return True
