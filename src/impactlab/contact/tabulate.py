"""Build the polynomial table of a law's elastic-plastic loading curve (``contact.table``) and
append it to the law's parameter vector: ``with_table(law_id, p)``.

Every row interpolates the closed form (``kernels.loading_force``) at DEG + 1 Chebyshev points
of its sub-interval and is then checked against it at DEG + 2 points between the nodes and at
both ends, through the engine's own evaluation (``table_force``): a row whose largest relative
difference exceeds ``TABLE_RTOL`` (a law's own switch inside it, a non-finite value) is marked
to be left to the closed form. Cost: ~2,000 law evaluations (~0.1 ms), once per parameter vector.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact import kernels as k
from impactlab.contact.kernel_arrays import loading_force_array
from impactlab.contact.table import (
    DEG,
    HEADER,
    SUB,
    TABLE_MAGIC,
    TABLE_RTOL,
    table_force,
)

#: Octaves covered: delta from the start of the elastic-plastic curve to 2^OCTAVES times it
#: (capped at the law's validity limit).
OCTAVES = 14

_N = DEG + 1
_NODES = np.cos((2.0 * np.arange(_N) + 1.0) * math.pi / (2.0 * _N))
#: Monomial coefficients from values at the nodes: c = _INV @ f.
_INV = np.linalg.inv(np.vander(_NODES, _N, increasing=True))
#: Check points: between the nodes and both ends of the sub-interval.
_CHECK = np.concatenate(([-1.0, 1.0 - 1e-12], 0.5 * (_NODES[:-1] + _NODES[1:]), [-0.999, 0.999]))


def _positions(delta_lo: float, octaves: int, t: np.ndarray) -> np.ndarray:
    """Interferences [m] at the positions ``t`` of every row, shape (rows, len(t))."""
    kk = np.repeat(np.arange(octaves), SUB)[:, None]
    jj = np.tile(np.arange(SUB), octaves)[:, None]
    return delta_lo * 2.0**kk * (1.0 + (jj + 0.5 * (t[None, :] + 1.0)) / SUB)


@njit(cache=True, error_model="numpy")
def _evaluate(p: np.ndarray, nparam: int, delta: np.ndarray) -> np.ndarray:
    out = np.empty(delta.shape[0])
    for i in range(delta.shape[0]):
        out[i] = table_force(p, nparam, delta[i])
    return out


def with_table(law_id: int, p: np.ndarray) -> np.ndarray:
    """``p`` (length NPARAM) with the table of the law's elastic-plastic loading curve appended
    (a new writable array); ``p`` itself (a copy) where the law has no such curve (Hertz) or
    no row passes its check."""
    p = np.require(np.array(p, dtype=np.float64), np.float64, ["C", "W"])
    if p.shape != (k.NPARAM,) or law_id == k.HERTZ:
        return p
    delta_lo = float(p[k.P_DSW])
    if not (math.isfinite(delta_lo) and delta_lo > 0.0):
        return p
    limit = float(p[k.P_DLIM])
    octaves = OCTAVES
    if math.isfinite(limit):
        octaves = min(OCTAVES, math.floor(math.log2(limit / delta_lo)))
    if octaves < 1:
        return p
    rows = octaves * SUB
    f = loading_force_array(law_id, p, _positions(delta_lo, octaves, _NODES).ravel())
    coeffs = (f.reshape(rows, _N) @ _INV.T).ravel()
    header = np.array([TABLE_MAGIC, 1.0 / delta_lo, 2.0**octaves])
    out = np.require(np.concatenate((p, header, coeffs)), np.float64, ["C", "W"])
    at = _positions(delta_lo, octaves, _CHECK)
    exact = loading_force_array(law_id, p, at.ravel()).reshape(at.shape)
    got = _evaluate(out, k.NPARAM, at.ravel()).reshape(at.shape)
    bad = ~(np.abs(got - exact) <= TABLE_RTOL * np.abs(exact)).all(axis=1)
    base = k.NPARAM + HEADER
    for row in np.flatnonzero(bad):
        out[base + row * _N] = math.nan
    if bad.all():
        return p
    return out


def has_table(p: object) -> bool:
    """True for a 1-D float64 parameter vector with a table appended (by ``with_table``)."""
    return (
        isinstance(p, np.ndarray)
        and p.ndim == 1
        and p.dtype == np.float64
        and p.shape[0] > k.NPARAM + HEADER
        and p[k.NPARAM] == TABLE_MAGIC
        and (p.shape[0] - k.NPARAM - HEADER) % _N == 0
    )


def table_rows(p: np.ndarray) -> tuple[int, int]:
    """(rows, rows kept) of the table in ``p`` ((0, 0): none)."""
    if p.shape[0] <= k.NPARAM:
        return 0, 0
    coeffs = p[k.NPARAM + HEADER :].reshape(-1, _N)
    return coeffs.shape[0], int(np.isfinite(coeffs[:, 0]).sum())


__all__ = ["OCTAVES", "has_table", "table_rows", "with_table"]
