"""The force evaluation of the Dormand-Prince stage loops, its pieces shared by the time step and
the w-step, the state tuple, the dense output and the step factor are compiled once by numba and
inlined by LLVM (``kernels._jit.njit_llvm_inline``): the stage loop's machine code calls none of
them."""

from __future__ import annotations

import re
from typing import Any

import pytest
from numba import njit
from numba import types as nbt

from impactlab.dynamics.core import approach, integrator
from impactlab.dynamics.kernels import dormand_prince, rhs, step_control, tuples
from impactlab.dynamics.kernels.layout import NC, NM

pytestmark = pytest.mark.perf  # the shape of the compiled engine, not its speed

_A1 = nbt.Array(nbt.float64, 1, "C")
_A2 = nbt.Array(nbt.float64, 2, "C")
_F = nbt.float64
_I = nbt.int64
_C = nbt.UniTuple(_F, NC)
_M = nbt.UniTuple(_F, NM)


def _llvm_inlined(module: object) -> list[Any]:
    """The module's compiled functions that LLVM inlines (by their options: their names are
    never used from Python, ``tests/core/test_compiled_wrappers.py``)."""
    return [
        f
        for f in vars(module).values()
        if getattr(f, "targetoptions", {}).get("forceinline")
        and f.py_func.__module__ == module.__name__  # type: ignore[attr-defined]
    ]


@pytest.mark.parametrize(
    ("module", "count"),
    # the stage force evaluation and the geometry, normal and tangential force it shares with
    # the w-step; the w-step's force evaluation; the state tuple; the dense output; the step
    # factor (counted, not named: their names are never used from Python)
    [(rhs, 4), (approach, 1), (tuples, 1), (dormand_prince, 1), (step_control, 1)],
)
def test_llvm_inlined_functions_have_no_wrappers_or_counts(module: object, count: int) -> None:
    fns = _llvm_inlined(module)
    assert len(fns) == count
    for fn in fns:
        opts = fn.targetoptions
        assert opts.get("_nrt") is False
        assert opts.get("no_cpython_wrapper") is True and opts.get("no_cfunc_wrapper") is True


def test_stage_loop_calls_no_force_evaluation() -> None:
    """``dp_step`` compiled afresh (outside the cache, whose code numba does not show): LLVM
    has inlined the force evaluation, and the loading curve's call inside it is still there
    (so the pattern finds calls)."""
    modules = (rhs, tuples, dormand_prince, step_control)
    inlined = {f.py_func.__name__ for m in modules for f in _llvm_inlined(m)}
    opts = {k: v for k, v in integrator.dp_step.targetoptions.items() if k != "nopython"}
    opts["cache"] = False
    step = njit(**opts)(integrator.dp_step.py_func)
    sig = (_I, _A1, _I, _C, _M, _A1, _A2, _F, _F, _A1, _A1)
    step.compile(sig)
    ir = step.inspect_llvm(sig)
    body = re.search(r"define [^\n]*dp_step[^\n]*\{(.*?)\n\}", ir, re.S)
    assert body is not None
    calls = re.findall(r"call [^\n]*@\"?(\w+)", body.group(1))
    assert any("loading_force" in c for c in calls)
    assert not [c for c in calls if any(name in c for name in inlined)]
