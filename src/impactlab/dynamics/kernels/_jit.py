"""Compile options of the engine: no reference counting; no wrappers.

No reference counting, for the core's hot leaf functions:

A function that allocates nothing needs no reference counts of its array arguments; numba
emits them anyway where a function is inlined (``inline="always"``) with array arguments, and
the LLVM pass that prunes them leaves many in a function as branched as the driver's step loop:
1664 atomic increments and decrements per impact were counted (gdb, benchmark case), each a
serialising ``lock`` instruction inside the dependency chain of the stages. Compiled with
numba's private ``_nrt=False`` option of ``numba.njit`` (used in numba's own tests), these
functions carry none; they may call ordinary compiled functions, but must not create arrays.

No wrappers, for the functions that only compiled code calls: numba gives every compiled
function a Python-callable and a C-callable wrapper; without them a cold rigid compile takes
about 2.3 s (6 %) less (``docs/engine/first-run.md``). Called from Python, such a function
crashes the interpreter: ``tests/core/test_compiled_wrappers.py`` checks that none is.

Constant arguments, compiled for once: numba compiles a function once per signature, and a
constant passed by compiled code is a type of its own (``Literal[int](2)``,
``Literal[bool](False)``), so ``f(x, FR_MINDLIN)`` beside ``f(x, fric)`` compiles ``f`` and
everything it calls twice. A caller that shares a kernel (or the rigid core) with another passes
the value instead: ``np.int64(FR_MINDLIN)``, or a ``False`` computed at run time
(``out.shape[0] < 0``). The rigid batch alone keeps its literal ``False`` for the history: it
folds the history code away, 1-3 % of its speed (``docs/engine/first-run.md``).
``tests/core/test_compiled_signatures.py`` checks the signatures a warm-up leaves in the cache.

Inlined by LLVM, for the force evaluation in the Dormand-Prince stage loops (and its pieces
shared by the time step and the w-step, and small kernels with many call sites: the state
tuple, the dense output, the step factor): numba's
``inline="always"`` inlines a function's Python IR into every caller, whose type inference and
lowering then handle the callee's body again, and numba's type inference of a loop body grows
faster than its size (it passes over the whole body again until no type changes).
``njit_llvm_inline`` compiles the body once, without wrappers or reference counting, and sets
numba's ``forceinline`` option (LLVM's ``alwaysinline`` attribute): LLVM inlines the compiled
body into each caller when it optimises the caller with its callees, so the callers' machine
code does the same operations as with ``inline="always"`` (the same bits:
``tools/fingerprint.py``), and numba's front end handles the body once instead of once per
stage loop (``docs/engine/first-run.md``). A function inlined this way is optimised with its
own callees first, so LLVM may inline more of them into the caller than it would have: the
event functions stay numba-inlined, since through ``njit_llvm_inline`` they brought the
Mindlin slip test (``friction.mindlin_trial_rate``) into ``integrator.dp_step`` (a quarter more
instructions, and slower).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any, TypeVar

from numba import njit

_F = TypeVar("_F", bound=Callable[..., Any])

#: numba's switch of the reference counting (NRT) for one function.
_NO_REFCOUNT: dict[str, Any] = {"_nrt": False}
#: numba's switches of the Python- and C-callable wrappers of a function.
_NO_WRAPPERS: dict[str, Any] = {"no_cpython_wrapper": True, "no_cfunc_wrapper": True}
#: numba's switch of LLVM's ``alwaysinline`` attribute for a compiled function.
_LLVM_INLINE: dict[str, Any] = {"forceinline": True}


def njit_no_refcount(fn: _F) -> _F:
    """``njit(cache=True, error_model="numpy")`` without reference counting (see module)."""
    return njit(cache=True, error_model="numpy", **_NO_REFCOUNT)(fn)  # type: ignore[no-any-return]


def njit_internal(fn: _F) -> _F:
    """``njit(cache=True, error_model="numpy")`` without the Python- and C-callable wrappers,
    for a function that only compiled code calls (see module)."""
    return njit(cache=True, error_model="numpy", **_NO_WRAPPERS)(fn)  # type: ignore[no-any-return]


def njit_leaf(fn: _F) -> _F:
    """``njit(cache=True, error_model="numpy")`` without wrappers or reference counting, for a
    function that only compiled code calls, through its address (``address_call``), and that
    creates no arrays (views of its arguments are none of its own; see module)."""
    opts = {**_NO_WRAPPERS, **_NO_REFCOUNT}
    return njit(cache=True, error_model="numpy", **opts)(fn)  # type: ignore[no-any-return]


def njit_llvm_inline(fn: _F) -> _F:
    """``njit(cache=True, error_model="numpy")`` compiled once, inlined by LLVM into every
    caller; without wrappers or reference counting (see module)."""
    opts = {**_NO_WRAPPERS, **_NO_REFCOUNT, **_LLVM_INLINE}
    return njit(cache=True, error_model="numpy", **opts)(fn)  # type: ignore[no-any-return]
