"""An atomic counter for compiled code: the work queue of the parallel batch.

numba's ``prange`` splits its range evenly over the threads before they start (static
scheduling). When one core is also busy with other work (a sweep's writer thread compresses and
writes the previous chunk while the next one computes), the thread on that core finishes late
and the other one waits. ``impact_batch`` therefore starts one loop per thread and lets each
thread take the next block of cases from a shared counter as soon as it is free (dynamic
scheduling); the counter is incremented with one atomic instruction (LLVM ``atomicrmw add``).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import numpy as np
from numba import types
from numba.extending import intrinsic


def _fetch_add(typingctx: Any, counter: Any, increment: Any) -> Any:
    """``counter[0] += increment`` as one atomic operation; returns the value before it.

    ``counter``: a C-contiguous int64 array (element 0 is the counter); ``increment``: int64.
    Each value is handed to exactly one caller, whatever the threads. The ordering is LLVM's
    ``monotonic``: the counter only hands out indices; the results of the cases are published
    by the join at the end of the parallel loop.
    """
    if not (
        isinstance(counter, types.Array)
        and counter.dtype == types.int64
        and counter.layout == "C"
        and isinstance(increment, types.Integer)
    ):
        return None  # numba reports the unsupported argument types
    sig = types.int64(counter, types.int64)

    def codegen(context: Any, builder: Any, signature: Any, args: Any) -> Any:
        arr = context.make_array(signature.args[0])(context, builder, args[0])
        return builder.atomic_rmw("add", arr.data, args[1], "monotonic")

    return sig, codegen


#: ``fetch_add(counter, increment) -> int``, callable from compiled code only (see ``_fetch_add``).
fetch_add: Callable[[np.ndarray, int], int] = intrinsic(_fetch_add)  # type: ignore[assignment]
