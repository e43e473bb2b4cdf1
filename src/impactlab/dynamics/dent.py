"""Predicted permanent dent: the envelope of residual caps along the contact path.

Model (derivation in docs/engine/index.md, "Dent model"). At every recorded instant t of the
contact the tip (radius R) is pressed to the interference delta(t) at the contact point
x_c(t). Unloading the law from delta(t) would leave a residual impression of depth
delta_r(t) = residual_depth(delta(t)) whose shape follows from the Hertzian unloading branch:
the sphere R and the residual dent of radius R_d unload with the relative radius R_r, so

    1 / R_r = 1 / R - 1 / R_d   ->   R_d = R R_r / (R_r - R)   (R_r > R).

The residual cap is approximated by its paraboloid, h_t(x, y) = -delta_r + ((x - x_c)^2 +
y^2) / (2 R_d), over its rim radius a_d = sqrt(2 R_d delta_r). Two bounds keep every cap
(with its depth delta_r) on the flat:

- elastic recovery only flattens the tip's imprint, so R_d >= R; where the law's R_r <= R
  the relation has no concave solution and the cap takes the tip's own radius, R_d = R: the
  narrowest cap of that depth (``AT_TIP_RADIUS``);
- the relation gives the residual surface inside the contact only; a rim beyond the widest
  circle the tip touched, a_c = max(a(delta), sqrt(R_r (delta - delta_r)), sqrt(2 R delta))
  (loading and unloading contact radii, the tip's crossing of the undeformed flat), as when
  R_r is just above R (R_d -> inf), is brought to a_c: R_d = a_c^2 / (2 delta_r) >= R
  (``AT_CONTACT_RADIUS``).

Plastic deformation is irreversible and deeper imprints overwrite shallower ones, so the dent
is the lower envelope h(x, y) = min(0, min_t h_t(x, y)). Elastic interaction between
neighbouring imprints, pile-up and the groove the moving tip ploughs through its own earlier
imprint are neglected.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from impactlab.contact.kernel_arrays import loading_contact_radius_array
from impactlab.contact.kernels import P_R
from impactlab.dynamics.core.batch import residual_caps

#: How a cap's shape was found (``ResidualCaps.bound``): by the Hertzian unloading relation,
#: at the tip's radius (R_d = R), at the widest contact radius (a_d = a_c).
BY_RELATION, AT_TIP_RADIUS, AT_CONTACT_RADIUS = 0, 1, 2

#: Relative margin by which the relation's rim must pass a_c to be brought to it (rounding:
#: Thornton's caps lie on sqrt(2 R delta) itself).
RIM_RTOL = 1e-6


class DentSurface(NamedTuple):
    """Grid and height of a dent (fields of ``DentMap``), SI units."""

    x: np.ndarray
    y: np.ndarray
    height: np.ndarray
    max_depth: float
    length: float
    width: float
    caps_at_tip_radius: int = 0
    caps_at_contact_radius: int = 0
    note: str = ""


class ResidualCaps(NamedTuple):
    """The residual caps after loading to each interference: depth ``delta_r`` [m], radius
    ``R_d`` [m] (inf without a dent), rim radius ``a_d`` [m] (0 without a dent) and ``bound``
    (``BY_RELATION``, ``AT_TIP_RADIUS`` or ``AT_CONTACT_RADIUS``)."""

    delta_r: np.ndarray
    R_d: np.ndarray
    a_d: np.ndarray
    bound: np.ndarray


def residual_cap_geometry(law_id: int, law_params: np.ndarray, delta: np.ndarray) -> ResidualCaps:
    """The residual caps (``ResidualCaps``, SI) after loading to each ``delta`` [m]."""
    d = np.ascontiguousarray(np.asarray(delta, dtype=np.float64))
    p = np.array(law_params, dtype=np.float64)
    dr, rr = residual_caps(int(law_id), p, d)
    R = float(p[P_R])
    dent = dr > 0.0
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        concave = dent & (rr > R * (1.0 + 1e-12))
        rd_rel = np.where(np.isinf(rr), R, R * rr / (rr - R))  # R_r = inf: no recovery, R_d = R
        a_rel = np.sqrt(2.0 * rd_rel * dr)
        a_unl = np.sqrt(rr * (d - dr))
    a_unl = np.where(np.isfinite(a_unl), a_unl, 0.0)
    a_load = loading_contact_radius_array(int(law_id), p, d)
    a_c = np.maximum(np.maximum(a_load, a_unl), np.sqrt(2.0 * R * np.maximum(d, 0.0)))
    bound = np.full(d.shape, BY_RELATION, dtype=np.int8)
    bound[dent & ~concave] = AT_TIP_RADIUS
    bound[concave & ~(a_rel <= a_c * (1.0 + RIM_RTOL))] = AT_CONTACT_RADIUS
    with np.errstate(divide="ignore", invalid="ignore"):
        rd = np.where(bound == AT_CONTACT_RADIUS, a_c * a_c / (2.0 * dr), rd_rel)
        rd = np.where(bound == AT_TIP_RADIUS, R, rd)
        ad = np.where(bound == AT_CONTACT_RADIUS, a_c, np.sqrt(2.0 * rd * dr))
    rd = np.where(dent, rd, np.inf)
    ad = np.where(dent & np.isfinite(ad), ad, 0.0)
    return ResidualCaps(dr, rd, ad, bound)


def bound_note(tip: int, contact: int, deepest: int) -> str:
    """What a ``DentMap``'s ``note`` says of its bounded caps: ``tip`` and ``contact`` caps of
    its surface at the tip's or the contact radius, the deepest cap's ``bound``."""
    parts = []
    if tip:
        deep = ", the deepest among them," if deepest == AT_TIP_RADIUS else ""
        parts.append(
            f"{tip} residual cap(s) of the surface{deep} drawn at the tip's radius R_d = R "
            "(the law's unloading radius R_r <= R gives no concave dent): width a lower bound"
        )
    if contact:
        deep = ", the deepest among them," if deepest == AT_CONTACT_RADIUS else ""
        parts.append(
            f"{contact} residual cap(s) of the surface{deep} narrowed to the contact radius "
            "(R_r just above R puts the unloading relation's rim beyond the contact): width "
            "an upper bound"
        )
    return "; ".join(parts) + ("; depths are the law's" if parts else "")


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
    dr, rd, ad, bound = residual_cap_geometry(law_id, law_params, delta)
    keep = (dr > 0.0) & (ad > 0.0)
    if not np.any(keep):
        # no permanent deformation (elastic law): a flat map around the contact path
        span = max(float(np.ptp(xc)), float(np.sqrt(law_params[P_R] * max(delta.max(), 0.0))), 1e-9)
        x = np.linspace(xc.min() - span, xc.max() + span, nx)
        y = np.linspace(-span, span, ny)
        return DentSurface(
            x=x, y=y, height=np.zeros((ny, nx)), max_depth=0.0, length=0.0, width=0.0
        )
    dr, rd, ad, xk, bound = dr[keep], rd[keep], ad[keep], xc[keep], bound[keep]
    x_lo = float(np.min(xk - ad))
    x_hi = float(np.max(xk + ad))
    a_max = float(ad.max())
    pad = margin * max(x_hi - x_lo, 2.0 * a_max)
    x = np.linspace(x_lo - pad, x_hi + pad, nx)
    y = np.linspace(-(a_max + pad), a_max + pad, ny)
    height = np.zeros((ny, nx))
    owner = np.full((ny, nx), -1)  # the cap that forms each point of the surface
    y2 = (y * y)[:, None]
    for i in range(dr.shape[0]):
        lo = np.searchsorted(x, xk[i] - ad[i])
        hi = np.searchsorted(x, xk[i] + ad[i], side="right")
        if hi <= lo:
            continue
        dx = x[lo:hi] - xk[i]
        cap = -dr[i] + (dx * dx + y2) / (2.0 * rd[i])
        lower = cap < height[:, lo:hi]
        height[:, lo:hi][lower] = cap[lower]
        owner[:, lo:hi][lower] = i
    deepest = int(np.argmax(dr))
    shown = np.zeros(dr.shape[0], dtype=bool)
    shown[owner[owner >= 0]] = True
    shown[deepest] = True
    tip = int(np.count_nonzero(shown & (bound == AT_TIP_RADIUS)))
    contact = int(np.count_nonzero(shown & (bound == AT_CONTACT_RADIUS)))
    return DentSurface(
        x=x,
        y=y,
        height=height,
        max_depth=float(dr.max()),
        length=x_hi - x_lo,
        width=2.0 * a_max,
        caps_at_tip_radius=tip,
        caps_at_contact_radius=contact,
        note=bound_note(tip, contact, int(bound[deepest])),
    )
