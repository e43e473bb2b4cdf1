"""Compiled force and contact radius of a contact with its history (``impactlab.contact.kernels``
holds the laws): the turning point where unloading starts, the force on the loading or unloading
branch, and the contact radius a [m] that the tangential models use (k_t = 8 G* a). On loading
it is the Jackson-Green area fit for the JG family (ghaednia, jackson_green) beyond 1.9 delta_c
and the Hertz radius sqrt(R delta) for every other law and range, including brake and
kogut_komvopoulos: their loading force is their own, but their truncation radius is not the
contact radius in the elastic range and their sources give none for the transition, so in
plastic contact this radius is below the FE one (1.1-1.41 sqrt(R delta)) by up to about 29 %.
On unloading sqrt(R_r (delta - delta_r)); 0 out of contact. Pure functions, SI units."""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.kernels import (
    GHAEDNIA,
    JACKSON_GREEN,
    JG_AREA_SWITCH,
    P_ESTAR,
    P_JG_DC,
    P_R,
    jg_contact_radius,
    loading_force,
    residual_depth,
    unloading_force,
    unloading_radius,
)


@njit(cache=True, error_model="numpy")
def turning_point(law: int, p: np.ndarray, delta_m: float) -> tuple[float, float, float]:
    """(F_m [N], delta_r [m], R_r [m]) of the unloading branch that starts at ``delta_m``."""
    F_m = loading_force(law, p, delta_m)
    if delta_m <= 0.0:
        return 0.0, 0.0, p[P_R]
    d_r = residual_depth(law, p, delta_m, F_m)
    return F_m, d_r, unloading_radius(p[P_ESTAR], delta_m, F_m, d_r)


@njit(cache=True, error_model="numpy")
def contact_force(
    law: int,
    p: np.ndarray,
    delta: float,
    delta_m: float,
    delta_r: float,
    R_r: float,
) -> float:
    """Force at ``delta`` given the history (delta_m: largest interference so far, and the
    unloading branch (delta_r, R_r) that belongs to it). On or beyond delta_m: loading curve."""
    if delta >= delta_m:
        return loading_force(law, p, delta)
    return unloading_force(p[P_ESTAR], R_r, delta_r, delta)


@njit(cache=True, error_model="numpy")
def loading_contact_radius(law: int, p: np.ndarray, delta: float) -> float:
    """Contact radius on the loading curve [m]: Jackson-Green area fit for the JG family beyond
    delta = 1.9 delta_c, Hertz sqrt(R delta) otherwise and for every other law (brake and
    kogut_komvopoulos included: a simplification, smaller than their plastic radius)."""
    if delta <= 0.0:
        return 0.0
    if (law == GHAEDNIA or law == JACKSON_GREEN) and delta > JG_AREA_SWITCH * p[P_JG_DC]:
        return jg_contact_radius(p, delta)
    return math.sqrt(p[P_R] * delta)


@njit(cache=True, error_model="numpy")
def contact_radius(
    law: int,
    p: np.ndarray,
    delta: float,
    delta_m: float,
    delta_r: float,
    R_r: float,
) -> float:
    """Contact radius a [m] at ``delta`` given the history (same arguments as contact_force):
    loading curve at or beyond delta_m, sqrt(R_r (delta - delta_r)) on unloading, 0 out of
    contact."""
    if delta <= 0.0:
        return 0.0
    if delta >= delta_m:
        return loading_contact_radius(law, p, delta)
    d = delta - delta_r
    if d <= 0.0:
        return 0.0
    return math.sqrt(R_r * d)


__all__ = ["contact_force", "contact_radius", "loading_contact_radius", "turning_point"]
