"""The right-hand side called through its address: the addresses for the model tuple (Python).

numba links the code of every compiled function a function calls into that function's library
and optimises and generates machine code for it again there; ``rhs.rates``, called directly
from the step, the event search and the event loop, was generated again in each of their
libraries. Called through its address instead (``address_call.call_rates``: the model tuple
carries the address, an int64), it is compiled once, and a drop without partial slip never
compiles the cells' right-hand side (``rhs.rates_cells``) at all. The address is read in
Python when a drop starts, never baked into compiled code: the cached engine holds none, and a
second process loads every function from the cache.
"""

from __future__ import annotations

import gc

from numba.experimental.function_type import _get_jit_address

from impactlab.dynamics.flexcore.address_call import (
    EVENTS_SIGNATURE,
    RATES_SIGNATURE,
    STEP_SIGNATURE,
)
from impactlab.dynamics.flexcore.events import handle_events
from impactlab.dynamics.flexcore.rhs import rates, rates_cells
from impactlab.dynamics.flexcore.stepper import dp_step, dp_step_cells

_ADDRESSES: dict[bool, tuple[int, int, int]] = {}


def addresses(partial_slip: bool) -> tuple[int, int, int]:
    """The entry points of the right-hand side and of the step (``rates_cells`` and
    ``dp_step_cells`` for partial slip, else ``rates`` and ``dp_step``) and of the event
    handler: compiled, or loaded from the cache, on first use, then kept for the process."""
    if partial_slip not in _ADDRESSES:
        rhs, step = (rates_cells, dp_step_cells) if partial_slip else (rates, dp_step)
        collecting = gc.isenabled()
        gc.disable()  # the garbage of these compilations waits for the drop's (_compile_gc)
        try:
            _ADDRESSES[partial_slip] = (
                int(_get_jit_address(rhs, RATES_SIGNATURE)),
                int(_get_jit_address(step, STEP_SIGNATURE)),
                int(_get_jit_address(handle_events, EVENTS_SIGNATURE)),
            )
        finally:
            if collecting:
                gc.enable()
    return _ADDRESSES[partial_slip]
