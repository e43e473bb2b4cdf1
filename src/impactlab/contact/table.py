"""A law's elastic-plastic loading curve as a table of polynomials, evaluated without any
transcendental function (the engine's inner loop evaluates the curve ~120 times per impact, one
stage after the other: the latency of the closed forms' log/exp/cos chain, ~70 ns for
Ghaednia's, was the largest single cost of an impact).

Layout: the table is appended to the law's parameter vector ``p`` (``p[NPARAM:]``, built by
``contact.tabulate.with_table``): ``p[NPARAM] = TABLE_MAGIC``, ``p[NPARAM + 1] = 1/delta_lo``,
``p[NPARAM + 2] = u_max`` (a power of two), then one row of ``DEG + 1`` monomial coefficients
per sub-interval. With u = delta/delta_lo in [1, u_max), the float's own exponent and
significand (``impactlab._floatbits``) give the octave k (u in [2^k, 2^(k+1))) and the position
inside it, which SUB equal sub-intervals split; t in [-1, 1] is the position inside one. A row
whose first coefficient is NaN (its check failed, e.g. a law's own switch inside it), or a
delta outside [delta_lo, delta_lo u_max), is evaluated by the closed form: ``table_force``
returns -1 for "not tabulated".

The rows interpolate the closed form at Chebyshev points (degree 7 over an eighth of an
octave); ``with_table`` checks every row against the closed form between the
nodes and keeps it only where the relative difference is below ``TABLE_RTOL`` (1e-13).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from impactlab._floatbits import significand_exponent

#: Polynomial degree of a row and sub-intervals per octave.
DEG = 7
SUB = 8
#: Largest relative difference from the closed form a row may have (checked when built).
TABLE_RTOL = 1e-13
#: Entries of the table's header (TABLE_MAGIC, 1/delta_lo, u_max); the marker tells a table
#: from anything else appended to a parameter vector.
HEADER = 3
TABLE_MAGIC = 7.0e-77


@njit(cache=True, inline="always", error_model="numpy")
def table_row(p: np.ndarray, nparam: int, delta: float) -> tuple[int, float, float, float]:
    """(first index of the row in ``p``, position t in [-1, 1] inside it, significand s and
    u = delta/delta_lo) of the table's row at ``delta`` [m]; row -1 where the table does not
    cover it (no table, outside its range, or a row left to the closed form)."""
    if p.shape[0] <= nparam or p[nparam] != TABLE_MAGIC:
        return -1, 0.0, 1.0, 1.0
    u = delta * p[nparam + 1]
    if not (u >= 1.0 and u < p[nparam + 2]):
        return -1, 0.0, 1.0, 1.0
    s, k = significand_exponent(u)  # u = s 2^k, s in [1, 2)
    x = (s - 1.0) * SUB
    j = int(x)
    t = 2.0 * (x - j) - 1.0
    row = nparam + HEADER + (k * SUB + j) * (DEG + 1)
    if not (p[row + DEG] == p[row + DEG] and p[row] == p[row]):
        return -1, 0.0, 1.0, 1.0
    return row, t, s, u


@njit(cache=True, inline="always", error_model="numpy")
def table_force(p: np.ndarray, nparam: int, delta: float) -> float:
    """The tabulated loading force [N] at ``delta`` [m], or -1.0 where the table does not cover
    it (no table, outside its range, or a row left to the closed form)."""
    row, t, _s, _u = table_row(p, nparam, delta)
    if row < 0:
        return -1.0
    return row_force(p, row, t)


@njit(cache=True, inline="always", error_model="numpy")
def row_force(p: np.ndarray, row: int, t: float) -> float:
    """The force [N] of the table's row starting at ``p[row]``, at position ``t`` in [-1, 1]:
    Estrin's scheme (pairs, then t^2, then t^4), a shorter dependency chain than Horner's."""
    t2 = t * t
    q0 = p[row] + p[row + 1] * t
    q1 = p[row + 2] + p[row + 3] * t
    q2 = p[row + 4] + p[row + 5] * t
    q3 = p[row + 6] + p[row + 7] * t
    return (q0 + q1 * t2) + (q2 + q3 * t2) * (t2 * t2)
