"""The levelled surface of a scan and the dent on it: where it is, its area, its dropouts.

:func:`find_dent` also checks the sign of the heights: a scan whose largest feature is a bump,
much higher than the deepest depression is deep, is a scan with depths stored as positive
heights (sign-flipped), refused with the option that reads it the other way up.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from impactlab.experiment.errors import DentCutOffError, DentNotFoundError, ScanError
from impactlab.experiment.profilometry.height_values import check_height_values
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.levelling import Levelled, level_plane, levelling_note
from impactlab.experiment.profilometry.outline import edges_touched, fill_nan

__all__ = ["Surface", "dent_region", "filled_fraction", "find_dent", "surface"]


@dataclass(frozen=True)
class Surface:
    """The levelled scan: ``zl`` (NaN = no data), ``valid``, ``zs`` (filled and smoothed),
    ``was_nan`` (filled pixels), ``sig_s`` (noise of ``zs`` [m]), ``lev``, pixel sizes, ``src``;
    ``zo``: ``zs`` without its pits (:func:`_without_pits`), the map the dent's outlines and
    extent are drawn on (None: ``zs``, which has none)."""

    zl: np.ndarray
    valid: np.ndarray
    zs: np.ndarray
    was_nan: np.ndarray
    sig_s: float
    lev: Levelled
    dx: float
    dy: float
    src: str
    zo: np.ndarray | None = None

    @property
    def outline_map(self) -> np.ndarray:
        """The smoothed map the outlines are drawn on: ``zo``, else ``zs``."""
        return self.zs if self.zo is None else self.zo


def surface(hm: HeightMap, smooth: float) -> Surface:
    """The levelled scan, filled over dropouts and smoothed by ``smooth`` pixels;
    FileFormatError for corrupt heights (:func:`check_height_values`)."""
    check_height_values(hm)
    lev = level_plane(hm)
    zl = np.asarray(lev.z)
    valid = np.isfinite(zl)
    zf, was_nan = fill_nan(zl)
    zs = ndimage.gaussian_filter(zf, smooth, mode="nearest") if smooth > 0 else zf
    clean = _without_pits(zf, lev.sigma)
    zo = None
    if clean is not zf:
        zo = ndimage.gaussian_filter(clean, smooth, mode="nearest") if smooth > 0 else clean
    # noise of the smoothed map on the plane's inliers
    r = zs[lev.inliers]
    sig_s = float(1.4826 * np.median(np.abs(r - np.median(r)))) if r.size else lev.sigma
    # heights in steps coarser than their noise: the smoothing does not average the rounding
    # out where every pixel around rounds alike (a flat surface, a dent's bottom)
    sig_s = max(sig_s, lev.step / math.sqrt(12.0), 1e-15)
    return Surface(zl, valid, zs, was_nan, sig_s, lev, hm.dx, hm.dy, hm.source or "scan", zo)


#: A pixel this many noise sigmas below the median of the 5 x 5 pixels around it is a pit (dust,
#: a dropout on a steep flank): the smoothed map, on which the outline is drawn, takes that median
#: instead (a tip's dent is smooth at the pixel scale: its 5 x 5 median is the pixel's own height
#: to its curvature, far below this).
PIT_SIGMAS = 8.0


def _without_pits(z: np.ndarray, noise: float) -> np.ndarray:
    """``z`` with its pits (:data:`PIT_SIGMAS`: up to a few pixels across) set to the median of
    the 5 x 5 pixels around them, so that no pit touching the dent's edge joins its outline
    (``z`` itself where it has none). The dent is found, and its deepest point taken, on the map
    with them (a pit there is named, or is the only depression)."""
    med = ndimage.median_filter(z, size=5, mode="nearest")
    pits = med - z > PIT_SIGMAS * max(noise, 1e-15)
    if not pits.any():
        return z
    return np.where(pits, med, z)


def _components(mask: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(labels, label indices, sizes [pixels]) of the 8-connected components of ``mask``."""
    lab, n = ndimage.label(mask, structure=np.ones((3, 3)))
    index = np.arange(1, n + 1)
    return lab, index, np.asarray(ndimage.sum(np.ones(mask.shape), lab, index=index))


def _check_sign(
    sf: Surface, depth: float, volume: float, detect_sigma: float, min_pixels: int
) -> None:
    """ScanError when the largest bump above the detection threshold is more than twice as high
    as the dent (``depth`` [m]) is deep and holds at least half its ``volume`` [m^3] (a dust
    grain is high but small; a pile-up is wide but low): a sign-flipped scan."""
    lab, index, sizes = _components(sf.zs > detect_sigma * sf.sig_s)
    good = sizes >= min_pixels
    if not good.any():
        return
    volumes = np.asarray(ndimage.sum(sf.zs, lab, index=index)) * sf.dx * sf.dy
    k = int(np.argmax(np.where(good, volumes, -np.inf)))
    height = float(ndimage.maximum(sf.zs, lab, index=index[k]))
    if height > 2.0 * depth and volumes[k] > 0.5 * volume:
        raise ScanError(
            f"{sf.src}: the scan's largest feature is a bump {height * 1e6:.3g} um high, not a "
            f"dent (its deepest depression is {depth * 1e6:.3g} um deep): the heights look "
            "sign-flipped (depths stored as positive heights); if so, read the scan the other "
            "way up: analyze(..., flip_heights=True) (impactlab analyze --flip-heights) or "
            "measure_dent(height_map.flipped()); if it was turned over already "
            "(flip_heights=True, --flip-heights), leave that out"
        )


