"""Gaps in the data that the dent's outline runs through: how far they leave its length, width
and L_s open.

The filled map (:func:`~.outline.fill_nan`) continues the dent into a gap smoothly, so the
outline runs on through it as if the data were there, and where the dent's edge lies inside a
large gap no measurement says. The outline is therefore measured again with each such gap at
its two extremes: the undeformed surface (the edge at the gap's near side) and as deep as the
deepest data around it (the edge at its far side). The ± of length, width and L_s covers the
spread, and a warning names the gap. Gaps of fewer than ``MIN_GAP_PIXELS`` pixels (single lost
pixels) are interpolated from all sides and left as they are.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
from scipy import ndimage

from impactlab.experiment.errors import DentCutOffError
from impactlab.experiment.profilometry.outline import edges_touched
from impactlab.experiment.profilometry.surface import Surface

__all__ = [
    "MIN_GAP_PIXELS",
    "GapSpread",
    "check_crossings",
    "gap_spread",
    "measured_samples",
    "outline_gaps",
]

#: A gap (8-connected pixels without data) of at least this many pixels that the outline runs
#: through widens the ± of length, width and L_s; a smaller one is interpolated from all sides.
MIN_GAP_PIXELS = 9

#: How deep, in outline thresholds, a gap is filled at least for the far-side extreme (below
#: both thresholds of the extrapolation, 1 and 2 x t_e).
_DEEP_THRESHOLDS = 2.5

#: ``measure(zs)``: (length, width) [m] of the dent on the smoothed map ``zs``, None when the
#: outline is lost there.
Measure = Callable[[np.ndarray], "tuple[float, float] | None"]


@dataclass(frozen=True)
class GapSpread:
    """What the gaps leave open: ``pixels`` without data in them, ``at`` the (x, y) [m] of the
    largest one's centre, the L_s [m] with the gaps at either extreme (``ls_near``,
    ``ls_far``; NaN where the outline is lost), and the standard uncertainties [m] that the
    spread adds to length, width and L_s (half-widths of a uniform spread around the value:
    the largest distance to an extreme over sqrt(3))."""

    pixels: int
    at: tuple[float, float]
    ls_near: float
    ls_far: float
    sigma_length: float
    sigma_width: float
    sigma_ls: float

    def note(self) -> str:
        """The warning that names the gap and what it leaves open."""
        x, y = self.at

        def um(v: float) -> str:
            return f"{v * 1e6:.4g} um" if math.isfinite(v) else "no outline"

        return (
            f"the dent's outline runs through {self.pixels} pixels without data (filled by "
            f"interpolation) around x = {x * 1e3:.4g} mm, y = {y * 1e3:.4g} mm, where no "
            "measurement says how far the dent reaches: L_s is "
            f"{um(self.ls_near)} with them as undeformed surface, {um(self.ls_far)} with them "
            "as deep as the dent beside them; the ± of length, width and L_s includes that "
            f"spread (L_s: ± {self.sigma_ls * 1e6:.3g} um); scan the dent again for data there"
        )


def outline_gaps(sf: Surface, outlines: Sequence[np.ndarray]) -> np.ndarray | None:
    """The gaps of ``MIN_GAP_PIXELS`` or more pixels without data that one of the closed
    ``outlines`` ((k, 2) (x, y) [m]) runs through or along (within a pixel), as a boolean map;
    None when it runs through none."""
    lab, n = ndimage.label(sf.was_nan, structure=np.ones((3, 3)))
    if n == 0:
        return None
    sizes = np.bincount(lab.ravel())
    big = sizes >= MIN_GAP_PIXELS
    big[0] = False
    if not big.any():
        return None
    near = ndimage.grey_dilation(np.where(big[lab], lab, 0), size=(3, 3))
    ny, nx = lab.shape
    hit: set[int] = set()
    for line in outlines:
        i = np.clip(np.rint(line[:, 1] / sf.dy).astype(int), 0, ny - 1)
        j = np.clip(np.rint(line[:, 0] / sf.dx).astype(int), 0, nx - 1)
        hit.update(int(k) for k in np.unique(near[i, j]))
    hit.discard(0)
    return np.isin(lab, sorted(hit)) if hit else None


def gap_spread(
    sf: Surface,
    gap: np.ndarray,
    thr: float,
    measure: Measure,
    nominal: tuple[float, float],
) -> GapSpread | None:
    """The spread of length, width and L_s [m] with the ``gap`` pixels at the undeformed
    surface and as deep as the deepest data around them (at least ``_DEEP_THRESHOLDS`` x the
    outline threshold ``thr`` [m]), around the ``nominal`` (length, width) [m]; where the
    outline is lost at an extreme, the gaps' extent bounds the spread. None when neither
    extreme moves them by more than a pixel (a gap on the dent's flank, away from its ends)."""
    ring = ndimage.binary_dilation(gap, structure=np.ones((3, 3))) & ~gap
    deep = min(float(np.min(sf.zs[ring])) if ring.any() else 0.0, -_DEEP_THRESHOLDS * thr)
    length, width = nominal
    ls = length - width
    ends: list[tuple[float, float] | None] = [
        measure(np.where(gap, fill, sf.outline_map)) for fill in (0.0, deep)
    ]
    rows, cols = np.nonzero(gap)
    extent = math.hypot(float(np.ptp(cols) + 1) * sf.dx, float(np.ptp(rows) + 1) * sf.dy)
    far = [0.0, 0.0, 0.0]
    for end in ends:
        if end is None or not all(math.isfinite(v) for v in end):
            far = [max(f, extent) for f in far]
            continue
        for k, (v, v0) in enumerate(
            zip((end[0], end[1], end[0] - end[1]), (length, width, ls), strict=True)
        ):
            far[k] = max(far[k], abs(v - v0))
    if max(far) <= min(sf.dx, sf.dy):
        return None
    lab, _ = ndimage.label(gap, structure=np.ones((3, 3)))
    largest = lab == 1 + int(np.argmax(np.bincount(lab.ravel())[1:]))
    ci, cj = ndimage.center_of_mass(largest)
    ls_at = [math.nan if e is None else e[0] - e[1] for e in ends]
    return GapSpread(
        pixels=int(gap.sum()),
        at=(float(cj) * sf.dx, float(ci) * sf.dy),
        ls_near=ls_at[0],
        ls_far=ls_at[1],
        sigma_length=far[0] / math.sqrt(3.0),
        sigma_width=far[1] / math.sqrt(3.0),
        sigma_ls=far[2] / math.sqrt(3.0),
    )


def _pixel(sf: Surface, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(rows, columns) of the pixels nearest the points ``xy`` ((k, 2) (x, y) [m])."""
    ny, nx = sf.was_nan.shape
    i = np.clip(np.rint(xy[:, 1] / sf.dy).astype(int), 0, ny - 1)
    j = np.clip(np.rint(xy[:, 0] / sf.dx).astype(int), 0, nx - 1)
    return i, j


def measured_samples(
    sf: Surface, origin: np.ndarray, direction: np.ndarray, s: np.ndarray
) -> np.ndarray:
    """Whether the nearest pixel of each profile sample ``origin + s direction`` [m] has data."""
    i, j = _pixel(sf, origin[None, :] + s[:, None] * direction[None, :])
    return ~sf.was_nan[i, j]


def check_crossings(
    sf: Surface, deepest: np.ndarray, offsets: tuple[np.ndarray, np.ndarray, np.ndarray]
) -> list[str]:
    """The names of the outline's crossings that lie in a gap without data of
    ``MIN_GAP_PIXELS`` or more pixels inside the scan (a warning's text); ``offsets`` (x, y) [m]
    from ``deepest``: the start and the end of the length, half the width across (both sides).
    DentCutOffError for one that lies in pixels without data that reach the scan's edge: the
    dent runs into a region without data, where only interpolation continues it (a no-data
    frame around the scan that the dent's edge, extrapolated to zero depth, reaches)."""
    lab, n = ndimage.label(sf.was_nan, structure=np.ones((3, 3)))
    if n == 0:
        return []
    start, end, side = offsets
    points = {
        "the start of its length": deepest + start,
        "the end of its length": deepest + end,
        "one side of its width": deepest - side,
        "the other side of its width": deepest + side,
    }
    names = list(points)
    i, j = _pixel(sf, np.array([points[k] for k in names], dtype=np.float64))
    sizes = np.bincount(lab.ravel())
    inside: list[str] = []
    for name, k in zip(names, lab[i, j], strict=True):
        if k == 0 or sizes[k] < MIN_GAP_PIXELS:
            continue
        gap = lab == k
        if not edges_touched(gap):
            inside.append(name)
            continue
        x, y = points[name]
        raise DentCutOffError(
            f"{sf.src}: the dent runs into a region without data: its edge ({name}, at x = "
            f"{x * 1e3:.4g} mm, y = {y * 1e3:.4g} mm) lies in {int(sizes[k])} pixels without "
            "data that reach the scan's edge, where only interpolation continues it, so its "
            "length and width cannot be measured; scan the dent again with data all around it"
        )
    return inside
