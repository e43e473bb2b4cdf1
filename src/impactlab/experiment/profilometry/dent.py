"""The dent on a levelled scan: detection, outline, delta_p, length, width, L_s, pile-up.

Definitions in the package docstring (:mod:`impactlab.experiment.profilometry`); the steps of
:func:`measure_dent`: level the scan, fill dropouts, find the deepest depression above the
detection threshold, outline it, fit its bottom (delta_p), measure length and width at the edge
threshold (extrapolated to the zero threshold when the dent is deep enough), orient the sliding
axis towards the sharper end, estimate the uncertainties, find the pile-up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from impactlab.experiment.errors import DentCutOffError, DentNotFoundError, ScanError
from impactlab.experiment.profilometry.bottom import bottom
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.levelling import Levelled, level_plane
from impactlab.experiment.profilometry.metrics import DentMetrics
from impactlab.experiment.profilometry.outline import (
    chord,
    edges_touched,
    fall_distance,
    feret,
    fill_nan,
    outline,
    sample,
)
from impactlab.experiment.uncertainty import Estimate

__all__ = ["DentMetrics", "measure_dent"]


@dataclass(frozen=True)
class _Surface:
    """The levelled scan: ``zl`` (NaN = no data), ``valid``, ``zs`` (filled and smoothed),
    ``was_nan`` (filled pixels), ``sig_s`` (noise of ``zs`` [m]), ``lev``, pixel sizes, ``src``."""

    zl: np.ndarray
    valid: np.ndarray
    zs: np.ndarray
    was_nan: np.ndarray
    sig_s: float
    lev: Levelled
    dx: float
    dy: float
    src: str


def _surface(hm: HeightMap, smooth: float) -> _Surface:
    lev = level_plane(hm)
    zl = np.asarray(lev.z)
    valid = np.isfinite(zl)
    zf, was_nan = fill_nan(zl)
    zs = ndimage.gaussian_filter(zf, smooth, mode="nearest") if smooth > 0 else zf
    # noise of the smoothed map on the plane's inliers
    r = zs[lev.inliers]
    sig_s = float(1.4826 * np.median(np.abs(r - np.median(r)))) if r.size else lev.sigma
    sig_s = max(sig_s, 1e-15)
    return _Surface(zl, valid, zs, was_nan, sig_s, lev, hm.dx, hm.dy, hm.source or "scan")


def _find(sf: _Surface, detect_sigma: float, min_pixels: int) -> tuple[int, int]:
    """(i, j) of the deepest pixel of the deepest depression below the detection threshold."""
    zs, sig_s, src = sf.zs, sf.sig_s, sf.src
    cand = zs < -detect_sigma * sig_s
    lab, nlab = ndimage.label(cand, structure=np.ones((3, 3)))
    deepest_val = float(np.min(zs))
    if nlab == 0:
        raise DentNotFoundError(
            f"{src}: no dent found: the deepest point is {-deepest_val * 1e6:.3g} um below the "
            f"levelled surface, less than the detection threshold {detect_sigma:g} x noise = "
            f"{detect_sigma * sig_s * 1e6:.3g} um"
        )
    sizes = ndimage.sum(np.ones_like(zs), lab, index=np.arange(1, nlab + 1))
    depths = ndimage.minimum(zs, lab, index=np.arange(1, nlab + 1))
    good = [i for i in range(nlab) if sizes[i] >= min_pixels]
    if not good:
        raise DentNotFoundError(
            f"{src}: no dent found: the depressions below the detection threshold "
            f"({detect_sigma * sig_s * 1e6:.3g} um) cover at most {int(max(sizes))} pixels "
            f"(need {min_pixels}); dust or noise, not a dent"
        )
    best = min(good, key=lambda i: depths[i])
    comp = lab == best + 1
    idx = int(np.argmin(np.where(comp, zs, np.inf)))
    i0, j0 = np.unravel_index(idx, zs.shape)
    return int(i0), int(j0)


def _region(sf: _Surface, ij: tuple[int, int], thr: float) -> np.ndarray:
    """The deformed area: the connected region around ``ij`` deeper than ``thr`` (holes
    filled); DentCutOffError when it reaches the scan's edge."""
    lab2, _ = ndimage.label(sf.zs < -thr, structure=np.ones((3, 3)))
    region = ndimage.binary_fill_holes(lab2 == lab2[ij])
    edges = edges_touched(region)
    if edges:
        raise DentCutOffError(
            f"{sf.src}: the dent is cut off by the scan's {' and '.join(edges)} edge: its outline "
            f"(depth {thr * 1e6:.3g} um) reaches the edge, so its length cannot be measured; "
            "scan a larger area around the dent"
        )
    return np.asarray(region)


