"""Predicted permanent dent: the envelope of the residual caps along the contact path.

Model (derivation in docs/engine/index.md, "Dent model"). At every recorded instant t of the
contact the tip (radius R) is pressed to the interference delta(t) at the contact point
x_c(t). Unloading the law from delta(t) would leave a residual impression of depth
delta_r(t) = residual_depth(delta(t)) whose shape follows from the Hertzian unloading branch:
the sphere R and the residual dent of radius R_d unload with the relative radius R_r, so

    1 / R_r = 1 / R - 1 / R_d   ->   R_d = R R_r / (R_r - R)   (R_r > R).

The residual cap is approximated by its paraboloid, h_t(x, y) = -delta_r + ((x - x_c)^2 +
y^2) / (2 R_d), over its rim radius a_d = sqrt(2 R_d delta_r). The relation gives the
residual surface inside the contact only, and the model has no pile-up, so no rim passes the
widest circle the tip touched, a_c = max(a(delta), sqrt(R_r (delta - delta_r)), sqrt(2 R
delta)) (loading and unloading contact radii, the tip's crossing of the undeformed flat). As
R_r -> R+ the relation's R_d -> inf and its rim passes a_c; for R_r <= R (some laws'
unloading stiffness) it has no concave solution, and its limit R_r -> R+ is kept. Such a cap
keeps its depth delta_r and is drawn with a_d = a_c, R_d = a_c^2 / (2 delta_r)
(``AT_CONTACT_RADIUS``), continuous in delta across R_r = R; R_d >= R since a_c^2 >= 2 R
delta > 2 R delta_r (``residual_depth``: delta_r < delta).

No cap reaches beyond the tip's radius R either: where a_c passes R (delta > R/2 with the
crossing of the paraboloid tip) it is held to R (``AT_TIP_RADIUS``; the paraboloid tip is
beyond its range there, the width is the tip's diameter).

Plastic deformation is irreversible and deeper imprints overwrite shallower ones, so the dent
is the lower envelope h(x, y) = min(0, min_t h_t(x, y)) of the caps that no deeper loading
superseded: the cap of an instant i is left out where a plastic instant j (delta_r,j > 0)
pressed the tip deeper than i everywhere within i's contact circle (strictly), and j's circle
contains i's (``superseded``): that material was loaded further and unloaded from j, so j's
cap stands for it. A normal impact thus leaves the cap of its deepest instant (no ring of the
shallower ones); along a sliding path the imprints behind the tip stay. Elastic interaction
between neighbouring imprints, pile-up and the groove the moving tip ploughs through its own
earlier imprint are neglected.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from impactlab.contact.kernel_arrays import loading_contact_radius_array
from impactlab.contact.kernels import P_R
from impactlab.dynamics.core.batch import residual_caps
from impactlab.materials import Material, body_yields_first, first_yield_factor

#: How a cap's shape was found (``ResidualCaps.bound``): by the Hertzian unloading relation,
#: at the widest contact radius (a_d = a_c), or at the tip's radius (a_c held to R).
BY_RELATION, AT_CONTACT_RADIUS, AT_TIP_RADIUS = 0, 1, 2

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
    caps_at_contact_radius: int = 0
    note: str = ""


class ResidualCaps(NamedTuple):
    """The residual caps after loading to each interference: depth ``delta_r`` [m], radius
    ``R_d`` [m] (inf without a dent), rim radius ``a_d`` [m] (0 without a dent), ``bound``
    (``BY_RELATION``, ``AT_CONTACT_RADIUS`` or ``AT_TIP_RADIUS``) and the widest contact
    radius ``a_c`` [m] (0 without contact)."""

    delta_r: np.ndarray
    R_d: np.ndarray
    a_d: np.ndarray
    bound: np.ndarray
    a_c: np.ndarray


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
    past_tip = a_c > R
    a_c = np.minimum(a_c, R)
    bound = np.full(d.shape, BY_RELATION, dtype=np.int8)
    # R_r <= R (no concave solution) and a rim beyond a_c: the relation's limit R_r -> R+
    bound[dent & ~(concave & (a_rel <= a_c * (1.0 + RIM_RTOL)))] = AT_CONTACT_RADIUS
    bound[dent & past_tip & (bound == AT_CONTACT_RADIUS)] = AT_TIP_RADIUS
    with np.errstate(divide="ignore", invalid="ignore"):
        rd = np.where(bound != BY_RELATION, a_c * a_c / (2.0 * dr), rd_rel)
        ad = np.where(bound != BY_RELATION, a_c, a_rel)
    rd = np.where(dent, rd, np.inf)
    ad = np.where(dent & np.isfinite(ad), ad, 0.0)
    return ResidualCaps(dr, rd, ad, bound, np.where(d > 0.0, a_c, 0.0))


def body_flattening(body: Material, flat: Material, depth: float, what: str) -> str:
    """Why a permanent interference is no dent in the flat, or ``""``: when the impacting body's
    material ``body`` yields before ``flat`` (``materials.body_yields_first``: the smaller
    first-yield pressure C(nu) S_y), the contact law takes the body's S_y and the permanent
    interference ``depth`` [m] (> 0; ``what``: its name, e.g. ``delta_p``) is the body's
    flattening, while the flat stays elastic to the law's approximation."""
    if not (depth > 0.0 and body_yields_first(body, flat)):
        return ""
    p_body = first_yield_factor(body.nu) * body.yield_strength
    p_flat = first_yield_factor(flat.nu) * flat.yield_strength
    return (
        f"the impacting body's material {body.name!r} yields before the flat {flat.name!r} "
        f"(first-yield pressure C(nu) S_y {p_body / 1e6:.4g} MPa against {p_flat / 1e6:.4g} "
        f"MPa: materials.body_yields_first), so the law takes the body's S_y and {what} = "
        f"{depth * 1e6:.4g} um is the body's permanent flattening, not a dent in the flat, "
        "which stays elastic to the law's approximation"
    )


