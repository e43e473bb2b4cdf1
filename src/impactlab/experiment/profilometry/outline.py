"""Geometry of the dent on a height map: gap filling, outlines, Feret diameter, chords, profiles,
and the dent's extent extrapolated to the zero threshold (:func:`extent`).

All lengths in metres; a height map ``zs`` (ny, nx) has row i at y = i dy and column j at
x = j dx.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import contourpy
import numpy as np
from scipy import ndimage
from scipy.optimize import brentq
from scipy.spatial import ConvexHull, QhullError

__all__ = [
    "Extent",
    "chord",
    "edges_touched",
    "extent",
    "fall_distance",
    "feret",
    "fill_nan",
    "outline",
    "principal_axis",
    "sample",
    "smoothing_sigma",
]


def fill_nan(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fill NaN pixels by normalised convolution (Gaussian-weighted mean of the valid
    neighbours), widening the kernel until every pixel is filled. Returns (filled, was_nan)."""
    nan = ~np.isfinite(z)
    if not nan.any():
        return z.copy(), nan
    w = (~nan).astype(np.float64)
    z0 = np.where(nan, 0.0, z)
    out = z.copy()
    todo = nan.copy()
    s = 1.0
    while todo.any() and s < max(z.shape):
        num = ndimage.gaussian_filter(z0, s, mode="nearest")
        den = ndimage.gaussian_filter(w, s, mode="nearest")
        ok = todo & (den > 0.05)
        out[ok] = num[ok] / den[ok]
        todo &= ~ok
        s *= 2.0
    out[todo] = np.nanmedian(z)
    return out, nan


def outline(
    zs: np.ndarray, dx: float, dy: float, level: float, inside: tuple[float, float]
) -> np.ndarray | None:
    """The closed contour of ``zs`` at ``level`` that encloses the point ``inside`` (x, y) [m]
    (largest such); None if there is none."""
    # matplotlib is a heavy import (~0.3 s) that only the outline needs: imported on use
    from matplotlib.path import Path as MplPath

    ny, nx = zs.shape
    gen = contourpy.contour_generator(
        np.arange(nx) * dx, np.arange(ny) * dy, zs, line_type=contourpy.LineType.Separate
    )
    best, best_area = None, -1.0
    for line in gen.lines(level):
        line = np.asarray(line)
        if line.shape[0] < 4 or not np.allclose(line[0], line[-1]):
            continue
        if not MplPath(line).contains_point(inside):
            continue
        x, y = line[:, 0], line[:, 1]
        area = 0.5 * abs(float(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1))))
        if area > best_area:
            best, best_area = line, area
    return best


def feret(polygon: np.ndarray) -> tuple[float, np.ndarray]:
    """Largest Feret diameter of a polygon [m] and its direction (unit vector)."""
    pts = polygon[:-1] if np.allclose(polygon[0], polygon[-1]) else polygon
    try:
        hull = pts[ConvexHull(pts).vertices]
    except QhullError:  # degenerate (collinear) polygon: all its points
        hull = pts
    d = hull[:, None, :] - hull[None, :, :]
    dist = np.einsum("ijk,ijk->ij", d, d)
    i, j = np.unravel_index(int(np.argmax(dist)), dist.shape)
    vec = hull[j] - hull[i]
    length = float(np.linalg.norm(vec))
    return length, vec / length


def principal_axis(polygon: np.ndarray) -> np.ndarray | None:
    """Unit vector of the long principal axis of the area a closed polygon (k, 2) [m] encloses
    (the eigenvector of its second moments of area about the centroid with the larger
    eigenvalue); None for a polygon without area or whose two moments are equal (a circle).

    The moments integrate over the whole outline, so the outline's noise averages out: on a
    nearly round dent (length 1.07 x width) this direction scatters by about 0.01 deg, where
    the direction of the largest Feret diameter, set by two outline points, scatters by 1-3 deg."""
    x, y = polygon[:, 0], polygon[:, 1]
    if not np.allclose(polygon[0], polygon[-1]):
        x, y = np.append(x, x[0]), np.append(y, y[0])
    x0, y0 = x[:-1] - x.mean(), y[:-1] - y.mean()  # about a nearby point: no cancellation
    x1, y1 = x[1:] - x.mean(), y[1:] - y.mean()
    cross = x0 * y1 - x1 * y0
    area = 0.5 * float(cross.sum())
    if not abs(area) > 0:
        return None
    cx = float(((x0 + x1) * cross).sum()) / (6.0 * area)
    cy = float(((y0 + y1) * cross).sum()) / (6.0 * area)
    ixx = float(((x0 * x0 + x0 * x1 + x1 * x1) * cross).sum()) / 12.0 - area * cx * cx
    iyy = float(((y0 * y0 + y0 * y1 + y1 * y1) * cross).sum()) / 12.0 - area * cy * cy
    ixy = (
        float(((x0 * y1 + 2.0 * x0 * y0 + 2.0 * x1 * y1 + x1 * y0) * cross).sum()) / 24.0
        - area * cx * cy
    )
    vals, vecs = np.linalg.eigh(np.sign(area) * np.array([[ixx, ixy], [ixy, iyy]]))
    if not vals[1] - vals[0] > 1e-9 * abs(vals[1]):
        return None
    return np.asarray(vecs[:, 1], dtype=np.float64)


