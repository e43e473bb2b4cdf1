"""Compiled lookup of the tabulated law (``law="tabulated"``): its loading curve and its residual
depth ratio, stored after the parameter vector (``p[NPARAM:]``) as cubic Hermite tables on
uniform grids in x = log(delta / delta_c).

Layout (``b = NPARAM``; every table has the same length, ``CURVE_LENGTH``, so per-case
parameter rows of a batch stack):

==========  ==============================================================================
slot        meaning
==========  ==============================================================================
b           ``CURVE_MAGIC`` (not ``contact.table.TABLE_MAGIC``: ``table_force`` returns -1)
b + 1       x_0 of the loading grid (x = log(delta / delta_c) at its first node)
b + 2       1 / h: inverse node spacing of the loading grid
b + 3       x_0 of the residual grid (x = log(delta_m / delta_c))
b + 4       1 / h of the residual grid
b + 5 ...   ``N_LOAD`` values z = log(F / F_c), then their ``N_LOAD`` slopes dz/du
            (u: node index), then ``N_RES`` values delta_r / delta_m and their slopes
==========  ==============================================================================

``F_c`` and ``delta_c`` are in the law's slots ``P_TB_FC`` and ``P_TB_DC`` (``kernels``).
Evaluation: one log, one exp and a cubic (Hermite form) for the force; one log and a cubic for
the residual ratio. Past the last node the force extends linearly in u and the ratio stays
at its last value (the engine never goes there: ``p[P_DLIM]`` is the last tabulated
interference); below the first residual node the ratio is 0 (elastic unloading).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

#: Marker of a tabulated law's curve tables (distinct from ``contact.table.TABLE_MAGIC``).
CURVE_MAGIC = 5.0e-77
#: Header entries before the tables.
CURVE_HEADER = 5
#: Nodes of the loading and the residual-ratio grids.
N_LOAD = 193
N_RES = 96
#: Entries appended to the parameter vector.
CURVE_LENGTH = CURVE_HEADER + 2 * N_LOAD + 2 * N_RES

#: The law's slots inside ``p[:NPARAM]`` (mirrored in ``contact.kernels``).
_P_DC = 8
_P_FC = 9


@njit(cache=True, inline="always", error_model="numpy")
def _hermite(p: np.ndarray, at: int, n: int, u: float) -> float:
    """The cubic Hermite interpolant of the n values at ``p[at:]`` (slopes at ``p[at + n:]``)
    at the node coordinate ``u``; linear in u beyond either end."""
    if u <= 0.0:
        return p[at] + p[at + n] * u
    last = n - 1
    if u >= last:
        return p[at + last] + p[at + n + last] * (u - last)
    j = int(u)
    t = u - j
    y0 = p[at + j]
    m0 = p[at + n + j]
    m1 = p[at + n + j + 1]
    d = p[at + j + 1] - y0
    return y0 + t * (m0 + t * ((3.0 * d - 2.0 * m0 - m1) + t * (m0 + m1 - 2.0 * d)))


@njit(cache=True, inline="always", error_model="numpy")
def curve_force(p: np.ndarray, nparam: int, delta: float) -> float:
    """The tabulated loading force [N] at ``delta`` [m] (> 0, at or past the first node)."""
    x = math.log(delta / p[_P_DC])
    u = (x - p[nparam + 1]) * p[nparam + 2]
    return p[_P_FC] * math.exp(_hermite(p, nparam + CURVE_HEADER, N_LOAD, u))


@njit(cache=True, inline="always", error_model="numpy")
def curve_residual_ratio(p: np.ndarray, nparam: int, delta_m: float) -> float:
    """delta_r / delta_m after unloading from ``delta_m`` [m]: 0 below the first node."""
    x = math.log(delta_m / p[_P_DC])
    u = (x - p[nparam + 3]) * p[nparam + 4]
    if u <= 0.0:
        return 0.0
    if u > N_RES - 1.0:
        u = N_RES - 1.0
    r = _hermite(p, nparam + CURVE_HEADER + 2 * N_LOAD, N_RES, u)
    return r if r > 0.0 else 0.0


def curve_nodes(p: np.ndarray, nparam: int = 16) -> np.ndarray:
    """The interferences of the loading table's nodes [m] (where its cubics join)."""
    x = p[nparam + 1] + np.arange(N_LOAD) / p[nparam + 2]
    return p[_P_DC] * np.exp(x)


def has_curves(p: object, nparam: int) -> bool:
    """True for a 1-D float64 vector with the tabulated law's tables after ``nparam`` slots."""
    return (
        isinstance(p, np.ndarray)
        and p.ndim == 1
        and p.dtype == np.float64
        and p.shape[0] == nparam + CURVE_LENGTH
        and p[nparam] == CURVE_MAGIC
    )


__all__ = [
    "CURVE_HEADER",
    "CURVE_LENGTH",
    "CURVE_MAGIC",
    "N_LOAD",
    "N_RES",
    "curve_force",
    "curve_nodes",
    "curve_residual_ratio",
    "has_curves",
]