def _depression_pixels(sf: Surface, lab: np.ndarray, index: np.ndarray, level: float) -> np.ndarray:
    """Measured pixels of each component (labels ``lab``, ``index``) that the unsmoothed
    levelled scan puts below ``level`` [m]; a pixel without data never counts (the filled map
    only continues its neighbours into it: no-data pixels cannot make a dent)."""
    deep = sf.valid & (sf.zl < level)
    return np.asarray(ndimage.sum(deep, lab, index=index))


def _candidates_note(
    sf: Surface,
    lab: np.ndarray,
    index: np.ndarray,
    good: list[int],
    best: int,
    depths: np.ndarray,
    pixels: np.ndarray,
    volumes: np.ndarray,
) -> str:
    """The warning for a scan with more than one depression that qualifies as a dent (the
    measured one, ``best``, first)."""
    where = []
    for i in sorted(good, key=lambda i: -volumes[i])[:_NAMED]:
        k = int(np.argmin(np.where(lab == index[i], sf.zs, np.inf)))
        r, c = np.unravel_index(k, sf.zs.shape)
        mark = " (measured)" if i == best else ""
        where.append(
            f"at x = {c * sf.dx * 1e3:.3g} mm, y = {r * sf.dy * 1e3:.3g} mm: "
            f"{-depths[i] * 1e6:.3g} um deep, {int(pixels[i])} pixels{mark}"
        )
    more = f" and {len(good) - _NAMED} more" if len(good) > _NAMED else ""
    return (
        f"{len(good)} depressions qualify as a dent ({'; '.join(where)}{more}); the one of the "
        "largest volume is measured (one dent per scan): crop the scan to the dent to measure "
        "another"
    )


#: At most this many depressions are named in the warning of more than one.
_NAMED = 4


def _shallow(sf: Surface, deepest: float, detect_sigma: float) -> str:
    """Why no point lies below the detection threshold: a flat scan, a levelling that failed
    (the plane's inliers scatter far more than their lagged noise, and the deepest point lies far
    below the surface by that noise), or no dent."""
    if not float(np.ptp(sf.zl[sf.valid])) > 0:
        return "the scan is flat (every height the same: no variation)"
    text = (
        f"the deepest point is {-deepest * 1e6:.3g} um below the levelled surface, less than "
        f"the detection threshold {detect_sigma:g} x noise = {detect_sigma * sf.sig_s * 1e6:.3g} um"
    )
    note = levelling_note(sf.lev)
    if note is None or not -deepest > detect_sigma * sf.lev.lag_sigma:
        return text
    return (
        f"the levelling failed: {text}, but {-deepest / sf.lev.lag_sigma:.3g} times the "
        f"inliers' lagged noise; {note.removeprefix('the levelling is in doubt: ')}"
    )


def find_dent(
    sf: Surface, detect_sigma: float, min_pixels: int, warnings: list[str] | None = None
) -> tuple[int, int]:
    """(i, j) of the deepest pixel of the dent: of the depressions deeper than the detection
    threshold on the smoothed map whose unsmoothed part below it covers ``min_pixels`` or more
    (fewer: dust or noise), the one of the largest volume; a warning (into ``warnings``) names
    each when more than one qualifies. DentNotFoundError when none does, ScanError when the
    scan looks sign-flipped."""
    zs, sig_s, src = sf.zs, sf.sig_s, sf.src
    level = -detect_sigma * sig_s
    lab, index, _ = _components(zs < level)
    pixels = _depression_pixels(sf, lab, index, level)
    deepest_val = float(np.min(zs))
    good = [i for i in range(index.size) if pixels[i] >= min_pixels]
    if not good:
        _check_sign(sf, -deepest_val, 0.0, detect_sigma, min_pixels)
    if index.size == 0:
        raise DentNotFoundError(f"{src}: no dent found: {_shallow(sf, deepest_val, detect_sigma)}")
    if not good:
        raise DentNotFoundError(
            f"{src}: no dent found: the depressions below the detection threshold "
            f"({detect_sigma * sig_s * 1e6:.3g} um) cover at most {int(max(pixels))} pixels "
            f"(need {min_pixels}); dust or noise, not a dent"
        )
    measured = np.where(sf.valid, lab, 0)  # depth and volume on the measured pixels only
    depths = np.asarray(ndimage.minimum(zs, measured, index=index))
    volumes = -np.asarray(ndimage.sum(zs, measured, index=index)) * sf.dx * sf.dy
    best = max(good, key=lambda i: volumes[i])
    if len(good) > 1 and warnings is not None:
        warnings.append(_candidates_note(sf, measured, index, good, best, depths, pixels, volumes))
    comp = measured == best + 1
    volume = -float(np.sum(zs[comp])) * sf.dx * sf.dy
    _check_sign(sf, -float(depths[best]), volume, detect_sigma, min_pixels)
    idx = int(np.argmin(np.where(comp, zs, np.inf)))
    i0, j0 = np.unravel_index(idx, zs.shape)
    return _spike_free(sf, comp, (int(i0), int(j0)), warnings)


