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


@njit(cache=True, error_model="numpy")
def _loading_force_1d(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    out = np.empty(delta.shape[0])
    for i in range(delta.shape[0]):
        out[i] = k.loading_force(law, p, delta[i])
    return out


@njit(cache=True, error_model="numpy")
def _loading_contact_radius_1d(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    out = np.empty(delta.shape[0])
    for i in range(delta.shape[0]):
        out[i] = hk.loading_contact_radius(law, p, delta[i])
    return out


def _flat(delta: np.ndarray) -> np.ndarray:
    """``delta`` as a contiguous 1-D float64 array: one compiled signature for every caller
    (the loops above are compiled on a first rigid impact, whose model building calls them)."""
    return np.ascontiguousarray(np.asarray(delta, dtype=np.float64).ravel())


def loading_force_array(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """Vectorised ``loading_force`` [N] over an array of interferences [m], in its shape."""
    return _loading_force_1d(law, p, _flat(delta)).reshape(np.shape(delta))


def loading_contact_radius_array(law: int, p: np.ndarray, delta: np.ndarray) -> np.ndarray:
    """Vectorised ``loading_contact_radius`` [m] over an array of interferences [m], in its
    shape."""
    return _loading_contact_radius_1d(law, p, _flat(delta)).reshape(np.shape(delta))


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
