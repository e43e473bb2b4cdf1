"""The dent on a levelled scan: detection, outline, delta_p, length, width, L_s, pile-up.

Definitions in the package docstring (:mod:`impactlab.experiment.profilometry`); the steps of
:func:`measure_dent`: level the scan, fill dropouts, find the deepest depression above the
detection threshold, outline it, fit its bottom (delta_p), measure length and width at the edge
threshold (extrapolated to the zero threshold when the dent is deep enough, from levels clear of
the smoothing's reach: :func:`~.extent.extent`), orient the sliding axis towards the sharper
end, estimate the uncertainties, find the pile-up.
"""

from __future__ import annotations

import math

import numpy as np
from scipy import ndimage

from impactlab.experiment.checks import check_instance
from impactlab.experiment.errors import ScanError
from impactlab.experiment.profilometry.bottom import bottom
from impactlab.experiment.profilometry.extent import (
    Extent,
    extent,
    merged_note,
    smoothing_note,
)
from impactlab.experiment.profilometry.gaps import (
    GapSpread,
    check_crossings,
    gap_spread,
    measured_samples,
    outline_gaps,
)
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.levelling import levelling_note, step_note
from impactlab.experiment.profilometry.metrics import (
    DentMetrics,
    sliding_length_note,
    unmeasured_notes,
)
from impactlab.experiment.profilometry.outline import outline, sample
from impactlab.experiment.profilometry.profiles import MAX_PROFILE_SAMPLES, orient, profiles
from impactlab.experiment.profilometry.surface import (
    Surface,
    dent_region,
    filled_fraction,
    find_dent,
    surface,
)
from impactlab.experiment.uncertainty import Estimate

__all__ = ["MAX_PROFILE_SAMPLES", "DentMetrics", "measure_dent"]


