"""Compiled (numba) force evaluations of every contact law: the engine's inner loop calls these.

Contract (shared by all laws; SI units):

- A law is identified by an integer id (``HERTZ`` ... ``THORNTON``) and a float64 parameter
  vector ``p`` of length ``NPARAM``. Slots ``0..6`` are common to all laws (see ``P_*``); slots
  ``7..15`` are law-specific and documented in each law's module.
- ``loading_force(law, p, delta)`` is the force on the virgin loading curve [N] for an
  interference ``delta`` [m] (0 for ``delta <= 0``).
- ``residual_depth(law, p, delta_m, F_m)`` is the residual depth delta_r [m] after unloading
  from the maximum (delta_m, F_m); ``0 <= delta_r < delta_m``.
- Unloading (and reloading below delta_m) is, for every law, Hertzian with a flattened radius
  R_r chosen for continuity at (delta_m, F_m): ``F = 4/3 E* sqrt(R_r) (delta - delta_r)^1.5``.
- ``p[P_DLIM]`` is the largest interference for which the law is valid (``inf`` when the law
  has no limit); the engine stops with a clear error beyond it.

Everything here is a pure function: no state is kept between calls.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

HERTZ = 0
GHAEDNIA = 1
JACKSON_GREEN = 2
KOGUT_KOMVOPOULOS = 3
BRAKE = 4
THORNTON = 5
N_LAWS = 6

NPARAM = 16
P_ESTAR = 0  # reduced modulus E* [Pa]
P_R = 1  # radius of the sphere / rod tip [m]
P_SY = 2  # yield strength used by the law [Pa]
P_NU = 3  # Poisson's ratio used by the law
P_DY = 4  # interference at yield onset delta_y [m] (inf for Hertz)
P_FY = 5  # force at yield onset F_y [N] (inf for Hertz)
P_DLIM = 6  # largest valid interference [m]
P_LAW0 = 7  # first law-specific slot


@njit(cache=True, inline="always")
def hertz_force(E_star: float, R: float, delta: float) -> float:
    """Hertz sphere-on-flat force 4/3 E* sqrt(R) delta^1.5 [N]; 0 for delta <= 0."""
    if delta <= 0.0:
        return 0.0
    return 4.0 / 3.0 * E_star * math.sqrt(R) * delta * math.sqrt(delta)


@njit(cache=True)
def loading_force(law: int, p: np.ndarray, delta: float) -> float:
    """Force on the loading curve of ``law`` at interference ``delta`` [N]."""
    if delta <= 0.0:
        return 0.0
    if law == HERTZ:
        return hertz_force(p[P_ESTAR], p[P_R], delta)
    # Other laws are dispatched here (filled in by their modules' kernels).
    return math.nan


@njit(cache=True)
def residual_depth(law: int, p: np.ndarray, delta_m: float, F_m: float) -> float:
    """Residual depth delta_r after unloading from (delta_m, F_m) [m]."""
    if law == HERTZ or delta_m <= 0.0:
        return 0.0
    return math.nan


@njit(cache=True, inline="always")
def unloading_radius(E_star: float, delta_m: float, F_m: float, delta_r: float) -> float:
    """Flattened radius R_r [m] making the Hertzian unloading curve pass through (delta_m, F_m)."""
    d = delta_m - delta_r
    if d <= 0.0:
        return math.inf
    c = 3.0 * F_m / (4.0 * E_star)
    return c * c / (d * d * d)


@njit(cache=True, inline="always")
def unloading_force(E_star: float, R_r: float, delta_r: float, delta: float) -> float:
    """Hertzian unloading force 4/3 E* sqrt(R_r) (delta - delta_r)^1.5 [N]; 0 below delta_r."""
    d = delta - delta_r
    if d <= 0.0:
        return 0.0
    return 4.0 / 3.0 * E_star * math.sqrt(R_r) * d * math.sqrt(d)


@njit(cache=True)
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


@njit(cache=True)
def loading_force_array(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """Vectorised ``loading_force`` over an array of interferences."""
    out = np.empty(delta.size)
    flat = delta.ravel()
    for i in range(flat.size):
        out[i] = loading_force(law, p, flat[i])
    return out.reshape(delta.shape)