#: The median filter's window [pixels] that sets a spike apart from the dent's bottom: a
#: depression of fewer than half its 25 pixels is a spike (dust, a flank's dropout), not a dent.
SPIKE_WINDOW = 5
#: A pixel is a spike when the smoothed map lies this many noise sigmas below the median-filtered
#: map there (at a dent's bottom the two agree within the noise: its curvature over two pixels
#: is far below it).
SPIKE_SIGMAS = 20.0


def _spike_free(
    sf: Surface, comp: np.ndarray, ij: tuple[int, int], warnings: list[str] | None
) -> tuple[int, int]:
    """``ij``, the smoothed map's deepest pixel of the dent ``comp``, unless it is a spike (one
    pixel, or a few, far below its neighbours): then the deepest pixel of ``comp`` on the map
    median-filtered over ``SPIKE_WINDOW`` pixels, with a warning into ``warnings``."""
    zf = fill_nan(sf.zl)[0]
    h = SPIKE_WINDOW // 2  # the window's median at ij first: the whole map only for a spike
    i, j = ij
    local = float(np.median(zf[max(i - h, 0) : i + h + 1, max(j - h, 0) : j + h + 1]))
    if local - sf.zs[ij] <= SPIKE_SIGMAS * max(sf.lev.sigma, sf.sig_s):
        return ij
    zm = ndimage.median_filter(zf, size=SPIKE_WINDOW, mode="nearest")
    i1, j1 = np.unravel_index(int(np.argmin(np.where(comp, zm, np.inf))), zm.shape)
    if warnings is not None:
        warnings.append(
            f"a spike at x = {ij[1] * sf.dx * 1e3:.4g} mm, y = {ij[0] * sf.dy * 1e3:.4g} mm "
            f"({(sf.zl[ij] if sf.valid[ij] else sf.zs[ij]) * 1e6:.4g} um deep, the median of "
            f"its neighbours {zm[ij] * 1e6:.4g} um) was the deepest pixel; the bottom is taken "
            f"at x = {j1 * sf.dx * 1e3:.4g} mm, y = {i1 * sf.dy * 1e3:.4g} mm, and the bottom's "
            "fit leaves such pixels out"
        )
    return int(i1), int(j1)


def dent_region(sf: Surface, ij: tuple[int, int], thr: float) -> np.ndarray:
    """The deformed area: the connected region around ``ij`` deeper than ``thr`` (holes
    filled); DentCutOffError when it reaches the scan's edge, or reaches it only through
    pixels without data (the dent runs into a region without data)."""
    lab2, _ = ndimage.label(sf.zs < -thr, structure=np.ones((3, 3)))
    region = ndimage.binary_fill_holes(lab2 == lab2[ij])
    edges = edges_touched(region & sf.valid)
    if edges:
        raise DentCutOffError(
            f"{sf.src}: the dent is cut off by the scan's {' and '.join(edges)} edge: its outline "
            f"(depth {thr * 1e6:.3g} um) reaches the edge, so its length cannot be measured; "
            "scan a larger area around the dent"
        )
    if edges_touched(region):  # through pixels without data only
        gaps, _ = ndimage.label(region & sf.was_nan, structure=np.ones((3, 3)))
        border = np.concatenate([gaps[0], gaps[-1], gaps[:, 0], gaps[:, -1]])
        gap = np.isin(gaps, border[border > 0])  # the no-data pixels that reach the edge
        rows, cols = np.nonzero(gap)
        raise DentCutOffError(
            f"{sf.src}: the dent runs into a region without data: at its outline's depth "
            f"({thr * 1e6:.3g} um) it continues into {int(gap.sum())} pixels without data "
            f"(x = {cols.min() * sf.dx * 1e3:.4g} to {cols.max() * sf.dx * 1e3:.4g} mm, "
            f"y = {rows.min() * sf.dy * 1e3:.4g} to {rows.max() * sf.dy * 1e3:.4g} mm), where "
            "only interpolation continues it, so its length cannot be measured; scan the dent "
            "again with data all around it"
        )
    return np.asarray(region)


def filled_fraction(
    sf: Surface, region: np.ndarray, max_filled: float, warnings: list[str]
) -> float:
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
