"""Kinematics of the contact point and the normal contact on the current branch (loading curve
or Hertzian unloading/reloading curve of the contact law)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.kernels import P_ESTAR, P_R, loading_force, unloading_force
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
        th = c[C_TH0] + phi
        s = math.sin(th)
        co = math.cos(th)
        a = d * co
        b = d * s + c[C_R]
        delta = d * (s - c[C_S0]) - y[S_Y]
        xs = y[S_X] - d * (co - c[C_C0])
        slide = xs + c[C_R] * phi
    return delta, a, b, xs, slide


@njit(cache=True, inline="always", error_model="numpy")
def normal_force(law, p, md, delta):
    """Normal force [N] at interference ``delta`` [m] on the current branch."""
    if md[M_PHASE] == 0.0:
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
