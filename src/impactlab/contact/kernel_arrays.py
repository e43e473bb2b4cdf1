"""Vectorised loops over the compiled contact kernels (``impactlab.contact.kernels``).

Used when a model is built (its loading curve is checked on a grid, its switch point located)
and for the arrays a ``ContactModel`` returns; the engine calls the scalar kernels directly.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact import history_kernels as hk
from impactlab.contact import kernels as k

_FORCE = 0
_RADIUS = 1


@njit(cache=True, error_model="numpy")
def _loading_array(quantity: int, law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """``loading_force`` (``_FORCE``) or ``loading_contact_radius`` (``_RADIUS``) over an array
    of interferences, in the array's shape."""
    out = np.empty(delta.size)
    flat = delta.ravel()
    for i in range(flat.size):
        if quantity == _FORCE:
            out[i] = k.loading_force(law, p, flat[i])
        else:
            out[i] = hk.loading_contact_radius(law, p, flat[i])
    return out.reshape(delta.shape)


@njit(cache=True, error_model="numpy")
def loading_force_array(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """Vectorised ``loading_force`` over an array of interferences."""
    return _loading_array(_FORCE, law, p, delta)


@njit(cache=True, error_model="numpy")
def loading_contact_radius_array(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """Vectorised ``loading_contact_radius`` over an array of interferences."""
    return _loading_array(_RADIUS, law, p, delta)


GAP_JACKSON_FAMILY = 0
GAP_KOGUT_KOMVOPOULOS = 1


@njit(cache=True, error_model="numpy")
def elastic_plastic_gap_array(kind: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """F_ep(delta) - F_elastic(delta) [N] on a 1-D array, for locating the continuous switch of
    the Jackson-Green family (``GAP_JACKSON_FAMILY``) or Kogut-Komvopoulos
    (``GAP_KOGUT_KOMVOPOULOS``) when a model is built (one compiled loop instead of thousands of
    Python calls)."""
    out = np.empty(delta.size)
    for i in range(delta.size):
        x = delta[i]
        if kind == GAP_JACKSON_FAMILY:
            out[i] = k.jg_ep_force(p, x) - k.hertz_force(p[k.P_ESTAR], p[k.P_R], x)
        elif kind == GAP_KOGUT_KOMVOPOULOS:
            out[i] = k.kk_ep_force(p, x) - k.kk_elastic_force(p, x)
        else:
            out[i] = math.nan
    return out
