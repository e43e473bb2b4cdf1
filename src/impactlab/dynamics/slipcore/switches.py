"""Mode changes of the partial-slip engine at events: birth and release of cells, stick/slip
switches of a cell (the cell kernels of ``kernels.cells``), the normal-contact transitions
(``kernels.transitions``), and the settle pass that applies every switch already due at a
restart.

Rules (docs/verification/index.md, "Partial slip"): a cell is born unstressed when the contact
radius reaches it, in SLIP (towards v_slip) when the stick trial outruns its growing limit, else
in STICK; it is released at zero force; a cell slips when |f| reaches its limit (f is clamped to
it) and sticks again when the limit outruns the stick trial. F_t is continuous at every switch.
"""

from __future__ import annotations

import numpy as np

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.cells import (
    CP_DX,
    SLIP,
    STICK,
    apply_due,
    birth,
    n_in,
    release,
    to_slip,
    to_stick,
)
from impactlab.dynamics.kernels.layout import EV_RELOAD, EV_VN, FR_MINDLIN, M_COMP, M_PHASE
from impactlab.dynamics.kernels.status import ST_OK
from impactlab.dynamics.kernels.transitions import unloading_branch
from impactlab.dynamics.kernels.tuples import mode_with
from impactlab.dynamics.slipcore.layout import G_BIRTH, G_CELL, G_REL, Y_CELL
from impactlab.dynamics.slipcore.model import evaluate


@njit_internal
def apply_cell_event(k, y, cm, sg, cp, mu, estar, W, ev):
    """The switch of the cell event ``k`` (birth, release or a cell's stick/slip)."""
    _delta, _a, _b, Fn, _Ft, vn, vs, ar, ad, nin = ev
    o = np.int64(Y_CELL)  # a value, not a constant: the flexible rod's compile of the cells
    if k == G_BIRTH:
        birth(nin, y, o, cm, sg, cp, mu, estar, Fn, vn, vs, ar, ad)
    elif k == G_REL:
        release(y, o, cm, nin)
    else:
        i = k - G_CELL
        if cm[i] == STICK:
            to_slip(i, y, o, cm, sg, W[0])
        elif cm[i] == SLIP:
            to_stick(i, y, o, cm, sg, W[0])


@njit_internal
def release_passed(y, cm, cp, ar, dy):
    """Release the outermost cell if it slips and the contact radius ``ar`` [m] has receded to
    its inner end: its force s_i L_i fell to zero there continuously (L_i ~ l^2) and stays zero,
    so the step ran through the release exactly and no event is needed (a sticking edge cell,
    force ~ l, is released at a located event). Zeroes its entry of the derivative ``dy``;
    True if it released."""
    nin = n_in(cm)
    if nin > 1 and cm[nin - 1] == SLIP and ar <= (nin - 1) * cp[CP_DX]:
        release(y, np.int64(Y_CELL), cm, nin)
        dy[Y_CELL + nin - 1] = 0.0
        return True
    return False


@njit_internal
def settle(law, p, c, md, y, cm, sg, cp, W, mu):
    """Apply every switch that is already due at a restart (several cells can change mode
    within one step; only the first event is located: ``kernels.cells.apply_due``, one at a
    time, each on the quantities evaluated anew). Returns (False if it does not settle, the
    quantities of ``model.evaluate`` at the settled state, ``W`` filled there)."""
    estar = p[P_ESTAR]
    ev = evaluate(law, p, c, md, y, cm, sg, cp, W)
    for _ in range(4 * cm.shape[0] + 8):
        _delta, _a, _b, Fn, _Ft, vn, vs, ar, ad, _nin = ev
        o = np.int64(Y_CELL)
        if not apply_due(y, o, cm, sg, cp, W[0], W[1], W[2], mu, estar, Fn, vn, vs, ar, ad):
            return True, ev
        ev = evaluate(law, p, c, md, y, cm, sg, cp, W)
    return False, ev


@njit_internal
def normal_switch(k, law, p, md, delta):
    """(status, mode) after the normal event ``k`` (EV_VN or EV_RELOAD): the core's rules,
    with the contact-radius factor that keeps a(t) continuous at the turning point."""
    if k == EV_VN:
        if md[M_COMP] != 0.0:
            if md[M_PHASE] == 0.0:
                status, md = unloading_branch(law, p, np.int64(FR_MINDLIN), md, delta)
                if status != ST_OK:
                    return status, md
            return ST_OK, mode_with(md, M_COMP, 0.0)
        return ST_OK, mode_with(md, M_COMP, 1.0)
    if k == EV_RELOAD:
        return ST_OK, mode_with(md, M_PHASE, 0.0)
    return ST_OK, md