def flattening_warning(clause: str) -> str:
    """The result's warning for a ``body_flattening`` clause (advisory: ``ok`` unchanged)."""
    return (
        f"body yields first: {clause}; dent() maps no dent in the flat (advisory: the value, "
        "the pair's permanent interference, and the other impact measures hold)"
    )


def flattening_error(clause: str) -> ValueError:
    """The error of ``dent()`` for a ``body_flattening`` clause."""
    return ValueError(
        f"dent(): there is no dent in the flat to map: {clause} (plot_contact_path leaves the "
        "dent out by itself)"
    )


def bound_note(contact: int, deepest: int, tip: int = 0) -> str:
    """What a ``DentMap``'s ``note`` says of its bounded caps: ``contact`` caps of its surface
    at the contact radius, ``tip`` of them at the tip's radius, the deepest cap's ``bound``."""
    if not contact:
        return ""
    deep = ", the deepest among them," if deepest != BY_RELATION else ""
    note = (
        f"{contact} residual cap(s) of the surface{deep} drawn at the contact radius (R_r <= "
        "R or just above R: the unloading relation gives no concave dent within the contact): "
        "width an upper bound; depths are the law's"
    )
    if tip:
        note += (
            f"; {tip} of them at the tip's radius R (the contact passes it beyond delta = R/2, "
            "where the paraboloid tip is out of its range): width the tip's diameter"
        )
    return note


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
    caps = residual_cap_geometry(law_id, law_params, delta)
    dr, ad, bound = caps.delta_r, caps.a_d, caps.bound
    keep = (dr > 0.0) & (ad > 0.0)
    if not np.any(keep):
        # no permanent deformation (elastic law): a flat map around the contact path
        span = max(float(np.ptp(xc)), float(np.sqrt(law_params[P_R] * max(delta.max(), 0.0))), 1e-9)
        x = np.linspace(xc.min() - span, xc.max() + span, nx)
        y = np.linspace(-span, span, ny)
        return DentSurface(
            x=x, y=y, height=np.zeros((ny, nx)), max_depth=0.0, length=0.0, width=0.0
        )
    x_lo = float(np.min(xc[keep] - ad[keep]))
    x_hi = float(np.max(xc[keep] + ad[keep]))
    a_max = float(ad[keep].max())
    pad = margin * max(x_hi - x_lo, 2.0 * a_max)
    x = np.linspace(x_lo - pad, x_hi + pad, nx)
    y = np.linspace(-(a_max + pad), a_max + pad, ny)
    kept = keep & ~superseded(delta, xc, caps, float(law_params[P_R]))
    height = np.zeros((ny, nx))
    owner = np.full((ny, nx), -1)  # the cap that forms each point of the surface
    y2 = (y * y)[:, None]
    for i in np.flatnonzero(kept):
        lo = np.searchsorted(x, xc[i] - ad[i])
        hi = np.searchsorted(x, xc[i] + ad[i], side="right")
        if hi <= lo:
            continue
        dx = x[lo:hi] - xc[i]
        cap = -dr[i] + (dx * dx + y2) / (2.0 * caps.R_d[i])
        lower = cap < height[:, lo:hi]
        height[:, lo:hi][lower] = cap[lower]
        owner[:, lo:hi][lower] = i
    deepest = int(np.argmax(dr))
    shown = np.zeros(dr.shape[0], dtype=bool)
    shown[owner[owner >= 0]] = True
    shown[deepest] = True
    contact = int(np.count_nonzero(shown & (bound != BY_RELATION)))
    tip = int(np.count_nonzero(shown & (bound == AT_TIP_RADIUS)))
    return DentSurface(
        x=x,
        y=y,
        height=height,
        max_depth=float(dr.max()),
        length=float(np.max(xc[kept] + ad[kept]) - np.min(xc[kept] - ad[kept])),
        width=2.0 * float(ad[kept].max()),
        caps_at_contact_radius=contact,
        note=bound_note(contact, int(bound[deepest]), tip),
    )


def superseded(delta: np.ndarray, xc: np.ndarray, caps: ResidualCaps, R: float) -> np.ndarray:
    """Which caps a deeper plastic loading supersedes (module docstring): cap i where some j
    with delta_r,j > 0 has a_c,j >= |x_j - x_i| + a_c,i and pressed deeper over i's circle,
    delta_j - delta_i > (d^2 + 2 |d| a_c,i) / (2 R), d = x_j - x_i (the tip's penetration
    delta - r^2 / 2R, compared at the point of i's circle where j's lead is least). Inputs SI.

    Only plastic caps are tested, deepest first, each against the caps found standing so far:
    the rule is transitive (a cap that supersedes j supersedes what j supersedes), and a
    superseding j is deeper than i, so the standing caps are all that need asking, a few per
    place of the path instead of every pair of a long drop's history."""
    out = np.zeros(delta.shape[0], dtype=bool)
    plastic = np.flatnonzero((caps.delta_r > 0.0) & (caps.a_c > 0.0))
    order = plastic[np.argsort(-delta[plastic], kind="stable")]
    sx, sd, sa = (np.empty(order.size) for _ in range(3))
    m = 0
    for i in order:
        if m:
            d = np.abs(sx[:m] - xc[i])
            lead = sd[:m] - delta[i] - (d * d + 2.0 * d * caps.a_c[i]) / (2.0 * R)
            if np.any((sa[:m] >= d + caps.a_c[i]) & (lead > 0.0)):
                out[i] = True
                continue
        sx[m], sd[m], sa[m] = xc[i], delta[i], caps.a_c[i]
        m += 1
    return out
