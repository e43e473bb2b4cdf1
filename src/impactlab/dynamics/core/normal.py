"""Kinematics of the contact point and the normal contact on the current branch (loading curve
or Hertzian unloading/reloading curve of the contact law)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.kernels import (
    KOGUT_KOMVOPOULOS,
    NPARAM,
    P_DSW,
    P_ESTAR,
    P_R,
    hertz_force,
    loading_force,
    table_force,
    unloading_force,
)
from impactlab.contact.kernels import contact_radius as _contact_radius
from impactlab.dynamics.core.layout import (
    C_A0,
    C_B0,
    C_C0,
    C_CONST,
    C_D,
    C_R,
    C_S0,
    C_TH0,
    M_AF,
    M_DR,
    M_PHASE,
    M_RR,
    S_PHI,
    S_X,
    S_Y,
)


@njit(cache=True, inline="always", error_model="numpy")
def geometry(c, y):
    """(delta, a, b, contact travel, sliding length) for state ``y``.

    a, b: horizontal and vertical lever arms from C to the contact point (paper Eq. 1)."""
    d = c[C_D]
    phi = y[S_PHI]
    if c[C_CONST] != 0.0:
        a = c[C_A0]
        b = c[C_B0]
        delta = a * phi - y[S_Y]
        xs = y[S_X] + d * c[C_S0] * phi
        slide = y[S_X] + b * phi
    else:
        ds, dc = rotation_increments(c[C_S0], c[C_C0], c[C_TH0], phi)
        a = d * (c[C_C0] + dc)
        b = d * (c[C_S0] + ds) + c[C_R]
        delta = d * ds - y[S_Y]
        xs = y[S_X] - d * dc
        slide = xs + c[C_R] * phi
    return delta, a, b, xs, slide


#: Reciprocals of the Taylor series' factors (a multiplication instead of a division).
_I6, _I12, _I20, _I30, _I42, _I56, _I72 = (1.0 / k for k in (6, 12, 20, 30, 42, 56, 72))
#: |phi| [rad] up to which ``rotation_increments`` uses its series (truncation below 1e-20).
SERIES_PHI = 0.05


@njit(cache=True, inline="always", error_model="numpy")
def rotation_increments(s0, c0, th0, phi):
    """(sin(th0 + phi) - s0, cos(th0 + phi) - c0) with s0 = sin th0, c0 = cos th0.

    A rod turns by milliradians during an impact: for |phi| < SERIES_PHI from the addition
    theorem with Taylor series of sin(phi) and cos(phi) - 1 (truncation error below 1e-20,
    no cancellation in the differences, no sin/cos call); beyond it from sin and cos."""
    if abs(phi) < SERIES_PHI:
        p2 = phi * phi
        sp = phi * (1.0 - p2 * _I6 * (1.0 - p2 * _I20 * (1.0 - p2 * _I42 * (1.0 - p2 * _I72))))
        cm = -0.5 * p2 * (1.0 - p2 * _I12 * (1.0 - p2 * _I30 * (1.0 - p2 * _I56)))
        return s0 * cm + c0 * sp, c0 * cm - s0 * sp
    th = th0 + phi
    return math.sin(th) - s0, math.cos(th) - c0


@njit(cache=True, inline="always", error_model="numpy")
def normal_force(law, p, md, delta):
    """Normal force [N] at interference ``delta`` [m] on the current branch.

    The tabulated loading curve is evaluated here, inline (``loading_force`` does the same
    first), and so is the Hertz curve below the switch: a call of ``loading_force`` with the
    parameter array costs two atomic reference count updates, which serialise the pipeline
    (~15 % of an impact when every stage made one)."""
    if md[M_PHASE] == 0.0:
        if delta >= p[P_DSW]:
            f = table_force(p, NPARAM, delta)
            if f >= 0.0:
                return f
        elif law != KOGUT_KOMVOPOULOS:
            # the elastic curve below the switch is Hertz's for every law but KK's (its own
            # elastic fit), inline as in ``loading_force``: the same numbers without its call
            return hertz_force(p[P_ESTAR], p[P_R], delta)
        return loading_force(law, p, delta)
    return unloading_force(p[P_ESTAR], md[M_RR], md[M_DR], delta)


@njit(cache=True, inline="always", error_model="numpy")
def radius(law, p, md, delta):
    """Contact radius [m] on the current branch. Phase 1: the unloading curve of
    ``contact_radius`` (also at delta = delta_m, where it would return the loading radius),
    scaled by md[M_AF] so that it starts from the loading radius at the turning point."""
    if md[M_PHASE] == 0.0:
        return _contact_radius(law, p, delta, delta, 0.0, p[P_R])
    return md[M_AF] * _contact_radius(law, p, delta, math.inf, md[M_DR], md[M_RR])


@njit(cache=True, inline="always", error_model="numpy")
def dforce_ddelta(law, p, md, delta, Fn):
    """dF_n/d delta on the current branch [N/m]."""
    if md[M_PHASE] != 0.0:
        d = delta - md[M_DR]
        return 1.5 * Fn / d if d > 0.0 else 0.0
    if delta <= 0.0:
        return 0.0
    h = 1e-6 * delta
    return (loading_force(law, p, delta + h) - loading_force(law, p, delta - h)) / (2.0 * h)


@njit(cache=True, inline="always", error_model="numpy")
def dradius_ddelta(law, p, md, delta):
    """d a / d delta on the current branch (central difference)."""
    base = 0.0 if md[M_PHASE] == 0.0 else md[M_DR]
    d = delta - base
    if d <= 0.0:
        return 0.0
    h = 1e-6 * d
    return (radius(law, p, md, delta + h) - radius(law, p, md, delta - h)) / (2.0 * h)
