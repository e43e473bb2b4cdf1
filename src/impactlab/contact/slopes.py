"""Compiled slopes d/d delta of a contact law's loading force and contact radius, each with the
value itself, from one pass (the partial-slip engine needs F_n, a and their time rates at every
stage: ``impactlab.dynamics.kernels.normal.normal_contact``).

The values are those of ``contact.table.table_force`` and
``contact.history_kernels.loading_contact_radius`` to the bit (the same expressions); the
slopes are the exact derivatives of the same formulas (no finite difference):

- the tabulated loading curve (``contact.table``): F(t) is a polynomial of degree DEG in the
  position t in [-1, 1] of its row, t = 2 SUB (s - 1) - 2 j - 1 with delta = delta_lo s 2^k,
  so dF/d delta = F'(t) 2 SUB / (delta_lo 2^k). The slope of the interpolant, not of the closed
  form: the rows match the closed form to TABLE_RTOL (1e-13) between Chebyshev nodes of degree
  7, so their slopes match its slope to about DEG^2 TABLE_RTOL ~ 1e-11 relative, and may jump by
  as much from one row to the next (the force itself is continuous to 1e-13).
- the Hertz radius a = sqrt(R delta): da/d delta = a / (2 delta); the Jackson-Green area fit
  a = sqrt(R delta (delta / (1.9 delta_c))^B) (Jackson & Green 2005,
  doi:10.1115/1.1866166): da/d delta = (1 + B) a / (2 delta).

Valid wherever the values are (delta > 0 on the loading curve); pure functions, SI units.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.kernels import (
    GHAEDNIA,
    JACKSON_GREEN,
    JG_AREA_SWITCH,
    P_JG_B,
    P_JG_DC,
    P_R,
    jg_contact_radius,
)
from impactlab.contact.table import SUB, row_force, table_row


@njit(cache=True, inline="always", error_model="numpy")
def table_force_slope(p: np.ndarray, nparam: int, delta: float) -> tuple[float, float]:
    """(F [N], dF/d delta [N/m]) of the tabulated loading curve at ``delta`` [m]; F = -1.0 (and
    slope 0) where the table does not cover ``delta`` (as ``contact.table.table_force``)."""
    row, t, s, u = table_row(p, nparam, delta)
    if row < 0:
        return -1.0, 0.0
    f = row_force(p, row, t)
    t2 = t * t
    # F'(t) = c1 + 2 c2 t + ... + 7 c7 t^6, in the same pairs
    d0 = p[row + 1] + 2.0 * p[row + 2] * t
    d1 = 3.0 * p[row + 3] + 4.0 * p[row + 4] * t
    d2 = 5.0 * p[row + 5] + 6.0 * p[row + 6] * t
    d3 = 7.0 * p[row + 7]
    dfdt = (d0 + d1 * t2) + (d2 + d3 * t2) * (t2 * t2)
    # dt/d delta = 2 SUB ds/du du/d delta = 2 SUB 2^-k / delta_lo, with 2^-k = s / u (exact)
    return f, dfdt * (2.0 * SUB) * p[nparam + 1] * (s / u)


@njit(cache=True, inline="always", error_model="numpy")
def loading_radius_slope(law: int, p: np.ndarray, delta: float) -> tuple[float, float]:
    """(a [m], da/d delta) on the loading curve at ``delta`` [m]: a as
    ``history_kernels.loading_contact_radius``; (0, 0) for delta <= 0."""
    if delta <= 0.0:
        return 0.0, 0.0
    if (law == GHAEDNIA or law == JACKSON_GREEN) and delta > JG_AREA_SWITCH * p[P_JG_DC]:
        a = jg_contact_radius(p, delta)
        return a, (0.5 + 0.5 * p[P_JG_B]) * a / delta
    a = math.sqrt(p[P_R] * delta)
    return a, 0.5 * a / delta


__all__ = ["loading_radius_slope", "table_force_slope"]
