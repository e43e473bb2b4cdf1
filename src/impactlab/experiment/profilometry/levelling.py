"""Levelling a scan: a plane fitted robustly to the surface around the dent, then subtracted."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from impactlab.experiment.checks import check_instance
from impactlab.experiment.profilometry.heightmap import HeightMap

__all__ = [
    "BORDER",
    "K_SIGMA",
    "LEVELLING_DOUBT",
    "LEVELLING_RATIO",
    "NOISE_LAG",
    "Levelled",
    "height_step",
    "lagged_noise",
    "level_plane",
    "levelling_note",
    "step_note",
]


@dataclass(frozen=True)
class Levelled:
    """A levelled height map: ``z`` (ny, nx) [m] (NaN = no data) after subtracting the plane
    ``plane`` = (a, b, c) [m, -, -] (z_plane = a + b x + c y), the ``inliers`` used for the plane,
    the robust noise ``sigma`` [m] of the inliers, ``iterations``; ``lag_sigma`` [m]: the
    inliers' noise from second differences ``NOISE_LAG`` pixels apart (:func:`lagged_noise`),
    which no plane changes; ``step`` [m]: the heights' quantum (:func:`height_step`), whose
    rounding error step / sqrt(12) floors both noises (``rounding``: the robust noise was
    below it)."""

    z: np.ndarray
    plane: tuple[float, float, float]
    inliers: np.ndarray
    sigma: float
    iterations: int
    lag_sigma: float = math.nan
    step: float = 0.0
    rounding: bool = False


#: Outlier threshold [noise sigmas] of the levelling plane's inliers.
K_SIGMA = 3.0
#: The plane's inliers scatter more than this many times their lagged noise (:func:`lagged_noise`):
#: the plane leans on the dent (too little undeformed surface around it) or the surface is not
#: flat. On the example and the synthetic scans with enough margin the ratio is 0.98-1.06 (white
#: noise), up to 1.2 (noise Gaussian-correlated over 3 pixels); with 5 pixels or fewer of surface
#: beyond the dent's outline 3.0-3.8 (delta_p then 2 % deep, about 4 sigma).
LEVELLING_RATIO = 2.5
#: The words that open :func:`levelling_note`: an analysis takes such a dent as a doubt.
LEVELLING_DOUBT = "the levelling is in doubt"
#: Lag [pixels] of the second differences of :func:`lagged_noise`: longer than the correlation of
#: the noise of an optical profilometer that samples finer than its lateral resolution (second
#: differences of neighbours see 1/3 to 1/11 of noise correlated over 1 to 2 pixels).
NOISE_LAG = 8
#: Width of the border frame the first plane is fitted to, as a fraction of the scan's size.
BORDER = 0.12


def level_plane(
    hm: HeightMap,
    *,
    k: float = K_SIGMA,
    border: float = BORDER,
    max_iter: int = 30,
    exclude_dilation: int = 3,
) -> Levelled:
    """Fit and subtract a plane, robustly, so the dent and its pile-up do not bias it.

    Start from the pixels of a border frame (``border`` x the size on each side, outside the dent
    in a centred scan); then iterate: least-squares plane on the inliers, robust sigma of their
    residuals (1.4826 x median absolute deviation), new inliers = pixels within ``k`` sigma,
    with the outliers' neighbourhood (``exclude_dilation`` pixels) excluded too; stop when the
    inlier set no longer changes."""
    check_instance(hm, HeightMap, "hm", "read one with read_scan()")
    z = hm.z
    valid = np.isfinite(z)
    X, Y = hm.coords()
    ny, nx = z.shape
    bx = max(2, int(border * nx))
    by = max(2, int(border * ny))
    frame = np.zeros_like(valid)
    frame[:by, :] = frame[-by:, :] = True
    frame[:, :bx] = frame[:, -bx:] = True
    inl = valid & frame
    step = height_step(z)
    floor = step / math.sqrt(12.0)  # the rounding error of heights read in steps
    if inl.sum() < 20:
        inl = valid.copy()
    coef = np.zeros(3)
    sigma = 0.0
    it = 0
    for it in range(1, max_iter + 1):  # noqa: B007
        A = np.column_stack([np.ones(inl.sum()), X[inl], Y[inl]])
        coef, *_ = np.linalg.lstsq(A, z[inl], rcond=None)
        res = z - (coef[0] + coef[1] * X + coef[2] * Y)
        r_in = res[inl]
        robust = float(1.4826 * np.median(np.abs(r_in - np.median(r_in))))
        # heights in steps coarser than their noise: the MAD is 0 or below the rounding error
        sigma = max(robust, floor) or float(np.std(r_in)) or 1e-15
        out = valid & (np.abs(np.nan_to_num(res)) > k * sigma)
        if exclude_dilation > 0:
            out = ndimage.binary_dilation(out, iterations=exclude_dilation)
        new = valid & ~out
        if new.sum() < 20:
            break
        if np.array_equal(new, inl):
            break
        inl = new
    zl = z - (coef[0] + coef[1] * X + coef[2] * Y)
    zl.setflags(write=False)
    plane = (float(coef[0]), float(coef[1]), float(coef[2]))
    rounding = floor > 0 and not robust > floor
    lag = lagged_noise(z, inl)
    lag = max(lag, floor) if math.isfinite(lag) else lag
    return Levelled(zl, plane, inl, sigma, it, lag, step, rounding)


def height_step(z: np.ndarray) -> float:
    """The quantum [m] of the heights ``z``, for heights that are whole numbers of a Z increment
    (an integer X3P, a sensor's resolution): the smallest difference between two distinct
    finite heights (differences under 1e-9 of their range taken as float rounding), where the
    range holds at most ``_LEVELS_PER_VALUE`` times as many such steps as there are distinct
    heights; 0 otherwise (heights as measured: n values spaced about range / n^2 at the
    closest) and for fewer than two."""
    v = np.unique(z[np.isfinite(z)])
    if v.size < 2:
        return 0.0
    span = float(v[-1] - v[0])
    d = np.diff(v)
    d = d[d > 1e-9 * span]
    if not d.size:
        return 0.0
    step = float(d.min())
    return step if span / step <= _LEVELS_PER_VALUE * v.size else 0.0


#: Heights are taken to come in steps (:func:`height_step`) where their range holds at most this
#: many steps per distinct height: a quantised scan fills most of its levels (a level per value),
#: a measured one has n values whose closest two lie about range / n^2 apart (n steps a value).
_LEVELS_PER_VALUE = 10


def step_note(lev: Levelled) -> str | None:
    """The warning for heights in steps coarser than their noise (``lev.rounding``; None
    otherwise)."""
    if not lev.rounding:
        return None
    return (
        f"the heights come in steps of {lev.step * 1e6:.3g} um, coarser than their noise (an "
        "integer format with a Z increment, or a sensor's height resolution): the noise is "
        f"taken as the rounding error, step / sqrt(12) = {lev.step / math.sqrt(12.0) * 1e6:.3g} "
        "um, in the +- of delta_p (the bottom's height is read to within a step) and of the "
        "outline; a scan with a finer height step (or heights stored as floating point) "
        "measures the dent better"
    )


def lagged_noise(z: np.ndarray, mask: np.ndarray | None = None, lag: int = NOISE_LAG) -> float:
    """The height noise [m] from second differences ``lag`` pixels apart along rows and columns
    (1.4826 MAD / sqrt 6), over the triples of pixels all in ``mask`` (all pixels when None):
    blind to a plane and a tilt, and, ``lag`` pixels apart, to noise correlated over fewer
    pixels; the dent's curvature is left out with it when ``mask`` is the plane's inliers. NaN
    without a valid triple."""
    if isinstance(lag, bool) or not isinstance(lag, int | np.integer) or lag < 1:
        raise ValueError(f"lag must be a whole number of pixels >= 1, got {lag!r}")
    m = np.isfinite(z) if mask is None else np.asarray(mask, bool) & np.isfinite(z)
    L = int(lag)
    parts = []
    for a, ma in ((z, m), (z.T, m.T)):
        if a.shape[1] > 2 * L:
            d = a[:, 2 * L :] - 2 * a[:, L:-L] + a[:, : -2 * L]
            parts.append(d[ma[:, 2 * L :] & ma[:, L:-L] & ma[:, : -2 * L]])
    d = np.concatenate(parts) if parts else np.zeros(0)
    if d.size == 0:
        return math.nan
    return float(1.4826 * np.median(np.abs(d - np.median(d))) / math.sqrt(6.0))


def levelling_note(lev: Levelled) -> str | None:
    """The warning for a plane whose inliers scatter more than ``LEVELLING_RATIO`` times their
    lagged noise (None otherwise)."""
    ratio = lev.sigma / lev.lag_sigma if lev.lag_sigma > 0 else math.nan
    if not ratio > LEVELLING_RATIO:
        return None
    return (
        f"{LEVELLING_DOUBT}: the plane's inliers scatter {lev.sigma * 1e6:.3g} um, "
        f"{ratio:.3g} times their noise from second differences {NOISE_LAG} pixels apart "
        f"({lev.lag_sigma * 1e6:.3g} um): "
        "too little undeformed surface around the dent, so that the plane leans on its flanks "
        "and pile-up (biasing delta_p and L_s beyond their +-), or a surface that is not flat "
        "(curved, a step, waviness over more than a few pixels); scan a larger area around the "
        "dent, with undeformed surface on every side"
    )