def chord(polygon: np.ndarray, point: np.ndarray, direction: np.ndarray) -> tuple[float, float]:
    """Distances (negative side, positive side) from ``point`` along ``direction`` to the nearest
    crossings of the closed polygon ``polygon``."""
    p0 = polygon[:-1] - point
    p1 = polygon[1:] - point
    n = np.array([-direction[1], direction[0]])
    s0 = p0 @ n
    s1 = p1 @ n
    cross = (s0 == 0) | (s0 * s1 < 0)
    if not cross.any():
        return math.nan, math.nan
    f = s0[cross] / (s0[cross] - s1[cross])
    pts = p0[cross] + f[:, None] * (p1[cross] - p0[cross])
    t = pts @ direction
    neg = t[t < 0]
    pos = t[t >= 0]
    return (float(-neg.max()) if neg.size else math.nan, float(pos.min()) if pos.size else math.nan)


def sample(zs: np.ndarray, dx: float, dy: float, pts: np.ndarray) -> np.ndarray:
    """Bilinear samples of ``zs`` at the points ``pts`` (k, 2) (x, y) [m]."""
    return ndimage.map_coordinates(zs, [pts[:, 1] / dy, pts[:, 0] / dx], order=1, mode="nearest")


def fall_distance(s: np.ndarray, z: np.ndarray, depth: float) -> float:
    """Distance along a profile (s >= 0 from the deepest point, z heights) over which the depth
    falls from 80 % to 20 % of ``depth`` (first crossings)."""
    d = -z

    def first_below(level: float) -> float:
        idx = np.flatnonzero(d < level)
        if idx.size == 0:
            return math.nan
        k = int(idx[0])
        if k == 0:
            return float(s[0])
        f = (d[k - 1] - level) / (d[k - 1] - d[k])
        return float(s[k - 1] + f * (s[k] - s[k - 1]))

    return first_below(0.2 * depth) - first_below(0.8 * depth)


def edges_touched(region: np.ndarray) -> list[str]:
    """Names of the scan edges that the boolean ``region`` touches."""
    names = []
    if region[:, 0].any():
        names.append("left (x = 0)")
    if region[:, -1].any():
        names.append("right (x max)")
    if region[0, :].any():
        names.append("bottom (y = 0)")
    if region[-1, :].any():
        names.append("top (y max)")
    return names


# --- the extent extrapolated to the zero threshold ---------------------------------------------
#
# The outlines lie on the smoothed map. The smoothing (``smooth`` pixels: sigma_n = smooth x the
# pixel along the edge's normal, different along x and y on rectangular pixels) rounds the kink
# where the dent meets the surface: an outline less than ~1.5 sigma_n inside the edge moves out
# (a flat surface beyond) or in (a pile-up) by up to ~sigma_n, and the extrapolation to the zero
# threshold carries that on (+50 um of length and width at 25 um pixels). Where it would, the
# levels move to 2 sigma_n inside the edge (depth 2 k sigma_n, k the edge's slope; the outline
# there is the unsmoothed one within 0.01 sigma_n); so that the dent's own curvature does not bias
# the longer extrapolation from there, the length is extrapolated quadratically (3 levels) and
# the width's square linearly (exact across a paraboloid).

#: The levels move inwards when the edge threshold lies less than this many sigmas inside ...
_SMOOTHED_SIGMAS = 1.5
#: ... to this many.
_INSIDE_SIGMAS = 2.0
#: The deepest level (3 t1 for the length, 2 t1 for the width) reaches at most this fraction
#: of the depth.
_DEEPEST_FRACTION = 0.6

#: (length, width [m], long axis, outline) of the outline at one level; None when lost.
LevelMetrics = tuple[float, float, np.ndarray, np.ndarray]


@dataclass(frozen=True)
class Extent:
    """Length, width [m] and the sliding axis (unit vector) of the deformed area, ``extrapolated``
    to the zero threshold or not; ``outlines`` measured (x, y) [m], those at thr and 2 thr first;
    ``levels`` t1 [m] of the length's and the width's extrapolation (from t1 and 2 t1, and 3 t1
    for the length where t1 > thr); ``model``: its model errors of length, width and L_s [m];
    ``noise_gain``: its gains on their outline noise (sqrt(5) linear, sqrt(19) quadratic)."""

    length: float
    width: float
    axis: np.ndarray
    extrapolated: bool
    outlines: tuple[np.ndarray, ...] = ()
    levels: tuple[float, float] = (0.0, 0.0)
    model: tuple[float, float, float] = (0.0, 0.0, 0.0)
    noise_gain: tuple[float, float] = (1.0, 1.0)


