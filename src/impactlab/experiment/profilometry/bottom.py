"""The bottom of the dent: delta_p from a paraboloid fitted around the deepest pixel.

The fit's disc is as wide as the bottom's curvature allows (radius R_c ~ width^2 / (8 depth), a
spherical cap, rising ~10 noise sigmas above the noise), so the noise does not bias the minimum;
the fit is recentred when its minimum falls outside the disc.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.experiment.profilometry.outline import chord, feret
from impactlab.experiment.uncertainty import propagate

__all__ = ["bottom", "quadric_min"]


def quadric_min(
    zl: np.ndarray,
    valid: np.ndarray,
    i0: int,
    j0: int,
    dx: float,
    dy: float,
    radius: int,
    recentre: bool = False,
) -> tuple[float, float, float, float, bool] | None:
    """Minimum of a paraboloid fitted to the valid pixels within ``radius`` of (i0, j0): returns
    (z_min, sigma, x_min, y_min, inside) or None when the fit has no minimum (not convex);
    ``inside`` is False when the minimum lies outside the fitted disc (then, with ``recentre``,
    the caller may refit there)."""
    ny, nx = zl.shape
    i_lo, i_hi = max(0, i0 - radius), min(ny, i0 + radius + 1)
    j_lo, j_hi = max(0, j0 - radius), min(nx, j0 + radius + 1)
    ii, jj = np.mgrid[i_lo:i_hi, j_lo:j_hi]
    sel = valid[i_lo:i_hi, j_lo:j_hi] & ((ii - i0) ** 2 + (jj - j0) ** 2 <= radius * radius)
    if sel.sum() < 10:
        return None
    u = (jj[sel] - j0) * dx
    v = (ii[sel] - i0) * dy
    zz = zl[i_lo:i_hi, j_lo:j_hi][sel]
    A = np.column_stack([np.ones_like(u), u, v, u * u, u * v, v * v])
    coef, *_ = np.linalg.lstsq(A, zz, rcond=None)
    res = zz - A @ coef
    s2 = float(res @ res) / max(zz.size - 6, 1)
    cov = s2 * np.linalg.pinv(A.T @ A)

    def zmin(c: np.ndarray) -> np.ndarray:
        H = np.array([[2 * c[3], c[4]], [c[4], 2 * c[5]]])
        xy = np.linalg.solve(H, -c[1:3])
        return np.array([c[0] + 0.5 * c[1:3] @ xy, xy[0], xy[1]])

    H = np.array([[2 * coef[3], coef[4]], [coef[4], 2 * coef[5]]])
    if np.any(np.linalg.eigvalsh(H) <= 0):
        return None
    y0, cy = propagate(zmin, coef, cov)
    r_max = radius * min(dx, dy)
    inside = math.hypot(y0[1], y0[2]) <= r_max
    if not inside and not recentre:
        return None
    return (
        float(y0[0]),
        float(math.sqrt(max(cy[0, 0], 0.0))),
        j0 * dx + float(y0[1]),
        i0 * dy + float(y0[2]),
        inside,
    )


def bottom(
    zl: np.ndarray,
    valid: np.ndarray,
    noise: float,
    polygon: np.ndarray,
    ij: tuple[int, int],
    depth_rough: float,
    dx: float,
    dy: float,
    quad_radius: int,
) -> tuple[float, float, float, float] | None:
    """(z_min [m], its sigma [m], x, y [m]) of the paraboloid at the deepest pixel ``ij`` of the
    levelled map ``zl`` (``valid`` pixels; ``noise`` its sigma [m]) inside the outline
    ``polygon``; None when no disc gives a paraboloid with its minimum inside."""
    i0, j0 = ij
    p_rough = (float(j0 * dx), float(i0 * dy))
    _, ax0 = feret(polygon)
    a0, b0 = chord(polygon, np.array(p_rough), np.array([-ax0[1], ax0[0]]))
    w0 = (a0 + b0) if math.isfinite(a0 + b0) else 0.0
    r_c = w0 * w0 / (8.0 * max(depth_rough, 1e-12)) if w0 > 0 else 0.0
    rad_phys = math.sqrt(20.0 * r_c * noise) if r_c > 0 else 0.0
    rad0 = int(min(max(quad_radius, math.ceil(rad_phys / min(dx, dy))), 40))
    q = None
    for rad in (rad0, 2 * rad0, 3 * rad0):
        ic, jc = int(i0), int(j0)
        for _ in range(3):
            q = quadric_min(zl, valid, ic, jc, dx, dy, rad, recentre=True)
            if q is None or q[4]:
                break
            ic = min(max(round(q[3] / dy), 0), zl.shape[0] - 1)
            jc = min(max(round(q[2] / dx), 0), zl.shape[1] - 1)
        if q is not None and q[4]:
            break
        q = None
    return None if q is None else q[:4]
