"""Kinematics of the contact point and the normal contact on the current branch (loading curve
or Hertzian unloading/reloading curve of the contact law)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.history_kernels import contact_radius as _contact_radius
from impactlab.contact.kernels import (
    KOGUT_KOMVOPOULOS,
    NPARAM,
    P_DSW,
    P_ESTAR,
    P_R,
    TABULATED,
    curve_force,
    hertz_force,
    loading_force,
    table_force,
    unloading_force,
)
from impactlab.contact.slopes import loading_radius_slope, table_force_slope
from impactlab.dynamics.kernels.layout import (
    C_A0,
    C_B0,
    C_C0,
    C_CONST,
    C_D,
    C_R,
    C_S0,
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
        s0 = c[C_S0]
        c0 = c[C_C0]
        sp, cm = rotation_terms(phi)
        ds = s0 * cm + c0 * sp  # sin(th0 + phi) - sin(th0)
        dc = c0 * cm - s0 * sp  # cos(th0 + phi) - cos(th0)
        a = d * (c0 + dc)
        b = d * (s0 + ds) + c[C_R]
        # d ds - y with d c0 and d s0 first (constants): the interference, which every force
        # evaluation waits for, two multiply-adds after the rotation terms
        delta = (d * c0) * sp + ((d * s0) * cm - y[S_Y])
        xs = y[S_X] - d * dc
        slide = xs + c[C_R] * phi
    return delta, a, b, xs, slide


#: Taylor coefficients of sin(phi) (phi^3 ... phi^9) and cos(phi) - 1 (phi^2 ... phi^8).
_S3, _S5, _S7, _S9 = -1.0 / 6.0, 1.0 / 120.0, -1.0 / 5040.0, 1.0 / 362880.0
_C2, _C4, _C6, _C8 = -0.5, 1.0 / 24.0, -1.0 / 720.0, 1.0 / 40320.0
#: |phi| [rad] up to which ``rotation_terms`` uses its series (truncation below 1e-16 of
#: each term: 2e-21 relative for the sine's, 2e-17 for the cosine's).
SERIES_PHI = 0.05


@njit(cache=True, inline="always", error_model="numpy")
def rotation_terms(phi):
    """(sin(phi), cos(phi) - 1) of the rotation ``phi`` [rad] since first touch, for the
    addition theorem (``geometry``).

    A rod turns by milliradians during an impact: for |phi| < SERIES_PHI from Taylor series
    (no cancellation in cos(phi) - 1, no sin/cos call), evaluated in Estrin's scheme (the
    powers of phi^2 side by side: a shorter dependency chain than Horner's, this being in the
    chain of every stage); beyond it from sin and cos (cos(phi) - 1 as -2 sin^2(phi/2))."""
    if abs(phi) < SERIES_PHI:
        p2 = phi * phi
        p4 = p2 * p2
        sp = phi + (phi * p2) * ((_S3 + _S5 * p2) + p4 * (_S7 + _S9 * p2))
        cm = p2 * ((_C2 + _C4 * p2) + p4 * (_C6 + _C8 * p2))
        return sp, cm
    half = math.sin(0.5 * phi)
    return math.sin(phi), -2.0 * half * half


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
            if law == TABULATED:  # its own tables, inline (as the polynomial table)
                return curve_force(p, NPARAM, delta)
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


@njit(cache=True, inline="always", error_model="numpy")
def normal_contact(law, p, md, delta):
    """(F_n [N], dF_n/d delta [N/m], a [m], da/d delta) on the current branch from one pass:
    the branch decided once, F_n and a as ``normal_force`` and ``radius`` (the same bits), the
    slopes exact (``contact.slopes``: 1.5 F_n / d and a / (2 d) on the Hertzian branches, the
    table's polynomial differentiated, (1 + B) a / (2 delta) on the Jackson-Green area fit)
    where ``dforce_ddelta`` and ``dradius_ddelta`` take central differences (relative error
    about 1e-10; kept for the rigid and flexible engines, whose results they define). Beyond
    the law's switch where no table row covers delta (no table, or a row left to the closed
    form), and on Kogut-Komvopoulos's elastic branch, the force keeps its central difference."""
    if md[M_PHASE] != 0.0:
        d = delta - md[M_DR]
        if d <= 0.0 or delta <= 0.0:
            return 0.0, 0.0, 0.0, 0.0
        Fn = unloading_force(p[P_ESTAR], md[M_RR], md[M_DR], delta)
        ar = md[M_AF] * math.sqrt(md[M_RR] * d)
        return Fn, 1.5 * Fn / d, ar, 0.5 * ar / d
    if delta <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    ar, ad = loading_radius_slope(law, p, delta)
    if delta >= p[P_DSW]:
        f, fd = table_force_slope(p, NPARAM, delta)
        if f >= 0.0:
            return f, fd, ar, ad
    elif law != KOGUT_KOMVOPOULOS:
        Fn = hertz_force(p[P_ESTAR], p[P_R], delta)
        return Fn, 1.5 * Fn / delta, ar, ad
    Fn = normal_force(law, p, md, delta)
    return Fn, dforce_ddelta(law, p, md, delta, Fn), ar, ad
