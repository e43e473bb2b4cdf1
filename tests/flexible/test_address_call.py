"""The flexible drop's functions called through their addresses: the model tuple has the one
type the callers are compiled for, the addresses are those of compiled code (the cell switches'
only with partial slip), a call with other argument types is refused when the caller compiles,
and neither the right-hand side of every model but partial slip nor the event handler names
the cells' kernels (they compile only for a drop that uses them)."""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest
from numba import njit, typeof
from numba.core.errors import TypingError

from impactlab.dynamics.flexcore import cellswitch, contacts, events, rhs, setup
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import (
    AT_CELLS,
    AT_EVENTS,
    AT_RHS,
    MODEL,
    N_ADDRESSES,
    call_rates,
)
from impactlab.dynamics.flexcore.indirect import addresses, batch_addresses
from impactlab.dynamics.flexcore.model import model_tuple
from impactlab.dynamics.kernels import cells as kernel_cells


def _model(friction_id: int) -> tuple[object, ...]:
    c = np.zeros(F.NFC)
    c[F.FC_FRIC] = friction_id
    m, ends = np.ones(3), np.ones((2, 3))
    return model_tuple(1, np.zeros(8), c, m, 0.01 * m, ends, ends, ends)


@pytest.mark.parametrize("friction_id", [1, F.FR_PARTIAL])
def test_the_model_tuple_has_the_callers_type(friction_id: int) -> None:
    mdl = _model(friction_id)
    assert typeof(mdl) == MODEL
    assert mdl[13:] == addresses(friction_id == F.FR_PARTIAL)


def test_addresses_are_kept_and_differ_per_friction_family() -> None:
    plain, cells = addresses(False), addresses(True)
    assert len(plain) == len(cells) == N_ADDRESSES
    switches = AT_CELLS - AT_RHS
    assert plain[switches] == 0  # never called, never compiled without partial slip
    assert all(isinstance(a, int) and a > 0 for a in plain[:switches] + cells)
    assert len(set(plain[:2] + cells[:2])) == 4  # the right-hand sides and steps
    assert plain[AT_EVENTS - AT_RHS : switches] == cells[AT_EVENTS - AT_RHS : switches]
    assert addresses(False) == plain
    assert batch_addresses(True) == (cells[0], cells[1], cells[switches])


def test_a_call_with_other_argument_types_is_refused() -> None:
    @njit
    def wrong(y: np.ndarray) -> None:
        call_rates(np.int64(1), y)

    with pytest.raises(TypingError, match="call_rates: arguments"):
        wrong(np.zeros(3))


def test_only_the_partial_slip_right_hand_side_names_the_cells() -> None:
    def cell_kernels(*fns: Any) -> set[str]:
        names = set().union(*(f.__code__.co_names for f in fns))
        return {n for n in names if n.startswith("cell_")}

    assert not cell_kernels(rhs.rates.py_func, rhs._end_forces.py_func)
    cells = cell_kernels(rhs.rates_cells.py_func, rhs._end_forces_cells.py_func)
    assert len(cells) == 3  # forces, rates, events


def test_the_event_handler_names_no_cell_switch() -> None:
    def compiled_in(module: Any) -> set[str]:
        return {
            name
            for name, value in vars(module).items()
            if getattr(getattr(value, "py_func", None), "__module__", "") == module.__name__
        }

    handler = (
        events.handle_events.py_func,
        events._apply.py_func,
        contacts.on_touch.py_func,
        contacts.on_separation.py_func,
        setup.touch_modes.py_func,
    )
    names = set().union(*(f.__code__.co_names for f in handler))
    switches = compiled_in(cellswitch) | compiled_in(kernel_cells)
    switches.discard(cellswitch.cell_action.py_func.__name__)
    assert len(switches) > 8  # the cell switches and the shared cell kernels are found
    assert not names & switches
    assert "call_cells" in names  # behind the one address of ``cellswitch.cell_action``