@dataclass(frozen=True)
class _Extent:
    """Length, width [m] and the sliding axis (unit vector) of the deformed area; ``length_t``,
    ``width_t`` at the threshold itself; ``extrapolated`` when length and width were
    extrapolated to the zero threshold."""

    length: float
    width: float
    axis: np.ndarray
    length_t: float
    width_t: float
    extrapolated: bool


def _filled(sf: _Surface, region: np.ndarray, max_filled: float, warnings: list[str]) -> float:
    """Fraction of the deformed area filled over dropouts; ScanError above ``max_filled``."""
    filled = float(sf.was_nan[region].mean())
    if filled > max_filled:
        raise ScanError(
            f"{sf.src}: {filled:.0%} of the dent area has no data (dropouts); at "
            f"most {max_filled:.0%} can be interpolated"
        )
    if filled > 0.05:
        warnings.append(f"{filled:.0%} of the dent area was interpolated over dropouts")
    return filled


def _deepest(
    sf: _Surface,
    polygon: np.ndarray,
    ij: tuple[int, int],
    depth_rough: float,
    quad_radius: int,
    warnings: list[str],
) -> tuple[float, float, float, float]:
    """(z_min, its sigma, x, y) [m] of the dent's bottom: the paraboloid fit, else the smoothed
    minimum (with a warning)."""
    i0, j0 = ij
    dx, dy = sf.dx, sf.dy
    q = bottom(sf.zl, sf.valid, sf.lev.sigma, polygon, ij, depth_rough, dx, dy, quad_radius)
    if q is not None:
        return q
    warnings.append("no paraboloid minimum at the deepest point; delta_p is the smoothed minimum")
    return float(sf.zs[i0, j0]), sf.lev.sigma, float(j0 * dx), float(i0 * dy)


def _extent(sf: _Surface, thr: float, depth: float, deepest: np.ndarray) -> _Extent:
    def metrics_at(level: float) -> tuple[float, float, np.ndarray] | None:
        ol = outline(sf.zs, sf.dx, sf.dy, -level, (float(deepest[0]), float(deepest[1])))
        if ol is None:
            return None
        L, ax = feret(ol)
        perp = np.array([-ax[1], ax[0]])
        a, b = chord(ol, deepest, perp)
        return L, a + b, ax

    m1 = metrics_at(thr)
    assert m1 is not None
    length, width, axis = m1
    if not math.isfinite(width):
        raise ScanError(f"{sf.src}: the outline does not cross the line through the deepest point")
    m2 = metrics_at(2.0 * thr) if depth > 4.0 * thr else None
    length_t, width_t = length, width  # at the threshold
    if m2 is not None:
        # the outline shrinks about linearly with the threshold near the dent's edge: extrapolate
        # the length and the width to the threshold 0 (the deformed area's true edge)
        length = 2.0 * length_t - m2[0]
        width = 2.0 * width_t - m2[1]
    return _Extent(length, width, axis, length_t, width_t, m2 is not None)