def smoothing_sigma(dx: float, dy: float, smooth: float, direction: np.ndarray) -> float:
    """Sigma [m] along the unit vector ``direction`` of a Gaussian of ``smooth`` pixels on
    pixels ``dx`` x ``dy`` [m] (sigma smooth dx along x, smooth dy along y)."""
    return smooth * math.hypot(dx * float(direction[0]), dy * float(direction[1]))


def _kink_at(y: float) -> float:
    """Where, in sigmas inside the edge, a kink (depth k u at u inside its edge, 0 outside)
    smoothed by a Gaussian of sigma reaches the depth y k sigma."""

    def depth(v: float) -> float:
        return math.exp(-0.5 * v * v) / math.sqrt(2 * math.pi) + 0.5 * v * math.erfc(-v / 2**0.5)

    return float(brentq(lambda v: depth(v) - y, -40.0, y + 10.0, xtol=1e-12))


def _kink_bias(shrink: float, sig: float) -> float:
    """The outward bias [m] of a length extrapolated linearly from thr and 2 thr across two
    kinked edges smoothed by sigma ``sig`` [m], from its ``shrink`` [m] between the two."""
    per_edge = 0.5 * shrink / sig  # = kink_at(2 y) - kink_at(y), y = thr / (k sig)
    if not per_edge > 0:
        return 0.0
    lo, hi = 1e-9, per_edge + 10.0

    def miss(u: float) -> float:
        return _kink_at(2.0 * u) - _kink_at(u) - per_edge

    if not miss(hi) > 0:
        return 0.0
    y = lo if miss(lo) >= 0 else float(brentq(miss, lo, hi))
    # the edge seen at thr lies y - kink_at(y) sigmas outside its unsmoothed place
    return 2.0 * sig * abs(2.0 * (y - _kink_at(y)) - (2.0 * y - _kink_at(2.0 * y)))


def _metrics_at(
    zs: np.ndarray, dx: float, dy: float, level: float, deepest: np.ndarray
) -> LevelMetrics | None:
    """Length (Feret), width (the chord through ``deepest`` across the outline's principal
    axis, else its Feret direction), axis and outline at depth ``level`` [m]."""
    ol = outline(zs, dx, dy, -level, (float(deepest[0]), float(deepest[1])))
    if ol is None:
        return None
    L, ax = feret(ol)
    principal = principal_axis(ol)  # the outline's long axis: far less noisy than Feret's
    ax = ax if principal is None else principal
    a, b = chord(ol, deepest, np.array([-ax[1], ax[0]]))
    return L, a + b, ax, ol


def _edge_level(
    at: Callable[[float], LevelMetrics | None], k: int, thr: float, depth: float, sig: float
) -> float:
    """The first level t1 [m] of quantity ``k`` (0 length, 1 width): the threshold ``thr``, or
    ``_INSIDE_SIGMAS`` smoothing sigmas ``sig`` [m] inside the edge (the edge's slope from the
    outlines at t1 and 2 t1, iterated); inf when that lies too deep or loses the outline."""
    t = thr
    for _ in range(3):
        a, b = at(t), at(2.0 * t)
        if a is None or b is None:
            return math.inf
        shrink = float(a[k]) - float(b[k])  # both edges move by t / slope
        if not shrink > 0:
            return t
        slope = 2.0 * t / shrink
        if t == thr and not _SMOOTHED_SIGMAS * slope * sig > thr:
            return thr
        want = _INSIDE_SIGMAS * slope * sig
        if not want > 1.05 * t:
            return t
        if not (3 - k) * want <= _DEEPEST_FRACTION * depth:
            return math.inf
        t = want
    return t


