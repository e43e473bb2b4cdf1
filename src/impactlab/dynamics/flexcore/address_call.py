"""Calls of compiled functions through their addresses (compiled; ``indirect`` has the why).

``call_rates(address, *args)``, ``call_step``, ``call_events``, ``call_accept``, ``call_coast``,
``call_outputs``, ``call_record`` and ``call_cells`` call the function at ``address`` (an int64:
the entry point of a compiled ``rhs.rates`` / ``rhs.rates_cells``, ``stepper.dp_step_rates`` /
``stepper.dp_step_cells``, ``events.handle_events``, ``steps.accept``, ``coast.out_of_contact``,
``results.fill_outputs``, ``history.history_row``, ``cellswitch.cell_action``), in numba's own
calling convention, with the arguments that follow the address (``kernels.address_call``):
``call_step(mdl[AT_STEP], mdl, md, y, ...)``. Packed in a tuple instead, every array in the
arguments (the model tuple's too) was counted in and out of the tuple at each call, some 60
atomic reference-count updates per step. The model tuple carries the addresses at the indices
``AT_*``.
"""

from __future__ import annotations

from numba import types

from impactlab.dynamics.kernels.address_call import address_intrinsic

_F1 = types.float64[::1]
_F2 = types.float64[:, ::1]
_F3 = types.float64[:, :, ::1]
_I1 = types.int64[::1]
#: The indices of the addresses in the model tuple: the right-hand side, the step, the event
#: handler, the accepted step, the free flight, the outputs, the history row and the cell
#: switches of partial slip (0, never called, in a drop without partial slip).
AT_RHS, AT_STEP, AT_EVENTS, AT_ACCEPT, AT_COAST, AT_OUTPUTS, AT_RECORD, AT_CELLS = range(13, 21)
#: The number of addresses in the model tuple.
N_ADDRESSES = 8
#: The batch's model tuple (``batch.drop_batch``) ends with partial slip's right-hand side, step
#: and cell switches (``indirect.batch_addresses``).
AT_PARTIAL_RHS, AT_PARTIAL_STEP, AT_PARTIAL_CELLS = range(13 + N_ADDRESSES, 16 + N_ADDRESSES)
#: The model tuple (``model.model_tuple``): the law id, p, c, om, om2, dmp, zeta, Ue, We, Pe,
#: Tg, ia, ib (C-contiguous copies), then the addresses (``AT_*``).
MODEL = types.Tuple(
    (types.int64, _F1, _F1, _F1, _F1, _F1, _F1, _F2, _F2, _F2, _F3, _I1, _I1)
    + (types.int64,) * N_ADDRESSES
)
#: ``rhs.rates`` and ``rhs.rates_cells``: the model's arrays one by one, then md, y, der, ev,
#: ek, Jn, Jt.
RATES_SIGNATURE = types.none(
    types.int64, _F1, _F1, _F1, _F1, _F2, _F2, _F2, _F3, _I1, _I1, _F2, _F1, _F1, _F1, _F2,
    _F2, _F2,
)  # fmt: skip
#: ``stepper.dp_step_rates`` and ``stepper.dp_step_cells``: mdl, md, y, K, h, rtol, sc, st,
#: ynew, ev, ek, Jn, Jt; the error norm.
STEP_SIGNATURE = types.float64(
    MODEL, _F2, _F1, _F2, types.float64, types.float64, _F1, _F1, _F1, _F1, _F2, _F2, _F2
)
#: ``events.handle_events``: jev, mdl, md, y, t, K, gold, sv, sc, contacts, dents, cur_con,
#: snap, y_end, der, ev, ek, Jn, Jt; False on a failure.
EVENTS_SIGNATURE = types.boolean(
    types.int64, MODEL, _F2, _F1, types.float64, _F2, _F1, _F1, _F1, _F2, _F2, _I1, _F2, _F1,
    _F1, _F1, _F2, _F2, _F2,
)  # fmt: skip

#: ``steps.accept``: mdl, md, y, t, h, rtol, sc, K, Q, gold, gnew, ynew, yev, sv, contacts,
#: dents, cur_con, record_on, hist, nh, yt, der, ev, ek, Jn, Jt; (ok, jev, tend, hist, nh).
ACCEPT_SIGNATURE = types.Tuple((types.boolean, types.int64, types.float64, _F2, types.int64))(
    MODEL, _F2, _F1, types.float64, types.float64, types.float64, _F1, _F2, _F2, _F1, _F1, _F1,
    _F1, _F1, _F2, _F2, _I1, types.boolean, _F2, types.int64, _F1, _F1, _F1, _F2, _F2, _F2,
)  # fmt: skip
#: ``coast.out_of_contact``: mdl, y, t, h, sv, stop_mode, yev, ek; (code, tau).
COAST_SIGNATURE = types.Tuple((types.int64, types.float64))(
    MODEL, _F1, types.float64, types.float64, _F1, types.int64, _F1, _F2
)
#: ``results.fill_outputs``: mdl, sv, t, ye, vx0, vy0, out, contacts, dents.
OUTPUTS_SIGNATURE = types.none(
    MODEL, _F1, types.float64, _F1, types.float64, types.float64, _F1, _F2, _F2
)
#: ``history.history_row``: hist, nh, t, mdl, y, ek, e0; (hist, nh).
RECORD_SIGNATURE = types.Tuple((_F2, types.int64))(
    _F2, types.int64, types.float64, MODEL, _F1, _F2, types.float64
)

#: ``cellswitch.cell_action``: action, i, mdl, md, y, der, ev, ek, Jn, Jt; False when the cells
#: do not settle.
CELLS_SIGNATURE = types.boolean(types.int64, types.int64, MODEL, _F2, _F1, _F1, _F1, _F2, _F2, _F2)


#: ``driver.drop`` as ``simulate_drop`` calls it from Python: mdl, vx0, vy0, w0, rtol, t_max,
#: stop_mode, record_on, out, contacts, dents, yfinal; (status, contacts, dents, history,
#: rows). The batch calls it through its address (``batch.drop_address``).
DROP_SIGNATURE = types.Tuple((types.int64, types.int64, types.int64, _F2, types.int64))(
    MODEL, *(types.float64,) * 5, types.int64, types.boolean, _F1, _F2, _F2, _F1
)


#: The intrinsics: compiled code calls them as ``call_rates(address, *args)``.
call_rates = address_intrinsic("call_rates", RATES_SIGNATURE)
call_step = address_intrinsic("call_step", STEP_SIGNATURE)
call_events = address_intrinsic("call_events", EVENTS_SIGNATURE)
call_accept = address_intrinsic("call_accept", ACCEPT_SIGNATURE)
call_coast = address_intrinsic("call_coast", COAST_SIGNATURE)
call_outputs = address_intrinsic("call_outputs", OUTPUTS_SIGNATURE)
call_record = address_intrinsic("call_record", RECORD_SIGNATURE)
call_cells = address_intrinsic("call_cells", CELLS_SIGNATURE)
call_drop = address_intrinsic("call_drop", DROP_SIGNATURE)
