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

from collections.abc import Callable
from typing import Any

from numba import types
from numba.extending import intrinsic

from impactlab.dynamics.kernels.address_call import typed_call

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


def _call_rates(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the right-hand side at ``address`` (int64) with ``args``."""
    return typed_call("call_rates", RATES_SIGNATURE, address, args)


def _call_step(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the Dormand-Prince step at ``address`` (int64) with ``args``; returns
    its error norm."""
    return typed_call("call_step", STEP_SIGNATURE, address, args)


def _call_events(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the event handler at ``address`` (int64) with ``args``; returns its
    success."""
    return typed_call("call_events", EVENTS_SIGNATURE, address, args)


def _call_accept(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the accepted step at ``address`` (int64) with ``args``."""
    return typed_call("call_accept", ACCEPT_SIGNATURE, address, args)


def _call_coast(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the free-flight test and jump at ``address`` (int64) with ``args``."""
    return typed_call("call_coast", COAST_SIGNATURE, address, args)


def _call_outputs(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the outputs at ``address`` (int64) with ``args``."""
    return typed_call("call_outputs", OUTPUTS_SIGNATURE, address, args)


def _call_record(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call the history row at ``address`` (int64) with ``args``."""
    return typed_call("call_record", RECORD_SIGNATURE, address, args)


def _call_cells(typingctx: Any, address: Any, *args: Any) -> Any:
    """Call partial slip's cell switches at ``address`` (int64) with ``args``."""
    return typed_call("call_cells", CELLS_SIGNATURE, address, args)


#: The intrinsics (typed for mypy as plain callables: compiled code calls them as
#: ``call_rates(address, *args)``).
call_rates: Callable[..., Any] = intrinsic(_call_rates)
call_step: Callable[..., Any] = intrinsic(_call_step)
call_events: Callable[..., Any] = intrinsic(_call_events)
call_accept: Callable[..., Any] = intrinsic(_call_accept)
call_coast: Callable[..., Any] = intrinsic(_call_coast)
call_outputs: Callable[..., Any] = intrinsic(_call_outputs)
call_record: Callable[..., Any] = intrinsic(_call_record)
call_cells: Callable[..., Any] = intrinsic(_call_cells)
