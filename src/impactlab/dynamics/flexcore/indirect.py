"""The addresses of the compiled right-hand side, step and event handler, for the model tuple
(Python).

numba links the code of every compiled function a function calls into that function's library
and optimises and generates machine code for it again there: ``rhs.rates`` was generated again
in the libraries of the step, the acceptance of a step, the event handler and the drop.
Called through their addresses instead (``address_call``: the model tuple carries them as
int64), ``rates``, ``stepper.dp_step`` and ``events.handle_events`` are generated once each
(``rates`` twice: the step's stage loop calls it directly, for speed), and a drop without
partial slip never compiles the cells' right-hand side and step (``rhs.rates_cells``,
``stepper.dp_step_cells``). The addresses are read in Python when a drop starts, never baked
into compiled code: the cached engine holds none, and a second process loads every function
from the cache.
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
