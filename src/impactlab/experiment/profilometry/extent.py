"""The dent's extent on the smoothed height map, extrapolated to the zero threshold
(:func:`extent`), and the warning when the smoothing's reach could not be escaped
(:func:`smoothing_note`).

All lengths in metres; a height map ``zs`` (ny, nx) has row i at y = i dy and column j at
x = j dx.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from scipy.optimize import brentq

from impactlab.experiment.profilometry.outline import chord, feret, outline, principal_axis

__all__ = ["OUTLINE_DOUBT", "Extent", "extent", "smoothing_note", "smoothing_sigma"]

#: The start of the doubt (a result not ok) of an outline that does not shrink smoothly between
#: the levels the length is extrapolated from: another mark, a pit or dust touches its edge.
OUTLINE_DOUBT = "the dent's outline changes shape between its levels"
#: Two steps of the length between the levels (t1 to 2 t1, 2 t1 to 3 t1) differ by more than this
#: fraction of their sum, and by more than _IRREGULAR_PIXELS pixels, on an irregular outline (a
#: tip's dent, a cap or a groove, shrinks about evenly: its two steps differ by 6 % of their sum
#: to 60 % of its depth).
_IRREGULAR_SHARE = 0.5
_IRREGULAR_PIXELS = 4.0

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
    for the length where t1 > thr; inf where the levels clear of the smoothing's reach could not
    be used: then from thr and 2 thr); ``model``: its model errors of length, width and L_s [m];
    ``noise_gain``: its gains on their outline noise (sqrt(5) linear, sqrt(19) quadratic);
    ``shift``: the smoothing's shift [m] that length and width carry (0 where escaped);
    ``wanted``: the first level [m] each would have needed where that lay too deep (else 0);
    ``irregular``: the doubt (:data:`OUTLINE_DOUBT`) of a length whose levels do not shrink
    evenly, or that exceeds the scan's diagonal ("" else)."""

    length: float
    width: float
    axis: np.ndarray
    extrapolated: bool
    outlines: tuple[np.ndarray, ...] = ()
    levels: tuple[float, float] = (0.0, 0.0)
    model: tuple[float, float, float] = (0.0, 0.0, 0.0)
    noise_gain: tuple[float, float] = (1.0, 1.0)
    shift: tuple[float, float] = (0.0, 0.0)
    wanted: tuple[float, float] = (0.0, 0.0)
    irregular: str = ""


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
) -> tuple[float, float]:
    """The first level t1 [m] of quantity ``k`` (0 length, 1 width): the threshold ``thr``, or
    ``_INSIDE_SIGMAS`` smoothing sigmas ``sig`` [m] inside the edge (the edge's slope from the
    outlines at t1 and 2 t1, iterated); inf when that lies too deep or loses the outline. With
    it the level it wanted [m] where that lay too deep (else 0)."""
    t = thr
    for _ in range(3):
        a, b = at(t), at(2.0 * t)
        if a is None or b is None:
            return math.inf, 0.0
        shrink = float(a[k]) - float(b[k])  # both edges move by t / slope
        if not shrink > 0:
            return t, 0.0
        slope = 2.0 * t / shrink
        if t == thr and not _SMOOTHED_SIGMAS * slope * sig > thr:
            return thr, 0.0
        want = _INSIDE_SIGMAS * slope * sig
        if not want > 1.05 * t:
            return t, 0.0
        if not (3 - k) * want <= _DEEPEST_FRACTION * depth:
            return math.inf, want
        t = want
    return t, 0.0


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
    width) fixes those (a map changed in a gap; inf for one that a gap kept at thr and 2 thr,
    with the smoothing's shift in its +-). None when the outline at thr is lost or does
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
    wanted = (0.0, 0.0)
    if levels is None:
        found = (_edge_level(at, 0, thr, depth, sig[0]), _edge_level(at, 1, thr, depth, sig[1]))
        levels, wanted = (found[0][0], found[1][0]), (found[0][1], found[1][1])
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
        # can make one look shallow and the other not); where one's levels inside lay too deep,
        # each whose edge the smoothing reaches at thr keeps its shift of a kinked edge in its
        # +- (and L_s the larger): where the edges are unlike, their biases do not cancel (64 um
        # pixels on a groove 22 um deep: the width +75 um, the length -6 um)
        reached = [t != thr and not all(map(math.isfinite, levels)) for t in levels]
        rows = [_linear(float(m1[k]), float(m2[k]), reached[k], sig[k]) for k in (0, 1)]
    (L0, d_len, in_len, k_len), (W0, d_wid, in_wid, k_wid) = rows
    # L_s: the threshold's non-linearity where length and width share it (a quarter of the
    # difference of their corrections at thr), the model errors of those from inside, and the
    # smoothing's shifts where it could not be escaped: the larger, not their difference (a
    # kinked edge's shift is a size, not this edge's: a pile-up moves an edge in, a flat surface
    # out, and the length's ends are unlike the width's sides; on 80 um pixels a groove 26 um
    # deep had shifts of 274 and 278 um, and its length -3 um, its width +160 um)
    shared = 0.25 * abs((float(m1[0]) - float(m2[0])) - (float(m1[1]) - float(m2[1])))
    inner = [d for d, i in ((d_len, in_len), (d_wid, in_wid)) if i]
    k_ls = max(k_len, k_wid)
    d_ls = math.sqrt(shared**2 + sum(d * d for d in inner) + k_ls**2)
    t1 = (float(levels[0]), float(levels[1]))
    # the gains on the outline noise: 3 x1 - 3 x2 + x3, 2 x1 - x2 (the width's square alike)
    gain = (math.sqrt(19.0) if in_len else math.sqrt(5.0), math.sqrt(5.0))
    model = (d_len, d_wid, d_ls)
    lengths = [float(m[0]) for m in (at(j * t1[0]) for j in (1, 2, 3)) if m is not None]
    odd = _irregular(lengths if in_len else [], L0, zs.shape, dx, dy, axis)
    return Extent(L0, W0, axis, True, tuple(outlines), t1, model, gain, (k_len, k_wid), wanted, odd)


def _irregular(
    lengths: list[float], L0: float, shape: tuple[int, ...], dx: float, dy: float, axis: np.ndarray
) -> str:
    """The doubt of a length extrapolated to ``L0`` [m] from ``lengths`` [m] at t1, 2 t1, 3 t1
    (empty: not from those) that do not shrink evenly, or of one longer than the scan's
    diagonal (map of ``shape`` pixels ``dx`` x ``dy`` [m]); "" else."""
    diagonal = math.hypot(shape[1] * dx, shape[0] * dy)
    um = ", ".join(f"{x * 1e6:.4g}" for x in lengths)
    if L0 > diagonal:
        return (
            f"{OUTLINE_DOUBT}: its length extrapolates to {L0 * 1e6:.4g} um, longer than the "
            f"scan's diagonal ({diagonal * 1e6:.4g} um; lengths {um} um at the levels): another "
            "mark, a pit or dust touches its edge; crop or clean the scan around the dent"
        )
    if len(lengths) != 3:
        return ""
    d1, d2 = lengths[0] - lengths[1], lengths[1] - lengths[2]
    pixel = math.hypot(dx * float(axis[0]), dy * float(axis[1]))
    if abs(d1 - d2) <= max(_IRREGULAR_SHARE * (abs(d1) + abs(d2)), _IRREGULAR_PIXELS * pixel):
        return ""
    return (
        f"{OUTLINE_DOUBT}: its length is {um} um at the three levels it is extrapolated from, "
        "not shrinking evenly as a tip's dent does: another mark, a pit or dust touches its "
        "edge, and its length and L_s are not measured; crop or clean the scan around the dent"
    )


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


def smoothing_note(ext: Extent, dx: float, dy: float, smooth: float, depth: float) -> list[str]:
    """The warning for each of length and width whose levels clear of the smoothing lay too deep
    or were lost, so that it carries the smoothing's shift (``ext`` measured on pixels ``dx`` x
    ``dy`` [m] smoothed by ``smooth`` pixels, the dent ``depth`` [m] deep): the smoothing's
    scale, the shift, and the pixel size that would clear it (levels too deep) or what else to
    do (a gap or a lost outline)."""
    notes = []
    perp = np.array([-ext.axis[1], ext.axis[0]])
    for k, name in enumerate(("length", "width")):
        if not ext.shift[k] > 0 or math.isfinite(ext.levels[k]):
            continue  # (one with levels inside, taken at thr with the other: the other's note)
        sig = smoothing_sigma(dx, dy, smooth, ext.axis if k == 0 else perp)
        head = (
            f"the dent's {name} is extrapolated from the edge threshold, within the reach of the "
            f"outline's smoothing (sigma {sig * 1e6:.3g} um: {smooth:g} pixel of "
            f"{dx * 1e6:.3g} x {dy * 1e6:.3g} um), whose shift it carries, up to "
            f"{ext.shift[k] * 1e6:.3g} um (in the +- of the {name} and of L_s)"
        )
        if ext.wanted[k] > 0:
            need = (3 - k) * ext.wanted[k]
            # the pixels that would bring that level to the deepest allowed, with the slope as
            # measured, and with the (steeper, unsmoothed) edge slope 4 depth / width of a
            # paraboloid, as across a sphere's cap: the finer of the two
            cap = _DEEPEST_FRACTION * ext.width / (4 * (3 - k) * _INSIDE_SIGMAS * sig)
            f = min(_DEEPEST_FRACTION * depth / need, cap)
            pix = f"{f * dx * 1e6:.2g} um"
            if dx != dy:
                pix = f"{f * dx * 1e6:.2g} x {f * dy * 1e6:.2g} um"
            notes.append(
                f"{head}: the pixels are too coarse for this dent, its levels clear of the "
                f"smoothing would reach {need * 1e6:.3g} um deep, past {_DEEPEST_FRACTION:.0%} "
                f"of its depth ({depth * 1e6:.3g} um); scan it with pixels of about {pix} or finer"
            )
        else:
            notes.append(
                f"{head}: its levels clear of the smoothing are lost (a gap without data where "
                "the outline runs, or no outline there); scan the dent again for data there, or "
                "with finer pixels"
            )
    return notes


#: A second minimum along the sliding axis is a second depression where it rises out of the
#: first by this fraction of the depth (a tip's dent has one: a cap, or a groove's flat bottom).
_MERGED_PROMINENCE = 0.25


def merged_note(s: np.ndarray, prof: np.ndarray, depth: float, noise: float) -> str:
    """The doubt (:data:`OUTLINE_DOUBT`) of a profile along the sliding axis (``s``, heights
    ``prof`` [m]) with two minima, each rising out of the other by at least
    ``_MERGED_PROMINENCE`` of the ``depth`` [m] and 5 ``noise`` [m]: two marks merged into one
    outline; "" else."""
    from scipy.signal import find_peaks

    ok = np.isfinite(prof)
    if ok.sum() < 5:
        return ""
    least = max(_MERGED_PROMINENCE * depth, 5.0 * noise)
    peaks, _ = find_peaks(-np.asarray(prof)[ok], prominence=least)
    if len(peaks) < 2:
        return ""
    at = ", ".join(f"{np.asarray(s)[ok][i] * 1e3:.3g} mm" for i in peaks)
    return (
        f"{OUTLINE_DOUBT}: its profile along the sliding axis has {len(peaks)} minima (at {at} "
        "from the deepest point), each rising out of the other by a quarter of its depth or "
        "more: two marks merged into one outline, whose length and L_s are not this dent's; "
        "crop the scan to one mark"
    )
