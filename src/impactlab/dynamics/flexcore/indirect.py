"""The addresses of the compiled right-hand side, step, event handler, accepted step, free
flight, outputs and history row, for the model tuple (Python).

numba links the code of every compiled function a function calls into that function's library
and optimises and generates machine code for it again there: ``rhs.rates`` was generated again
in the libraries of the step, the acceptance of a step, the event handler and the drop.
Called through their addresses instead (``address_call``: the model tuple carries them as
int64), ``rates``, ``stepper.dp_step_rates``, ``events.handle_events``, ``steps.accept``,
``coast.out_of_contact``, ``results.fill_outputs`` and ``history.history_row`` are generated
once each (``rates`` twice: the step's stage loop calls it directly, for speed), and a drop without
partial slip never compiles the cells' right-hand side and step (``rhs.rates_cells``,
``stepper.dp_step_cells``). The addresses are read in Python when a drop starts, never baked
into compiled code: the cached engine holds none, and a second process loads every function
from the cache.
"""

from __future__ import annotations

from functools import cache

from impactlab.dynamics.flexcore.address_call import (
    ACCEPT_SIGNATURE,
    AT_CELLS,
    AT_RHS,
    AT_STEP,
    CELLS_SIGNATURE,
    COAST_SIGNATURE,
    EVENTS_SIGNATURE,
    OUTPUTS_SIGNATURE,
    RATES_SIGNATURE,
    RECORD_SIGNATURE,
    STEP_SIGNATURE,
)
from impactlab.dynamics.flexcore.cellswitch import cell_action
from impactlab.dynamics.flexcore.coast import out_of_contact
from impactlab.dynamics.flexcore.events import handle_events
from impactlab.dynamics.flexcore.history import history_row
from impactlab.dynamics.flexcore.results import fill_outputs
from impactlab.dynamics.flexcore.rhs import rates, rates_cells
from impactlab.dynamics.flexcore.stepper import dp_step_cells, dp_step_rates
from impactlab.dynamics.flexcore.steps import accept
from impactlab.dynamics.kernels.address_call import compiled_addresses


@cache
def addresses(partial_slip: bool) -> tuple[int, ...]:
    """The entry points (``address_call.AT_*``) of the right-hand side and of the step
    (``rates_cells`` and ``dp_step_cells`` for partial slip, else ``rates`` and
    ``dp_step_rates``), of the event handler, the accepted step, the free flight, the outputs
    and the history row, and of the cell switches (``cellswitch.cell_action``; 0 without
    partial slip: never called, never compiled): compiled, or loaded from the cache, on first
    use, then kept for the process."""
    functions = [
        (rates_cells if partial_slip else rates, RATES_SIGNATURE),
        (dp_step_cells if partial_slip else dp_step_rates, STEP_SIGNATURE),
        (handle_events, EVENTS_SIGNATURE),
        (accept, ACCEPT_SIGNATURE),
        (out_of_contact, COAST_SIGNATURE),
        (fill_outputs, OUTPUTS_SIGNATURE),
        (history_row, RECORD_SIGNATURE),
    ]
    if partial_slip:
        functions.append((cell_action, CELLS_SIGNATURE))
    found = compiled_addresses(functions)
    return found if partial_slip else (*found, 0)


def batch_addresses(partial_slip: bool) -> tuple[int, int, int]:
    """The right-hand side, step and cell switches of partial slip that a batch's model tuple
    ends with (``batch.drop_batch``; a batch without partial slip: those of the other models,
    never called)."""
    a = addresses(partial_slip)
    return a[AT_RHS - AT_RHS], a[AT_STEP - AT_RHS], a[AT_CELLS - AT_RHS]
