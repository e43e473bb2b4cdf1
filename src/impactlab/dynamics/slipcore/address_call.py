"""Calls of the partial-slip engine's step, event search, recomputation at an event, switch
and history through their addresses (compiled; ``kernels.address_call`` has the why).

``call_step(at[SA_STEP], *args)``, ``call_first_event``, ``call_integrate_to``,
``call_switch``, ``call_record`` and ``call_rows`` call ``stepper.dp_step_slip``,
``stepper.slip_first_event``, ``stepper.slip_integrate_to``, ``restart.switch_at_event``,
``outputs.history_row`` and ``outputs.dense_rows`` with the arguments that follow the address.
The impact receives the addresses as the tuple ``at`` (``indirect.addresses``, indices
``SA_*``): each of these functions is generated once, in its own library, instead of again in
every library that calls it (the step in the recomputation's, and all of them in the impact's
and the batch's).
"""

from __future__ import annotations

from numba import types

from impactlab.dynamics.kernels.address_call import address_intrinsic
from impactlab.dynamics.kernels.layout import NC, NM

_F1 = types.float64[::1]
_F2 = types.float64[:, ::1]
_I1 = types.int64[::1]
_F8 = types.float64
_I8 = types.int64
#: The constants and mode tuples (``kernels.layout``: C_*, M_*).
_C = types.UniTuple(_F8, NC)
_MD = types.UniTuple(_F8, NM)
#: The quantities of ``model.evaluate``: (delta, a, b, F_n, F_t, v_n, v_slip, radius,
#: d radius/dt, cells in contact).
EV = types.Tuple((_F8,) * 9 + (_I8,))
#: The indices of the addresses in ``at``: the step, the event search, the recomputation at an
#: event, the switch at an event, a history row and the history rows inside a step.
SA_STEP, SA_FIRST_EVENT, SA_INTEGRATE_TO, SA_SWITCH, SA_RECORD, SA_ROWS = range(6)
#: The number of addresses.
N_SLIP_ADDRESSES = 6
#: The type of ``at``.
ADDRESSES = types.UniTuple(_I8, N_SLIP_ADDRESSES)

#: ``stepper.dp_step_slip``: law, p, c, md, y, cm, sg, cp, W, K, h, rtol, sc, ynew, q;
#: (error norm, ev).
STEP_SIGNATURE = types.Tuple((_F8, EV))(
    _I8, _F1, _C, _MD, _F1, _I1, _F1, _F1, _F2, _F2, _F8, _F8, _F1, _F1, _F1
)
#: ``stepper.slip_first_event``: gold, gnew, gmid, law, p, c, md, y0, K, Q, h, cm, sg, cp, W,
#: ev, Wm, yt; (event, theta).
FIRST_EVENT_SIGNATURE = types.Tuple((_I8, _F8))(
    _F1, _F1, _F1, _I8, _F1, _C, _MD, _F1, _F2, _F2, _F8, _I1, _F1, _F1, _F2, EV, _F2, _F1
)
#: ``stepper.slip_integrate_to``: the step's address, law, p, c, md, y, cm, sg, cp, W, k0, H, rtol,
#: sc, out, R; (steps, ev).
INTEGRATE_TO_SIGNATURE = types.Tuple((_I8, EV))(
    _I8, _I8, _F1, _C, _MD, _F1, _I1, _F1, _F1, _F2, _F1, _F8, _F8, _F1, _F1, _F2
)
#: ``restart.switch_at_event``: k, law, p, c, md, y, cm, sg, cp, W, ev, acc, K, gold; (status or
#: GO_ON, c, md).
SWITCH_SIGNATURE = types.Tuple((_I8, _C, _MD))(
    _I8, _I8, _F1, _C, _MD, _F1, _I1, _F1, _F1, _F2, EV, _F1, _F2, _F1
)
#: ``outputs.history_row``: hist, n, t, law, p, c, md, y, cm, sg, cp, W; (hist, rows).
RECORD_SIGNATURE = types.Tuple((_F2, _I8))(
    _F2, _I8, _F8, _I8, _F1, _C, _MD, _F1, _I1, _F1, _F1, _F2
)
#: ``outputs.dense_rows``: hist, nh, t, h, theta, law, p, c, md, y, cm, sg, cp, W, Q, yt;
#: (hist, rows).
ROWS_SIGNATURE = types.Tuple((_F2, _I8))(
    _F2, _I8, _F8, _F8, _F8, _I8, _F1, _C, _MD, _F1, _I1, _F1, _F1, _F2, _F2, _F1
)


#: The intrinsics: compiled code calls them as ``call_step(address, *args)``.
call_step = address_intrinsic("call_step", STEP_SIGNATURE)
call_first_event = address_intrinsic("call_first_event", FIRST_EVENT_SIGNATURE)
call_integrate_to = address_intrinsic("call_integrate_to", INTEGRATE_TO_SIGNATURE)
call_switch = address_intrinsic("call_switch", SWITCH_SIGNATURE)
call_record = address_intrinsic("call_record", RECORD_SIGNATURE)
call_rows = address_intrinsic("call_rows", ROWS_SIGNATURE)