def _deepest(
    sf: Surface,
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


def _extent(
    sf: Surface,
    thr: float,
    depth: float,
    deepest: np.ndarray,
    smooth: float,
    zs: np.ndarray | None = None,
    levels: tuple[float, float] | None = None,
) -> Extent | None:
    """The extent (:func:`~.extent.extent`) on the smoothed map (``zs``, default the scan's);
    None when the outline at the threshold ``thr`` [m] is lost or does not cross the line
    through ``deepest``."""
    zmap = sf.outline_map if zs is None else zs
    return extent(zmap, sf.dx, sf.dy, thr, depth, deepest, smooth, levels)


def _gaps(
    sf: Surface, thr: float, depth: float, deepest: np.ndarray, ext: Extent, smooth: float
) -> GapSpread | None:
    """What the large gaps without data that the outlines run through leave open (:mod:`.gaps`);
    None when they run through none, or leave no more than a pixel open."""
    gap = outline_gaps(sf, ext.outlines[:2])  # the outlines at thr and 2 thr
    if gap is None:
        return None

    def measure(zs: np.ndarray) -> tuple[float, float] | None:
        e = _extent(sf, thr, depth, deepest, smooth, zs, ext.levels)
        return None if e is None else (e.length, e.width)

    return gap_spread(sf, gap, thr, measure, (ext.length, ext.width))


def _clear_of_gaps(
    sf: Surface, thr: float, depth: float, deepest: np.ndarray, smooth: float, ext: Extent
) -> Extent:
    """``ext`` with the length's or the width's levels back at thr and 2 thr where a gap that
    the outline runs through moves it by more than a pixel (no edge there to place the levels
    inside the edge by; :func:`_gaps` then measures its spread at thr and 2 thr)."""
    gap = None if ext.levels == (thr, thr) else outline_gaps(sf, ext.outlines[:2])
    if gap is None:
        return ext

    def measure(zs: np.ndarray) -> tuple[float, float] | None:
        e = _extent(sf, thr, depth, deepest, smooth, zs, ext.levels)
        return None if e is None else (e.length, e.width)

    spread = gap_spread(sf, gap, thr, measure, (ext.length, ext.width))
    if spread is None:
        return ext
    pixel = min(sf.dx, sf.dy) / math.sqrt(3.0)  # spreads are stated as sigmas of a uniform one
    moved = (spread.sigma_length > pixel, spread.sigma_width > pixel)
    # a level moved back from inside the edge to thr, where the smoothing shifts the outline:
    # inf, so that the extrapolation from thr and 2 thr carries that shift in its +-
    levels = (
        math.inf if moved[0] and ext.levels[0] > thr else ext.levels[0],
        math.inf if moved[1] and ext.levels[1] > thr else ext.levels[1],
    )
    return _extent(sf, thr, depth, deepest, smooth, levels=levels) or ext


def _outline_noise(
    sig_s: float,
    s: np.ndarray,
    prof: np.ndarray,
    ends: tuple[float, float],
    sc: np.ndarray,
    cprof: np.ndarray,
    width: float,
    measured: tuple[np.ndarray, np.ndarray],
) -> tuple[float, float]:
    """Position noise [m] of the outline's crossings along (length) and across (width): the
    height noise over the profiles' slopes there, at the sample nearest each crossing whose
    pixel has data (``measured``, of ``s`` and ``sc``: a filled pixel's slope is the fill's)."""
    slope_terms = []
    for sv, pv, targets, ok in (
        (s, prof, ends, measured[0]),
        (sc, cprof, (-0.5 * width, 0.5 * width), measured[1]),
    ):
        g = np.gradient(pv, sv)
        for target in targets:
            far = np.abs(sv - target)
            k = int(np.argmin(np.where(ok, far, np.inf) if ok.any() else far))
            sl = abs(float(g[k]))
            if sl > 0:
                slope_terms.append((sig_s / sl) ** 2)
    noise_len = math.sqrt(sum(slope_terms[:2])) if len(slope_terms) >= 2 else 0.0
    noise_wid = math.sqrt(sum(slope_terms[2:])) if len(slope_terms) >= 4 else 0.0
    return noise_len, noise_wid


def _sigmas(
    ext: Extent, thr: float, depth: float, noise: tuple[float, float]
) -> tuple[float, float, float]:
    """Standard uncertainties of length, width and L_s [m]: the threshold sensitivity and the
    outline noise."""
    noise_len, noise_wid = noise
    if ext.extrapolated:
        # the extrapolation's model error and the outline noise, amplified by the extrapolation
        d_len, d_wid, d_ls = ext.model
        g_len, g_wid = ext.noise_gain
    else:
        d_len, d_wid, d_ls = abs(0.5 * thr / max(depth, 1e-30) * ext.length), 0.0, 0.0
        g_len, g_wid = 1.0, 1.0
    sig_len = math.hypot(d_len, g_len * noise_len)
    sig_wid = math.hypot(d_wid, g_wid * noise_wid)
    sig_ls = math.sqrt(d_ls**2 + (g_len * noise_len) ** 2 + (g_wid * noise_wid) ** 2)
    return sig_len, sig_wid, sig_ls


def _pileup(
    sf: Surface, region: np.ndarray, width: float, pileup_band: float
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
    quad_radius : smallest radius of the paraboloid fit at the deepest point, in pixels of the
        longer side (the fit's disc is a disc in metres).
    pileup_band : width of the band around the outline searched for pile-up, x the dent width.
    max_filled : largest fraction of the dent area that may be dropouts (filled by interpolation).

    Raises :class:`DentNotFoundError` (no dent), :class:`DentCutOffError` (the dent reaches the
    scan's edge) or :class:`ScanError`.
    """
    check_instance(hm, HeightMap, "hm", "read one with read_scan()")
    sf = surface(hm, smooth)
    notes = (levelling_note(sf.lev), step_note(sf.lev))
    warnings: list[str] = [note for note in notes if note]
    i0, j0 = find_dent(sf, detect_sigma, min_pixels, warnings)
    depth_rough = -float(sf.zs[i0, j0])
    thr = max(edge_sigma * sf.sig_s, edge_fraction * depth_rough)
    region = dent_region(sf, (i0, j0), thr)
    filled = filled_fraction(sf, region, max_filled, warnings)
    polygon = outline(sf.zs, sf.dx, sf.dy, -thr, (float(j0 * sf.dx), float(i0 * sf.dy)))
    if polygon is None:
        raise ScanError(
            f"{sf.src}: no closed outline around the deepest point at {-thr * 1e6:.3g} "
            "um; the dent is too irregular to measure"
        )
    zmin, zsig, xm, ym = _deepest(sf, polygon, (i0, j0), depth_rough, quad_radius, warnings)
    # fit noise, plus an allowance of a quarter of the noise sigma for the levelling plane and the
    # paraboloid's model error (validated on the synthetic grooves of the tests), and the heights'
    # rounding to their step, which the fit does not average out (its pixels round alike)
    rounding = sf.lev.step / math.sqrt(12.0)
    delta_p = Estimate(-zmin, math.sqrt(zsig**2 + (0.25 * sf.lev.sigma) ** 2 + rounding**2), "m")
    if delta_p.value < 5.0 * sf.lev.sigma:
        warnings.append(
            f"delta_p = {delta_p.value * 1e6:.3g} um is only {delta_p.value / sf.lev.sigma:.2g} "
            f"times the scan's noise ({sf.lev.sigma * 1e6:.2g} um): the dent is barely resolved"
        )
    return _metrics(
        hm,
        sf,
        delta_p,
        np.array([xm, ym]),
        polygon,
        thr,
        region,
        filled,
        (pileup_band, smooth),
        warnings,
    )


def _uncrossed(sf: Surface, thr: float, deepest: np.ndarray) -> str:
    """The message for an outline (at ``thr`` [m]) that the line through the deepest point
    (x, y) [m] across its long axis does not cross: its likely cause and what to do."""
    head = (
        f"{sf.src}: the dent's outline at {thr * 1e6:.3g} um deep does not cross the line "
        f"across it through its deepest point (x = {deepest[0] * 1e3:.4g} mm, "
        f"y = {deepest[1] * 1e3:.4g} mm), so its width cannot be measured: "
    )
    if sf.lev.step > 0.1 * thr:
        return head + (
            f"the heights come in steps of {sf.lev.step * 1e6:.3g} um, "
            f"{sf.lev.step / thr:.2g} times the outline's depth, so the outline follows the "
            "steps' edges (likely cause: a coarse height step, an integer format with a Z "
            "increment or a sensor's resolution); export the scan with a finer height step, or "
            "its heights as floating point"
        )
    return head + (
        "the deepest point lies off the dent's middle (dust or a pit in it, or a dent at the "
        "noise); check the scan and its dent plot, and clean or crop it"
    )


def _xy(v: np.ndarray | tuple[float, float]) -> tuple[float, float]:
    return float(v[0]), float(v[1])


def _metrics(
    hm: HeightMap,
    sf: Surface,
    delta_p: Estimate,
    deepest: np.ndarray,
    polygon: np.ndarray,
    thr: float,
    region: np.ndarray,
    filled: float,
    options: tuple[float, float],
    warnings: list[str],
) -> DentMetrics:
    """The dent's extent, sliding axis, profiles, uncertainties and pile-up around its deepest
    point ``deepest`` (x, y) [m] and its outline ``polygon`` at the threshold ``thr`` [m];
    ``options`` (pileup_band, smooth) of :func:`measure_dent`."""
    pileup_band, smooth = options
    depth = delta_p.value
    ext = _extent(sf, thr, depth, deepest, smooth)
    if ext is None:
        raise ScanError(_uncrossed(sf, thr, deepest))
    ext = _clear_of_gaps(sf, thr, depth, deepest, smooth, ext)
    length, width = ext.length, ext.width
    s, prof, sc, cprof = profiles(sf, deepest, ext.axis, length, width)
    axis, s, prof, d_minus, d_plus, ambiguous = orient(s, prof, ext.axis, depth)
    # extent along the axis from the outline, for the deepest point's position
    proj = (polygon - deepest) @ axis
    s_start, s_end = float(proj.min()), float(proj.max())
    perp = np.array([-ext.axis[1], ext.axis[0]])  # the cross profile's direction
    in_gaps = check_crossings(sf, deepest, (s_start * axis, s_end * axis, 0.5 * width * perp))
    measured = (measured_samples(sf, deepest, axis, s), measured_samples(sf, deepest, perp, sc))
    noise = _outline_noise(sf.sig_s, s, prof, (s_start, s_end), sc, cprof, width, measured)
    sig_len, sig_wid, sig_ls = _sigmas(ext, thr, depth, noise)
    gaps = _gaps(sf, thr, depth, deepest, ext, smooth)
    if gaps is not None:
        sig_len = math.hypot(sig_len, gaps.sigma_length)
        sig_wid = math.hypot(sig_wid, gaps.sigma_width)
        sig_ls = math.hypot(sig_ls, gaps.sigma_ls)
        warnings.append(gaps.note())
    if in_gaps and gaps is None:  # the gap's spread names it otherwise
        warnings.append(
            f"the dent's edge ({', '.join(in_gaps)}) lies in pixels without data, filled by "
            "interpolation: its place there is the fill's; scan the dent again for data there"
        )
    warnings += smoothing_note(ext, sf.dx, sf.dy, smooth, depth)
    sw = s[(s >= s_start) & (s <= s_end)]  # the outline's own stretch, on the map without pits
    own = sample(sf.outline_map, sf.dx, sf.dy, deepest[None, :] + sw[:, None] * axis[None, :])
    merged = "" if ext.irregular else merged_note(sw, own, depth, sf.lev.sigma)
    warnings += [w for w in (ext.irregular, merged) if w]
    if not ext.extrapolated:
        warnings.append(
            "the dent is too shallow to extrapolate its outline to the zero "
            "threshold; length and width are taken at the threshold"
        )
    warnings += unmeasured_notes(
        delta_p=(delta_p.value, delta_p.sigma),
        length=(length, sig_len),
        width=(width, sig_wid),
    ) + sliding_length_note(length - width, sig_ls, width)
    pileup, pile_at = _pileup(sf, region, width, pileup_band)
    return DentMetrics(
        delta_p=delta_p,
        sliding_length=Estimate(length - width, sig_ls, "m"),
        length=Estimate(length, sig_len, "m"),
        width=Estimate(width, sig_wid, "m"),
        deepest=_xy(deepest),
        axis=_xy(axis),
        sliding_angle=math.atan2(axis[1], axis[0]),
        direction_ambiguous=bool(ambiguous),
        end_sharpness=(float(d_minus), float(d_plus)),
        deepest_fraction=float(-s_start / (s_end - s_start) if s_end > s_start else 0.5),
        pileup=pileup,
        pileup_at=pile_at,
        outline=polygon,
        edge_threshold=thr,
        noise=sf.lev.sigma,
        plane=sf.lev.plane,
        dropout_fraction=float(1.0 - sf.valid.mean()),
        filled_in_dent=filled,
        profile=(s, prof),
        cross_profile=(sc, cprof),
        levelled=HeightMap(sf.zl, sf.dx, sf.dy, hm.source, {"levelled": True}),
        source=hm.source,
        warnings=tuple(warnings),
    )
