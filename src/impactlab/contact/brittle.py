"""A brittle material past its first yield (``ResultFlag.BRITTLE``).

A brittle material (``Material.brittle``: glass, ceramics, cemented carbides) carries its
compressive strength as ``yield_strength``; past first yield it cracks rather than yields, and
impactlab has no fracture model. Both bodies carry the same contact pressure, so each brittle
member of the pair is checked, whichever of the two yields first.

Criterion: the largest mean contact pressure p_m = F_max / (pi a^2), with a the law's contact
radius on its loading curve at delta_max (``history_kernels.loading_contact_radius``: the
Jackson-Green area fit where the law has one, else Hertz's sqrt(R delta), which overstates the
pressure of a plastic contact by up to 2), exceeds the mean pressure of a Hertzian contact at
the brittle material's first yield, (2/3) p_0 with p_0 = C(nu) S_y,
C(nu) = 1.295 exp(0.736 nu) (Jackson & Green 2005, doi:10.1115/1.1866166; p_0 = C S_y is
Hertz's p_0 = (2 E*/pi) sqrt(delta/R) at their delta_c). For a brittle material that yields
first and an elastic contact this is delta_max > delta_c; a hard brittle body on a soft metal
(a carbide ball on steel), whose pressure the metal's yield caps far below the carbide's
strength, is not flagged.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.contact import kernels as k
from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.flags import FLAG_BRITTLE
from impactlab.materials import Material

__all__ = ["brittle_flags", "brittle_pressure", "first_yield_pressure", "mean_pressure"]


def first_yield_pressure(m: Material) -> float:
    """The mean contact pressure [Pa] of a Hertzian contact at ``m``'s first yield:
    (2/3) C(nu) S_y (Jackson & Green 2005)."""
    return 2.0 / 3.0 * 1.295 * math.exp(0.736 * m.nu) * m.yield_strength


def brittle_pressure(body: Material, flat: Material) -> float:
    """The lowest :func:`first_yield_pressure` [Pa] of the pair's brittle members; inf when
    neither is brittle."""
    if not (body.brittle or flat.brittle):  # the common case, on simulate's fast path
        return math.inf
    return min((first_yield_pressure(m) for m in (body, flat) if m.brittle), default=math.inf)


def mean_pressure(law_id: int, params: Any, delta_max: Any, max_force: Any) -> np.ndarray:
    """F_max / (pi a^2) [Pa] per case, a the law's loading contact radius at ``delta_max`` [m]
    (``params``: one parameter vector or one per case; NaN where delta_max is not > 0)."""
    dm = np.atleast_1d(np.asarray(delta_max, dtype=np.float64))
    fm = np.broadcast_to(np.asarray(max_force, dtype=np.float64), dm.shape)
    p = np.asarray(params, dtype=np.float64)
    rows = p if p.ndim == 2 else np.broadcast_to(p, (dm.size, p.shape[-1]))
    out = np.full(dm.shape, np.nan)
    for i in np.flatnonzero(np.isfinite(dm) & (dm > 0.0)):
        a = loading_contact_radius(int(law_id), np.ascontiguousarray(rows[i]), float(dm[i]))
        out[i] = fm[i] / (math.pi * a * a)
    return out


def brittle_flags(law_id: int, params: Any, delta_max: Any, max_force: Any, limit: Any) -> Any:
    """``FLAG_BRITTLE`` where the largest mean contact pressure (:func:`mean_pressure`) exceeds
    ``limit`` [Pa] (:func:`brittle_pressure`, one or per case; inf: no brittle member), else 0
    (int, or an int64 array for array inputs; 0 for NaN and for an unknown law)."""
    scalar = np.ndim(delta_max) == 0
    dm = np.atleast_1d(np.asarray(delta_max, dtype=np.float64))
    lim = np.broadcast_to(np.asarray(limit, dtype=np.float64), dm.shape)
    out = np.zeros(dm.shape, dtype=np.int64)
    check = np.isfinite(lim) & np.isfinite(dm)
    if params is not None and 0 <= int(law_id) < k.N_LAWS and check.any():
        p = np.asarray(params, dtype=np.float64)
        p = p[0] if p.ndim == 2 and p.shape[0] == 1 else p  # one vector shared by every case
        fm = np.broadcast_to(np.asarray(max_force, dtype=np.float64), dm.shape)
        rows = p[check] if p.ndim == 2 else p
        pm = mean_pressure(law_id, rows, dm[check], fm[check])
        out[check] = np.where(pm > lim[check], FLAG_BRITTLE, 0)
    return int(out[0]) if scalar else out
