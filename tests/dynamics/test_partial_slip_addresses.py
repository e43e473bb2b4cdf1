"""The partial-slip engine's functions called through their addresses: the addresses are those
of compiled code, kept for the process, one per function, and a call with other argument types
is refused when the caller compiles."""

from __future__ import annotations

import numpy as np
import pytest
from numba import njit, typeof
from numba.core.errors import TypingError

from impactlab.dynamics.slipcore import slip_addresses
from impactlab.dynamics.slipcore.address_call import ADDRESSES, N_SLIP_ADDRESSES, call_step


def test_addresses_are_compiled_distinct_and_kept() -> None:
    at = slip_addresses()
    assert len(at) == N_SLIP_ADDRESSES
    assert all(isinstance(a, int) and a > 0 for a in at)
    assert len(set(at)) == N_SLIP_ADDRESSES
    assert slip_addresses() is at
    assert typeof(at) == ADDRESSES


def test_a_call_with_other_argument_types_is_refused() -> None:
    @njit
    def wrong(y: np.ndarray) -> None:
        call_step(np.int64(1), y)

    with pytest.raises(TypingError, match="call_step: arguments"):
        wrong(np.zeros(3))
