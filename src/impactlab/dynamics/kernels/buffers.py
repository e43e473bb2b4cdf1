"""Copies between work arrays, as loops.

An array assigned to a slice (``new[:n] = hist[:n]``, ``y[:] = yev``) makes numba compile, in
every process that compiles such a caller, the formatter of its shape-mismatch message (string
joins and integer reprs, about 3.5 s of CPU per array rank; it is not kept in the disk cache).
The engines copy between arrays whose shapes match by construction, so they copy element by
element: the same numbers, the same speed, none of that compilation.
"""

from __future__ import annotations

import numpy as np
from numba import njit


@njit(cache=True, error_model="numpy")
def grown(hist, n, extra):
    """A history buffer of twice the rows of ``hist`` (rows, columns) plus ``extra``, its first
    ``n`` rows copied from ``hist``."""
    cols = hist.shape[1]
    new = np.empty((2 * hist.shape[0] + extra, cols))
    for i in range(n):
        for j in range(cols):
            new[i, j] = hist[i, j]
    return new


@njit(cache=True, error_model="numpy")
def copy_into(dst, src):
    """``dst[:] = src`` for 1-d arrays of one size."""
    for i in range(src.size):
        dst[i] = src[i]
