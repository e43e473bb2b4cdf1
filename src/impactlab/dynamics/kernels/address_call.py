"""Calls of compiled functions through their addresses, shared by the drivers.

numba links the code of every compiled function a function calls into that function's library,
and optimises and generates machine code for it again there: a callee of the step loop is
generated once in its own library and once more in each library that calls it. Called through
its address instead, a callee's machine code is generated once. ``address_intrinsic`` makes
the intrinsic for one callee signature, ``typed_call`` its signature and code: the call in
numba's own calling convention (as numba's first-class function type calls a jit function),
with the arguments that follow the address, borrowed as numba passes them to any call (packed
in a tuple, every array in it would be counted in and out of the tuple at each call). The
argument types must be the signature's exactly (checked when the caller is compiled).

``compiled_addresses`` reads the addresses in Python (compiling, or loading from the cache, on
first use): they are passed to compiled code as int64 values, never baked into it, so the
cached engine holds none and a second process loads every function from the cache.
"""

from __future__ import annotations

import gc
from collections.abc import Callable, Sequence
from typing import Any

from numba.core import cgutils, types
from numba.core.errors import TypingError
from numba.experimental.function_type import _get_jit_address
from numba.extending import intrinsic


def typed_call(name: str, sig: Any, address: Any, args: tuple[Any, ...]) -> Any:
    """The signature and code generator of a call through ``address`` for ``sig`` (``args``:
    the argument types after the address, received by numba as a ``StarArgTuple``); None
    (not this intrinsic) when ``address`` is no integer."""
    if not isinstance(address, types.Integer):
        return None
    if tuple(args) != tuple(sig.args):
        raise TypingError(f"{name}: arguments {args} are not {sig.args}")
    argtys = tuple(sig.args)

    def codegen(context: Any, builder: Any, signature: Any, llargs: Any) -> Any:
        fnty = context.call_conv.get_function_type(sig.return_type, argtys)
        fptr = builder.inttoptr(llargs[0], fnty.as_pointer())
        vals = cgutils.unpack_tuple(builder, llargs[1], len(argtys))
        status, res = context.call_conv.call_function(builder, fptr, sig.return_type, argtys, vals)
        with cgutils.if_unlikely(builder, status.is_error):
            context.call_conv.return_status_propagate(builder, status)
        return res if sig.return_type != types.none else context.get_dummy_value()

    return sig.return_type(address, types.StarArgTuple.from_types(argtys)), codegen


def address_intrinsic(name: str, sig: Any) -> Callable[..., Any]:
    """The intrinsic ``name(address, *args)``: a call of the compiled function of signature
    ``sig`` at ``address`` (int64) with ``args`` (``typed_call``); typed for mypy as a plain
    callable."""

    def typer(typingctx: Any, address: Any, *args: Any) -> Any:
        return typed_call(name, sig, address, args)

    typer.__name__ = typer.__qualname__ = name
    return intrinsic(typer)  # type: ignore[no-any-return]


def compiled_addresses(functions: Sequence[tuple[Any, Any]]) -> tuple[int, ...]:
    """The entry points of the compiled ``(dispatcher, signature)`` pairs, compiled (or loaded
    from the cache) here, with the cyclic garbage collector paused meanwhile (as
    ``impactlab._compile_gc`` pauses it around a compile). Each is compiled for its argument
    types, as a call from Python compiles it (numba's cache keys a compile by the signature it
    was asked for: with the return type, a compile that a call from Python left in the cache
    was not found), and the return type is then checked against the signature's."""
    collecting = gc.isenabled()
    gc.disable()
    try:
        for fn, sig in functions:
            if tuple(sig.args) not in fn.overloads:
                fn.compile(tuple(sig.args))
        return tuple(int(_get_jit_address(fn, sig)) for fn, sig in functions)
    finally:
        if collecting:
            to_oldest_generation()
            gc.enable()


def to_oldest_generation() -> None:
    """Hand the objects of the compilations just made (numba keeps most of them alive) to the
    collector's oldest generation, where its next full pass finds their garbage: the next
    collection of the youngest generation would otherwise pass over every one of them (0.7 s
    of CPU after a first drop's compile, rigid engine cached). ``gc.freeze`` and
    ``gc.unfreeze`` move every object without passing over any. Where the caller keeps objects
    frozen (``impactlab._compile_gc.garbage_deferred``) they join them until it hands them back."""
    caller_froze = gc.get_freeze_count() > 0
    gc.freeze()
    if not caller_froze:
        gc.unfreeze()
