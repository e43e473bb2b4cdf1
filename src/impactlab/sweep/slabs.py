"""A sweep's case array a part at a time: the blocks (slabs) that cover it in C order, each
of a bounded number of cases and aligned with the store's chunks where they fit, so that
exports and counts hold one block in memory whatever the size of the store."""

from __future__ import annotations

from collections.abc import Iterator
from typing import Any

import numpy as np

__all__ = ["slabs", "store_chunks"]


def store_chunks(ds: Any) -> tuple[int, ...] | None:
    """The store's chunk shape (``status``'s Zarr chunks), None for a Dataset not read from one."""
    if "status" not in ds:
        return None
    chunks = ds["status"].encoding.get("chunks")
    return tuple(int(c) for c in chunks) if chunks else None


def slabs(
    shape: tuple[int, ...], limit: int, chunks: tuple[int, ...] | None = None
) -> Iterator[tuple[slice, ...]]:
    """Blocks of an array of ``shape`` that cover it in C order, one after the other, each of at
    most ``limit`` cases (at least 1): whole trailing dimensions, a run along the next one (a
    multiple of ``chunks`` along it where it fits) and single indices before it."""
    n = len(shape)
    if n == 0 or 0 in shape:
        yield tuple(slice(0, s) for s in shape)
        return
    k = 0
    while k < n - 1 and int(np.prod(shape[k + 1 :], dtype=np.int64)) > limit:
        k += 1
    step = max(1, limit // int(np.prod(shape[k + 1 :], dtype=np.int64)))
    if chunks is not None and 0 < chunks[k] <= step:
        step -= step % chunks[k]
    tail = (slice(None),) * (n - k - 1)
    for lead in np.ndindex(*shape[:k]):
        head = tuple(slice(i, i + 1) for i in lead)
        for a in range(0, shape[k], step):
            yield (*head, slice(a, min(a + step, shape[k])), *tail)