def _profiles(
    sf: _Surface, deepest: np.ndarray, axis: np.ndarray, length: float, width: float
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """(s, heights) along the axis and (s, heights) across it, through the deepest point [m]."""
    zs, dx, dy = sf.zs, sf.dx, sf.dy
    step = 0.5 * min(dx, dy)
    half_len = length + 2 * width
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
    sc = np.arange(-width * 1.5, width * 1.5 + step, step)
    cl = deepest[None, :] + sc[:, None] * perp[None, :]
    okc = (
        (cl[:, 0] >= 0)
        & (cl[:, 0] <= (zs.shape[1] - 1) * dx)
        & (cl[:, 1] >= 0)
        & (cl[:, 1] <= (zs.shape[0] - 1) * dy)
    )
    sc, cl = sc[okc], cl[okc]
    return s, prof, sc, sample(zs, dx, dy, cl)


def _orient(
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


def _outline_noise(
    sig_s: float,
    s: np.ndarray,
    prof: np.ndarray,
    ends: tuple[float, float],
    sc: np.ndarray,
    cprof: np.ndarray,
    width: float,
) -> tuple[float, float]:
    """Position noise [m] of the outline's crossings along (length) and across (width): the
    height noise over the profiles' slopes there."""
    slope_terms = []
    for sv, pv, targets in ((s, prof, ends), (sc, cprof, (-0.5 * width, 0.5 * width))):
        g = np.gradient(pv, sv)
        for target in targets:
            k = int(np.argmin(np.abs(sv - target)))
            sl = abs(float(g[k]))
            if sl > 0:
                slope_terms.append((sig_s / sl) ** 2)
    noise_len = math.sqrt(sum(slope_terms[:2])) if len(slope_terms) >= 2 else 0.0
    noise_wid = math.sqrt(sum(slope_terms[2:])) if len(slope_terms) >= 4 else 0.0
    return noise_len, noise_wid


def _sigmas(
    ext: _Extent, thr: float, depth: float, noise: tuple[float, float]
) -> tuple[float, float, float]:
    """Standard uncertainties of length, width and L_s [m]: the threshold sensitivity and the
    outline noise."""
    noise_len, noise_wid = noise
    length, width = ext.length, ext.width
    if ext.extrapolated:
        # a quarter of the extrapolation's correction (its non-linearity) and the outline noise,
        # amplified by the extrapolation (2 x1 - x2: about sqrt(5))
        d_len = 0.25 * abs(length - ext.length_t)
        d_wid = 0.25 * abs(width - ext.width_t)
        d_ls = 0.25 * abs((length - width) - (ext.length_t - ext.width_t))
        amp = math.sqrt(5.0)
    else:
        d_len, d_wid, d_ls = abs(0.5 * thr / max(depth, 1e-30) * length), 0.0, 0.0
        amp = 1.0
    sig_len = math.hypot(d_len, amp * noise_len)
    sig_wid = math.hypot(d_wid, amp * noise_wid)
    sig_ls = math.sqrt(d_ls**2 + amp**2 * (noise_len**2 + noise_wid**2))
    return sig_len, sig_wid, sig_ls


def _pileup(
    sf: _Surface, region: np.ndarray, width: float, pileup_band: float
) -> tuple[float, tuple[float, float]]:
    """Height [m] and (x, y) [m] of the highest point in a band around the deformed area."""
    dx, dy, zs = sf.dx, sf.dy, sf.zs
    band_px = max(2, round(pileup_band * width / min(dx, dy)))
    band = ndimage.binary_dilation(region, iterations=band_px) & ~region & sf.valid
    if not band.any():
        return 0.0, (math.nan, math.nan)
    zb = np.where(band, zs, -np.inf)
    kb = int(np.argmax(zb))
    ib, jb = np.unravel_index(kb, zs.shape)
    return max(float(zs[ib, jb]), 0.0), (float(jb * dx), float(ib * dy))


def measure_dent(
    hm: HeightMap,
    *,
    detect_sigma: float = 8.0,
    edge_sigma: float = 3.0,
    edge_fraction: float = 0.02,
    smooth: float = 1.0,
    min_pixels: int = 25,
    quad_radius: int = 4,
    pileup_band: float = 0.5,
    max_filled: float = 0.25,
) -> DentMetrics:
    """Level the scan, find the dent and measure it (definitions in the package docstring).

    Parameters
    ----------
    hm : the scan (:func:`read_scan`).
    detect_sigma : a dent must be deeper than this many noise sigmas (of the smoothed map).
    edge_sigma, edge_fraction : the outline's threshold t_e = max(edge_sigma x smoothed noise,
        edge_fraction x depth).
    smooth : Gaussian smoothing [pixels] for the outline and the profiles (not for delta_p).
    min_pixels : smallest dent area [pixels] (smaller depressions are dust or noise).
    quad_radius : radius [pixels] of the paraboloid fit at the deepest point.
    pileup_band : width of the band around the outline searched for pile-up, x the dent width.
    max_filled : largest fraction of the dent area that may be dropouts (filled by interpolation).

    Raises :class:`DentNotFoundError` (no dent), :class:`DentCutOffError` (the dent reaches the
    scan's edge) or :class:`ScanError`.
    """
    sf = _surface(hm, smooth)
    src, zs, dx, dy, lev = sf.src, sf.zs, sf.dx, sf.dy, sf.lev
    i0, j0 = _find(sf, detect_sigma, min_pixels)
    depth_rough = -float(zs[i0, j0])
    thr = max(edge_sigma * sf.sig_s, edge_fraction * depth_rough)
    region = _region(sf, (i0, j0), thr)
    warnings: list[str] = []
    filled = _filled(sf, region, max_filled, warnings)
    polygon = outline(zs, dx, dy, -thr, (float(j0 * dx), float(i0 * dy)))
    if polygon is None:
        raise ScanError(
            f"{src}: no closed outline around the deepest point at {-thr * 1e6:.3g} "
            "um; the dent is too irregular to measure"
        )
    zmin, zsig, xm, ym = _deepest(sf, polygon, (i0, j0), depth_rough, quad_radius, warnings)
    depth = -zmin
    deepest = np.array([xm, ym])
    ext = _extent(sf, thr, depth, deepest)
    length, width = ext.length, ext.width
    s, prof, sc, cprof = _profiles(sf, deepest, ext.axis, length, width)
    axis, s, prof, d_minus, d_plus, ambiguous = _orient(s, prof, ext.axis, depth)
    # extent along the axis from the outline, for the deepest point's position
    proj = (polygon - deepest) @ axis
    s_start, s_end = float(proj.min()), float(proj.max())
    frac = -s_start / (s_end - s_start) if s_end > s_start else 0.5
    noise = _outline_noise(sf.sig_s, s, prof, (s_start, s_end), sc, cprof, width)
    sig_len, sig_wid, sig_ls = _sigmas(ext, thr, depth, noise)
    if not ext.extrapolated:
        warnings.append(
            "the dent is too shallow to extrapolate its outline to the zero "
            "threshold; length and width are taken at the threshold"
        )
    # fit noise, plus an allowance of a quarter of the noise sigma for the levelling plane and the
    # paraboloid's model error (validated on the synthetic grooves of the tests)
    sig_depth = math.sqrt(zsig**2 + (0.25 * lev.sigma) ** 2)
    pileup, pile_at = _pileup(sf, region, width, pileup_band)
    return DentMetrics(
        delta_p=Estimate(depth, sig_depth, "m"),
        sliding_length=Estimate(length - width, sig_ls, "m"),
        length=Estimate(length, sig_len, "m"),
        width=Estimate(width, sig_wid, "m"),
        deepest=(float(deepest[0]), float(deepest[1])),
        axis=(float(axis[0]), float(axis[1])),
        sliding_angle=math.degrees(math.atan2(axis[1], axis[0])),
        direction_ambiguous=bool(ambiguous),
        end_sharpness=(float(d_minus), float(d_plus)),
        deepest_fraction=float(frac),
        pileup=pileup,
        pileup_at=pile_at,
        outline=polygon,
        edge_threshold=thr,
        noise=lev.sigma,
        plane=lev.plane,
        dropout_fraction=float(1.0 - sf.valid.mean()),
        filled_in_dent=filled,
        profile=(s, prof),
        cross_profile=(sc, cprof),
        levelled=HeightMap(sf.zl, dx, dy, hm.source, {"levelled": True}),
        source=hm.source,
        warnings=tuple(warnings),
    )
