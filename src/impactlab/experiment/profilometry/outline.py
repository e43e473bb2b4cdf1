"""Geometry of the dent on a height map: gap filling, outlines, Feret diameter, chords, profiles
(the dent's extent extrapolated to the zero threshold from them: :mod:`.extent`).

All lengths in metres; a height map ``zs`` (ny, nx) has row i at y = i dy and column j at
x = j dx.
"""

from __future__ import annotations

import math

import contourpy
import numpy as np
from scipy import ndimage
from scipy.spatial import ConvexHull, QhullError

__all__ = [
    "chord",
    "edges_touched",
    "fall_distance",
    "feret",
    "fill_nan",
    "outline",
    "principal_axis",
    "sample",
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
