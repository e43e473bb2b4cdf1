"""Predicted permanent dent: the envelope of residual caps along the contact path.

Model (derivation in docs/engine/index.md, "Dent model"). At every recorded instant t of the
contact the tip (radius R) is pressed to the interference delta(t) at the contact point
x_c(t). Unloading the law from delta(t) would leave a residual impression of depth
delta_r(t) = residual_depth(delta(t)) whose shape follows from the Hertzian unloading branch:
the sphere R and the residual dent of radius R_d unload with the relative radius R_r, so

    1 / R_r = 1 / R - 1 / R_d   ->   R_d = R R_r / (R_r - R)   (R_r > R).

The residual cap is approximated by its paraboloid, h_t(x, y) = -delta_r + ((x - x_c)^2 +
y^2) / (2 R_d), over its rim radius a_d = sqrt(2 R_d delta_r). Plastic deformation is
irreversible and deeper imprints overwrite shallower ones, so the dent is the lower envelope
h(x, y) = min(0, min_t h_t(x, y)). Elastic interaction between neighbouring imprints, pile-up
and the groove the moving tip ploughs through its own earlier imprint are neglected.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from impactlab.contact.kernels import P_R
from impactlab.dynamics.core.batch import residual_caps


class DentSurface(NamedTuple):
    """Grid and height of a dent (fields of ``DentMap``), SI units."""

    x: np.ndarray
    y: np.ndarray
    height: np.ndarray
    max_depth: float
    length: float
    width: float


def residual_cap_geometry(
    law_id: int,
    law_params: np.ndarray,
    delta: np.ndarray,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(delta_r, R_d, a_d) [m] of the residual caps after loading to each ``delta`` [m]."""
    d = np.ascontiguousarray(np.asarray(delta, dtype=np.float64))
    dr, rr = residual_caps(int(law_id), np.array(law_params, dtype=np.float64), d)
    R = float(law_params[P_R])
    with np.errstate(divide="ignore", invalid="ignore"):
        rd = np.where(rr > R * (1.0 + 1e-12), R * rr / (rr - R), np.inf)
        ad = np.where(dr > 0.0, np.sqrt(2.0 * rd * dr), 0.0)
    ad = np.where(np.isfinite(ad), ad, 0.0)
    return dr, rd, ad


def dent_map(
    law_id: int,
    law_params: np.ndarray,
    penetration: np.ndarray,
    contact_x: np.ndarray,
    *,
    nx: int = 241,
    ny: int = 121,
    margin: float = 0.15,
) -> DentSurface:
    """The dent height map from an impact's history columns ``penetration`` [m] and
    ``contact_x`` [m] (see the module docstring); ``DentMap`` (``impactlab.dynamics.results``)
    wraps it."""
    if nx < 3 or ny < 3:
        raise ValueError(f"nx and ny must be >= 3, got nx={nx!r}, ny={ny!r}")
    if not (math.isfinite(margin) and margin >= 0.0):
        raise ValueError(f"margin must be finite and >= 0, got {margin!r}")
    delta = np.asarray(penetration)
    xc = np.asarray(contact_x)
    dr, rd, ad = residual_cap_geometry(law_id, law_params, delta)
    keep = (dr > 0.0) & (ad > 0.0)
    if not np.any(keep):
        # no permanent deformation (elastic law): a flat map around the contact path
        span = max(float(np.ptp(xc)), float(np.sqrt(law_params[P_R] * max(delta.max(), 0.0))), 1e-9)
        x = np.linspace(xc.min() - span, xc.max() + span, nx)
        y = np.linspace(-span, span, ny)
        return DentSurface(
            x=x, y=y, height=np.zeros((ny, nx)), max_depth=0.0, length=0.0, width=0.0
        )
    dr, rd, ad, xk = dr[keep], rd[keep], ad[keep], xc[keep]
    x_lo = float(np.min(xk - ad))
    x_hi = float(np.max(xk + ad))
    a_max = float(ad.max())
    pad = margin * max(x_hi - x_lo, 2.0 * a_max)
    x = np.linspace(x_lo - pad, x_hi + pad, nx)
    y = np.linspace(-(a_max + pad), a_max + pad, ny)
    height = np.zeros((ny, nx))
    y2 = (y * y)[:, None]
    for i in range(dr.shape[0]):
        lo = np.searchsorted(x, xk[i] - ad[i])
        hi = np.searchsorted(x, xk[i] + ad[i], side="right")
        if hi <= lo:
            continue
        dx = x[lo:hi] - xk[i]
        cap = -dr[i] + (dx * dx + y2) / (2.0 * rd[i])
        np.minimum(height[:, lo:hi], cap, out=height[:, lo:hi])
    np.minimum(height, 0.0, out=height)
    return DentSurface(
        x=x, y=y, height=height, max_depth=float(dr.max()), length=x_hi - x_lo, width=2.0 * a_max
    )