def extent(
    zs: np.ndarray,
    dx: float,
    dy: float,
    thr: float,
    depth: float,
    deepest: np.ndarray,
    smooth: float,
    levels: tuple[float, float] | None = None,
) -> Extent | None:
    """The dent's extent on the map ``zs`` smoothed by ``smooth`` pixels: its outline at the
    edge threshold ``thr`` [m] around the deepest point ``deepest`` (x, y) [m], extrapolated to
    the zero threshold when the dent (``depth`` [m]) is deeper than 4 thr: linearly from thr and
    2 thr where the smoothing leaves the outline there alone, else quadratically from levels
    2 smoothing sigmas inside the edge (the module's notes); ``levels`` (t1 of length and
    width) fixes those (a map changed in a gap). None when the outline at thr is lost or does
    not cross the line through ``deepest``."""
    cache: dict[float, LevelMetrics | None] = {}

    def at(t: float) -> LevelMetrics | None:
        if t not in cache:
            cache[t] = _metrics_at(zs, dx, dy, t, deepest)
        return cache[t]

    m1 = at(thr)
    if m1 is None or not math.isfinite(m1[1]):
        return None
    L1, W1, axis, ol1 = m1
    m2 = at(2.0 * thr) if depth > 4.0 * thr else None
    if m2 is None:
        return Extent(L1, W1, axis, False, (ol1,))
    perp = np.array([-axis[1], axis[0]])
    sig = (smoothing_sigma(dx, dy, smooth, axis), smoothing_sigma(dx, dy, smooth, perp))
    if levels is None:
        levels = (_edge_level(at, 0, thr, depth, sig[0]), _edge_level(at, 1, thr, depth, sig[1]))
    rows: list[_Extrapolated] = []
    outlines = [ol1, m2[3]]
    for k, t in enumerate(levels):
        n = 3 - k  # the length from t1, 2 t1 and 3 t1; the width from t1 and 2 t1
        ms = [at(m * t) for m in range(1, n + 1)] if math.isfinite(t) and t != thr else []
        got = [m for m in ms if m is not None]
        if ms and len(got) == n:
            rows.append(_inside([float(m[k]) for m in got], sig, float(W1)))
            outlines += [m[3] for m in got]
        else:
            rows.append(_linear(float(m1[k]), float(m2[k]), t != thr, sig[k]))
    if rows[0][2] != rows[1][2] and abs(sig[0] - sig[1]) <= 0.1 * max(sig):
        # one from inside, one not, under the same smoothing (square pixels): both at thr and
        # 2 thr, where their biases are alike and cancel in L_s = length - width (a noisy edge
        # can make one look shallow and the other not)
        rows = [_linear(float(m1[k]), float(m2[k]), False, sig[k]) for k in (0, 1)]
    (L0, d_len, in_len, k_len), (W0, d_wid, in_wid, k_wid) = rows
    # L_s: the threshold's non-linearity where length and width share it (a quarter of the
    # difference of their corrections at thr), the model errors of those from inside, and the
    # smoothing's shifts where it could not be escaped
    shared = 0.25 * abs((float(m1[0]) - float(m2[0])) - (float(m1[1]) - float(m2[1])))
    inner = [d for d, i in ((d_len, in_len), (d_wid, in_wid)) if i]
    d_ls = math.sqrt(shared**2 + sum(d * d for d in inner) + (k_len - k_wid) ** 2)
    t1 = (float(levels[0]), float(levels[1]))
    # the gains on the outline noise: 3 x1 - 3 x2 + x3, 2 x1 - x2 (the width's square alike)
    gain = (math.sqrt(19.0) if in_len else math.sqrt(5.0), math.sqrt(5.0))
    return Extent(L0, W0, axis, True, tuple(outlines), t1, (d_len, d_wid, d_ls), gain)


#: (value [m], model error [m], from levels inside the edge, the smoothing's shift in it [m])
_Extrapolated = tuple[float, float, bool, float]


def _inside(x: list[float], sig: tuple[float, float], width: float) -> _Extrapolated:
    """A length ``x`` [m] at levels t1, 2 t1, 3 t1 (the length: quadratic) or at t1, 2 t1 (the
    width: its square linear, as across a paraboloid) extrapolated to the level 0; its model
    error: a quarter of its difference from the linear extrapolation and the smoothing's lift
    of a dent curved like the tip (radius R, lifted by sigma^2 / R: its edge moves in by about
    2 (sigma_along^2 + sigma_across^2) / ``width``, the smoothing sigmas ``sig`` [m])."""
    if len(x) == 3:
        value = 3.0 * x[0] - 3.0 * x[1] + x[2]
    else:
        value = math.sqrt(max(2.0 * x[0] ** 2 - x[1] ** 2, 0.0))
    lift = 2.0 * (sig[0] ** 2 + sig[1] ** 2) / max(width, 1e-30)
    return value, math.hypot(0.25 * (value - (2.0 * x[0] - x[1])), lift), True, 0.0


def _linear(x1: float, x2: float, too_deep: bool, sig: float) -> _Extrapolated:
    """Linear extrapolation of a length at thr (``x1`` [m]) and 2 thr (``x2``) to the level 0
    (the outline shrinks about linearly with the threshold near the edge); its model error: a
    quarter of the correction (its non-linearity), and when the levels inside lie too deep
    (``too_deep``) the shift that a smoothing of sigma ``sig`` [m] gives a kinked edge at thr
    and 2 thr."""
    value = 2.0 * x1 - x2
    kink = _kink_bias(x1 - x2, sig) if too_deep else 0.0
    return value, math.hypot(0.25 * (value - x1), kink), False, kink
