"""The binary exponent and significand of a float64 read from its bits, for the compiled core.

``math.frexp`` compiles to a call of the C library's ``frexp``: ~10 cycles of call and
branches in the dependency chain of every loading-curve evaluation (``contact.table``) and of
every step-size update (``dynamics.core.integrator.growth``). Here the same two numbers come
from the IEEE 754 fields: a bit cast and two integer operations, inline.
"""

from __future__ import annotations

import struct

from llvmlite import ir
from numba import config, njit, types
from numba.extending import intrinsic

#: The significand's bits of a float64 and the bits of the exponent of 1.0.
_FRACTION = 0x000F_FFFF_FFFF_FFFF
_ONE = 0x3FF0_0000_0000_0000


@intrinsic
def _bits_of(typingctx, x):  # type: ignore[no-untyped-def]
    """The 64 bits of the float64 ``x`` as an int64 (a bit cast: no conversion)."""
    if x != types.float64:
        return None

    def codegen(context, builder, signature, args):  # type: ignore[no-untyped-def]
        return builder.bitcast(args[0], ir.IntType(64))

    return types.int64(types.float64), codegen


@intrinsic
def _float_of(typingctx, i):  # type: ignore[no-untyped-def]
    """The float64 whose 64 bits are the int64 ``i`` (a bit cast)."""
    if i != types.int64:
        return None

    def codegen(context, builder, signature, args):  # type: ignore[no-untyped-def]
        return builder.bitcast(args[0], ir.DoubleType())

    return types.float64(types.int64), codegen


def _significand_exponent_py(x: float) -> tuple[float, int]:
    """``significand_exponent`` in plain Python (``NUMBA_DISABLE_JIT=1``: intrinsics cannot
    run there), from the same bits."""
    (bits,) = struct.unpack("<q", struct.pack("<d", x))
    e = ((bits >> 52) & 0x7FF) - 1023
    (s,) = struct.unpack("<d", struct.pack("<q", (bits & _FRACTION) | _ONE))
    return s, e


@njit(cache=True, inline="always", error_model="numpy")
def significand_exponent(x):  # type: ignore[no-untyped-def]
    """(s, e) with x = s 2^e and s in [1, 2), for a positive normal float64 ``x`` (frexp's
    (m, k) are (s / 2, e + 1), both exact). Zero, subnormals, infinities and NaN give
    e = -1023 or 1024: the callers range-check x (or e) first."""
    bits: int = _bits_of(x)  # type: ignore[call-arg]
    e = ((bits >> 52) & 0x7FF) - 1023
    return _float_of((bits & _FRACTION) | _ONE), e  # type: ignore[call-arg]


if config.DISABLE_JIT:  # type: ignore[attr-defined]  # plain Python: no intrinsics
    significand_exponent = _significand_exponent_py  # type: ignore[assignment]
