"""The dent's profiles along and across its sliding axis through the deepest point, and the
axis pointed towards the sharper end (the end of the sliding)."""

from __future__ import annotations

import math

import numpy as np

from impactlab.experiment.errors import ScanError
from impactlab.experiment.profilometry.outline import fall_distance, sample
from impactlab.experiment.profilometry.surface import Surface

__all__ = ["MAX_PROFILE_SAMPLES", "orient", "profiles"]

#: The most samples the profiles along and across the dent may take (half a pixel apart): more
#: means pixels far longer one way than the other, a pixel size read wrong.
MAX_PROFILE_SAMPLES = 1_000_000


def profiles(
    sf: Surface, deepest: np.ndarray, axis: np.ndarray, length: float, width: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(s, heights) along the axis and (s, heights) across it, through the deepest point [m]."""
    zs, dx, dy = sf.zs, sf.dx, sf.dy
    step = 0.5 * min(dx, dy)
    half_len, half_cross = length + 2 * width, 1.5 * width
    n = 2.0 * (half_len + half_cross) / step
    if not n <= MAX_PROFILE_SAMPLES:  # pixels far longer one way than the other
        raise ScanError(
            f"{sf.src}: the dent measures {length:.4g} m by {width:.4g} m on pixels of "
            f"{dx:.4g} m x {dy:.4g} m: its profiles, half the smaller pixel apart, would take "
            f"{n:.3g} samples (at most {MAX_PROFILE_SAMPLES:.0e}); check the pixel size"
        )
    s = np.arange(-half_len, half_len + step, step)
    line = deepest[None, :] + s[:, None] * axis[None, :]
    inside = (
        (line[:, 0] >= 0)
        & (line[:, 0] <= (zs.shape[1] - 1) * dx)
        & (line[:, 1] >= 0)
        & (line[:, 1] <= (zs.shape[0] - 1) * dy)
    )
    s, line = s[inside], line[inside]
    prof = sample(zs, dx, dy, line)
    perp = np.array([-axis[1], axis[0]])
    sc = np.arange(-half_cross, half_cross + step, step)
    cl = deepest[None, :] + sc[:, None] * perp[None, :]
    okc = (
        (cl[:, 0] >= 0)
        & (cl[:, 0] <= (zs.shape[1] - 1) * dx)
        & (cl[:, 1] >= 0)
        & (cl[:, 1] <= (zs.shape[0] - 1) * dy)
    )
    sc, cl = sc[okc], cl[okc]
    return s, prof, sc, sample(zs, dx, dy, cl)


def orient(
    s: np.ndarray, prof: np.ndarray, axis: np.ndarray, depth: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float, bool]:
    """Point the axis towards the sharper end (the end of the sliding): (axis, s, profile,
    fall distance at the start, at the end, ambiguous)."""
    fwd = s >= 0
    bwd = s <= 0
    d_plus = fall_distance(s[fwd], prof[fwd], depth)
    d_minus = fall_distance(-s[bwd][::-1], prof[bwd][::-1], depth)
    if math.isfinite(d_plus) and math.isfinite(d_minus) and d_plus > d_minus:
        axis = -axis  # the sharper end lies on the minus side
        s = -s[::-1]
        prof = prof[::-1]
        d_plus, d_minus = d_minus, d_plus
    ambiguous = not (math.isfinite(d_plus) and math.isfinite(d_minus)) or abs(
        d_minus - d_plus
    ) < 0.1 * max(d_minus, d_plus)
    return axis, s, prof, d_minus, d_plus, ambiguous
