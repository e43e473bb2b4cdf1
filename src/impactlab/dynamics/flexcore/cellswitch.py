"""Mode changes of the partial-slip cells at the ends of the flexible rod (compiled): the cell
events (birth, release, stick/slip), the settle pass that applies every switch already due at a
restart, and the cells at a touch. The rules and the cell kernels are the shared ones
(``kernels.cells``; docs/verification/index.md, "Partial slip"): a cell is born unstressed
when the contact radius reaches it, slipping when the stick trial outruns its growing limit; it
is released at zero force; it slips when |f| reaches its limit and sticks again when the limit
outruns the trial.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.cells import reset, views
from impactlab.dynamics.flexcore.rhs import evaluate_model
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.cells import (
    SLIP,
    STICK,
    apply_due,
    birth,
    n_in,
    release,
    to_slip,
    to_stick,
)


@njit(cache=True, inline="always", error_model="numpy")
def cell_offset(mdl, k):
    """Index of end k's first cell force in the state."""
    return 6 + 2 * mdl[3].shape[0] + F.NQUAD + k * F.NCS


@njit(cache=True, inline="always", error_model="numpy")
def _due(mdl, md, k, y, ek):
    """Apply end k's first birth or release already due, else every due stick/slip switch;
    False when none is."""
    c = mdl[2]
    o = cell_offset(mdl, k)
    cm, sg, cp, L, Ld, f = views(c, md, ek, k)
    fn, vn, vs = ek[k, F.EK_FN], ek[k, F.EK_VN], ek[k, F.EK_VT]
    ar, ad = ek[k, F.EK_A], ek[k, F.EK_AD]
    return apply_due(y, o, cm, sg, cp, L, Ld, f, c[F.FC_MU], mdl[1][P_ESTAR], fn, vn, vs, ar, ad)


@njit(cache=True, inline="always", error_model="numpy")
def settle(mdl, md, y, der, ev, ek, Jn, Jt):
    """Apply every cell switch already due at y (several cells can change within one step;
    only the first event is located). False if it does not settle."""
    for _ in range(4 * F.NCS + 8):
        evaluate_model(mdl, md, y, der, ev, ek, Jn, Jt)
        changed = False
        for k in range(F.NE):
            if not changed and md[k, F.MD_IN] != 0.0:
                changed = _due(mdl, md, k, y, ek)
        if not changed:
            return True
    return False


@njit(cache=True, inline="always", error_model="numpy")
def apply_cell_event(jev, mdl, md, y, ek):
    """The switch of the cell event ``jev`` (>= NEV: birth, release or a cell's stick/slip)."""
    c = mdl[2]
    k = (jev - F.NFEV) // F.NFEVC
    kind = (jev - F.NFEV) % F.NFEVC
    o = cell_offset(mdl, k)
    cm, sg, cp, L, _Ld, _f = views(c, md, ek, k)
    nin = n_in(cm)
    if kind == F.FG_BIRTH:
        if nin < F.NCS:
            fn, vn, vs = ek[k, F.EK_FN], ek[k, F.EK_VN], ek[k, F.EK_VT]
            ar, ad = ek[k, F.EK_A], ek[k, F.EK_AD]
            birth(nin, y, o, cm, sg, cp, c[F.FC_MU], mdl[1][P_ESTAR], fn, vn, vs, ar, ad)
    elif kind == F.FG_REL:
        if nin > 1:
            release(y, o, cm, nin)
    else:
        i = kind - F.FG_CELL
        if cm[i] == STICK:
            to_slip(i, y, o, cm, sg, L)
        elif cm[i] == SLIP:
            to_stick(i, y, o, cm, sg, L)


@njit_internal
def touch_cells(mdl, md, k, y, ek):
    """End k touches: its cells reset, the first born at a = 0 (``ek``: before the touch)."""
    c = mdl[2]
    o = cell_offset(mdl, k)
    reset(md, k, y, o)
    if not c[F.FC_MU] > 0.0:
        return
    cm, sg, cp, _L, _Ld, _f = views(c, md, ek, k)
    vn, vs = ek[k, F.EK_VN], ek[k, F.EK_VT]
    birth(np.int64(0), y, o, cm, sg, cp, c[F.FC_MU], mdl[1][P_ESTAR], 0.0, vn, vs, 0.0, 0.0)


#: The actions of ``cell_action``: a cell event, the switches due, an end's touch, its separation.
CELL_EVENT, CELL_SETTLE, CELL_TOUCH, CELL_RESET = 0, 1, 2, 3


@njit_internal
def cell_action(action, i, mdl, md, y, der, ev, ek, Jn, Jt):
    """Partial slip's cell switches, called through their address (``address_call.call_cells``)
    by a partial-slip drop only (another drop compiles none of them): the cell event ``i``
    (``CELL_EVENT``, ``apply_cell_event``), every switch already due (``CELL_SETTLE``,
    ``settle``: False when it does not settle), end i's cells at its touch (``CELL_TOUCH``,
    ``touch_cells``) or at its separation (``CELL_RESET``: out of contact, unstressed)."""
    if action == CELL_EVENT:
        apply_cell_event(i, mdl, md, y, ek)
    elif action == CELL_SETTLE:
        return settle(mdl, md, y, der, ev, ek, Jn, Jt)
    elif action == CELL_TOUCH:
        touch_cells(mdl, md, i, y, ek)
    else:
        reset(md, i, y, cell_offset(mdl, i))
    return True
