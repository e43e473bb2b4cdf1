"""The compile option of the core's hot leaf functions: no reference counting.

A function that allocates nothing needs no reference counts of its array arguments; numba
emits them anyway where a function is inlined (``inline="always"``) with array arguments, and
the LLVM pass that prunes them leaves many in a function as branched as the driver's step loop:
1664 atomic increments and decrements per impact were counted (gdb, benchmark case), each a
serialising ``lock`` instruction inside the dependency chain of the stages. Compiled with
numba's private ``_nrt=False`` option of ``numba.njit`` (used in numba's own tests), these
functions carry none; they may call ordinary compiled functions, but must not create arrays.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from numba import njit

_F = TypeVar("_F", bound=Callable[..., Any])

#: numba's switch of the reference counting (NRT) for one function.
_NO_REFCOUNT: dict[str, Any] = {"_nrt": False}


def njit_no_refcount(fn: _F) -> _F:
    """``njit(cache=True, error_model="numpy")`` without reference counting (see module)."""
    return njit(cache=True, error_model="numpy", **_NO_REFCOUNT)(fn)  # type: ignore[no-any-return]
