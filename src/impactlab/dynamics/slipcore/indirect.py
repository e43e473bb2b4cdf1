"""The addresses of the partial-slip engine's step, event search, recomputation at an event,
switch and history (``address_call``), for ``impact_slip``'s argument ``at`` (Python).

Read in Python when an impact or a batch starts, never baked into compiled code
(``kernels.address_call``): compiled, or loaded from the cache, on first use, then kept for
the process.
"""

from __future__ import annotations

from functools import cache

from impactlab.dynamics.kernels.address_call import compiled_addresses
from impactlab.dynamics.slipcore.address_call import (
    FIRST_EVENT_SIGNATURE,
    INTEGRATE_TO_SIGNATURE,
    RECORD_SIGNATURE,
    ROWS_SIGNATURE,
    STEP_SIGNATURE,
    SWITCH_SIGNATURE,
)
from impactlab.dynamics.slipcore.outputs import dense_rows, history_row
from impactlab.dynamics.slipcore.restart import switch_at_event
from impactlab.dynamics.slipcore.stepper import dp_step_slip, slip_first_event, slip_integrate_to


@cache
def addresses() -> tuple[int, ...]:
    """The entry points (``address_call.SA_*``) of ``stepper.dp_step_slip``,
    ``stepper.slip_first_event``, ``stepper.slip_integrate_to``, ``restart.switch_at_event``,
    ``outputs.history_row`` and ``outputs.dense_rows``."""
    return compiled_addresses(
        (
            (dp_step_slip, STEP_SIGNATURE),
            (slip_first_event, FIRST_EVENT_SIGNATURE),
            (slip_integrate_to, INTEGRATE_TO_SIGNATURE),
            (switch_at_event, SWITCH_SIGNATURE),
            (history_row, RECORD_SIGNATURE),
            (dense_rows, ROWS_SIGNATURE),
        )
    )
