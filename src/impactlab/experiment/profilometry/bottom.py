"""The bottom of the dent: delta_p from a paraboloid fitted around the deepest pixel.

The fit's disc is as wide as the bottom's curvature allows (radius R_c ~ width^2 / (8 depth), a
spherical cap, rising ~10 noise sigmas above the noise), so the noise does not bias the minimum;
the fit is recentred when its minimum falls outside the disc. The disc is a disc in metres: on
pixels longer one way than the other it spans fewer pixels along the longer side (an ellipse
in pixel indices), so it never reaches past the bottom along the coarse axis.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.experiment.profilometry.outline import chord, feret
from impactlab.experiment.uncertainty import propagate

__all__ = ["bottom", "quadric_min"]

#: The bottom counts as flat along one direction (a trough) when the paraboloid's smaller
#: curvature lies within this many of its sigmas of zero.
_FLAT_SIGMAS = 3.0


#: A pixel whose residual from the fitted paraboloid exceeds this many robust sigmas is a
#: spike, left out of the fit (Gaussian noise reaches it once in 10^15 pixels).
_SPIKE_SIGMAS = 8.0


def _not_spikes(res: np.ndarray) -> np.ndarray:
    """The residuals ``res`` [m] of a fit that are not spikes: within ``_SPIKE_SIGMAS`` robust
    sigmas (1.4826 MAD, at least 0.3 of the RMS, for heights in coarse steps) of zero."""
    mad = 1.4826 * float(np.median(np.abs(res - np.median(res))))
    rms = float(np.sqrt(np.mean(res * res)))
    return np.abs(res) <= _SPIKE_SIGMAS * max(mad, 0.3 * rms, 1e-15)


def quadric_min(
    zl: np.ndarray,
    valid: np.ndarray,
    i0: int,
    j0: int,
    dx: float,
    dy: float,
    radius: float,
    recentre: bool = False,
) -> tuple[float, float, float, float, bool] | None:
    """Minimum of a paraboloid fitted to the valid pixels within ``radius`` [m] of the pixel
    (i0, j0) (a disc in metres: an ellipse in pixel indices when dx != dy): returns
    (z_min, sigma, x_min, y_min, inside) or None when the fit has no minimum (not convex);
    ``inside`` is False when the minimum lies outside the fitted disc (then, with ``recentre``,
    the caller may refit there)."""
    ny, nx = zl.shape
    unit = min(dx, dy)  # the disc in units of the smaller pixel: exact integers on square ones
    ay, ax, rad = dy / unit, dx / unit, radius / unit
    ri, rj = math.floor(rad / ay + 1e-9), math.floor(rad / ax + 1e-9)
    i_lo, i_hi = max(0, i0 - ri), min(ny, i0 + ri + 1)
    j_lo, j_hi = max(0, j0 - rj), min(nx, j0 + rj + 1)
    ii, jj = np.mgrid[i_lo:i_hi, j_lo:j_hi]
    dist2 = ((ii - i0) * ay) ** 2 + ((jj - j0) * ax) ** 2
    sel = valid[i_lo:i_hi, j_lo:j_hi] & (dist2 <= rad * rad * (1.0 + 1e-9))
    if sel.sum() < 10:
        return None
    # coordinates in units of the radius: a well-conditioned fit and covariance (in metres,
    # the columns 1, u, u^2 span 8 orders of magnitude and A^T A loses the covariance)
    u = (jj[sel] - j0) * (dx / radius)
    v = (ii[sel] - i0) * (dy / radius)
    zz = zl[i_lo:i_hi, j_lo:j_hi][sel]
    A = np.column_stack([np.ones_like(u), u, v, u * u, u * v, v * v])
    coef, *_ = np.linalg.lstsq(A, zz, rcond=None)
    res = zz - A @ coef
    keep = _not_spikes(res)
    if not keep.all() and keep.sum() >= 10:  # a spike (dust, a dropout): fitted without it
        A, zz = A[keep], zz[keep]
        coef, *_ = np.linalg.lstsq(A, zz, rcond=None)
        res = zz - A @ coef
    s2 = float(res @ res) / max(zz.size - 6, 1)
    cov = s2 * np.linalg.pinv(A.T @ A)

    def hessian(c: np.ndarray) -> np.ndarray:
        return np.array([[2 * c[3], c[4]], [c[4], 2 * c[5]]])

    def zmin(c: np.ndarray) -> np.ndarray:
        xy = np.linalg.solve(hessian(c), -c[1:3])
        return np.array([c[0] + 0.5 * c[1:3] @ xy, xy[0], xy[1]])

    def zmin_across(c: np.ndarray) -> np.ndarray:
        # a trough: the minimum across it (the curved direction) through the disc's centre
        lam, vec = np.linalg.eigh(hessian(c))
        t = -float(c[1:3] @ vec[:, 1]) / lam[1]
        return np.array([c[0] + 0.5 * t * float(c[1:3] @ vec[:, 1]), t * vec[0, 1], t * vec[1, 1]])

    lam = np.linalg.eigvalsh(hessian(coef))
    if lam[1] <= 0:
        return None
    _, c_lam = propagate(lambda c: np.linalg.eigvalsh(hessian(c))[:1], coef, cov)
    sig_lam = math.sqrt(max(float(c_lam[0, 0]), 0.0))
    if lam[0] <= -_FLAT_SIGMAS * sig_lam:
        return None  # a saddle
    # flat along the bottom within the noise (a groove dragged at a constant depth): the
    # minimum along it is noise, and a paraboloid's minimum there would run deep
    y0, cy = propagate(zmin if lam[0] >= _FLAT_SIGMAS * sig_lam else zmin_across, coef, cov)
    inside = math.hypot(y0[1], y0[2]) <= 1.0
    if not inside and not recentre:
        return None
    return (
        float(y0[0]),
        float(math.sqrt(max(cy[0, 0], 0.0))),
        j0 * dx + float(y0[1]) * radius,
        i0 * dy + float(y0[2]) * radius,
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
    ``polygon``, on pixels ``dx`` x ``dy`` [m]; the disc's radius is at least ``quad_radius``
    pixels of the longer side; None when no disc gives a paraboloid with its minimum inside."""
    i0, j0 = ij
    p_rough = (float(j0 * dx), float(i0 * dy))
    _, ax0 = feret(polygon)
    a0, b0 = chord(polygon, np.array(p_rough), np.array([-ax0[1], ax0[0]]))
    w0 = (a0 + b0) if math.isfinite(a0 + b0) else 0.0
    r_c = w0 * w0 / (8.0 * max(depth_rough, 1e-12)) if w0 > 0 else 0.0
    rad_phys = math.sqrt(20.0 * r_c * noise) if r_c > 0 else 0.0
    # at least quad_radius pixels along the longer pixel side, at most a disc of as many pixels
    # as one of 40 square pixels' radius; on square pixels a whole number of pixels
    unit = min(dx, dy)
    rad0 = max(quad_radius * max(dx, dy), math.ceil(rad_phys / unit) * unit)
    rad0 = min(rad0, 40.0 * math.sqrt(dx * dy))
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
