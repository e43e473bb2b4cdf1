"""The state and mode as tuples (numba keeps them in registers): conversion from the state
array and a mode with one entry replaced."""

from __future__ import annotations

from numba import njit

from impactlab.dynamics.kernels._jit import njit_llvm_inline


@njit_llvm_inline
def state_tuple(y):
    """The state array ``y`` (length NS) as a tuple; compiled once for each array type and
    inlined by LLVM (``kernels._jit.njit_llvm_inline``): numba would translate and type it
    again at each of its two dozen call sites."""
    return (y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7])


@njit(cache=True, inline="always", error_model="numpy")
def mode_with(md, i, v):
    """The mode tuple ``md`` with entry ``i`` (an ``M_*`` index) set to ``v``."""
    return (
        v if i == 0 else md[0],
        v if i == 1 else md[1],
        v if i == 2 else md[2],
        v if i == 3 else md[3],
        v if i == 4 else md[4],
        v if i == 5 else md[5],
        v if i == 6 else md[6],
        v if i == 7 else md[7],
    )
