"""Is the measured dent one that the rod can make? Refuse the impossible, warn on the implausible.

A wrong height unit, a wrong pixel size or a sign-flipped scan give numbers that look like
measurements. These checks compare the dent with the rod that made it (tip radius R, length L):

impossible (:class:`ScanError`, each message naming the likely cause):

* delta_p below 1 nm (no profilometer resolves it: the height unit) or deeper than R;
* a dent wider than the tip's diameter 2R or longer than the rod (the pixel size);
* a dent more than 10 times deeper than a sphere of radius R reaches at the dent's width
  (a residual dent is never deeper than the tip's cap: the pixel size or the height unit);

implausible (warnings): delta_p below 0.1 um; a dent 100 times shallower than the tip's cap at
its width (the height unit or the pixel size). The sign of the heights is checked by
:func:`impactlab.experiment.measure_dent` itself (a bump instead of a dent).
"""

from __future__ import annotations

import math

from impactlab.experiment.errors import ScanError
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry.extent import OUTLINE_DOUBT
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.levelling import LEVELLING_DOUBT
from impactlab.experiment.profilometry.metrics import DentMetrics

__all__ = [
    "NARROW_DOUBT_RATIO",
    "check_dent",
    "dent_findings",
    "height_unit_doubt",
    "narrow_dent_doubt",
]

#: Shallowest dent [m] a profilometer resolves; below it the height unit is wrong.
MIN_DEPTH = 1e-9
#: Shallowest plausible dent [m] of a drop test; below it a warning names the height unit.
PLAUSIBLE_DEPTH = 0.1e-6
#: A dent shallower than PLAUSIBLE_DEPTH and this many times shallower than the tip's cap at its
#: width is read in a height unit 1000 times too small (um heights read as nm: the ratio of a
#: residual dent to the cap lies near 1, R over the residual crater's radius of curvature).
UNIT_DOUBT_RATIO = 300.0


def _length(x: float) -> str:
    """A length [m] in the unit that reads best (m, mm, um or nm)."""
    for unit, scale in (("m", 1.0), ("mm", 1e-3), ("um", 1e-6)):
        if abs(x) >= scale:
            return f"{x / scale:.4g} {unit}"
    return f"{x * 1e9:.4g} nm"


def _units(scan: HeightMap | None) -> tuple[str, str]:
    """(how the heights were read, the pixel size) for the messages."""
    if scan is None:
        return "the height unit", "the pixel size"
    meta = scan.meta or {}
    unit = meta.get("height_unit") or meta.get("unit")
    heights = f"the height unit (read as {unit!r})" if unit else "the height unit"
    pixels = f"the pixel size ({_length(scan.dx)} x {_length(scan.dy)})"
    if meta.get("format") == "xyz":  # SurfaceTopography reads x, y in the heights' unit
        pixels = (
            f"the point list's x, y (read in its height unit {unit!r}, as x,y,z lists are: "
            f"{_length(scan.dx)} apart; write x, y in the unit of z)"
        )
    return heights, pixels


def _too_small(scan: HeightMap | None) -> str:
    """`` (heights stored in metres and read as 'nm' come out 1e+09 times too small)``, with the
    height unit the scan was read in (a generic sentence when it is not known)."""
    meta = (scan.meta or {}) if scan is not None else {}
    unit = meta.get("height_unit") or meta.get("unit")
    try:
        factor = 1.0 / length_factor(str(unit)) if unit else math.nan
    except ValueError:
        factor = math.nan
    if not (math.isfinite(factor) and factor > 1.0):
        return " (heights stored in metres and read in a smaller unit come out too small)"
    return f" (heights stored in metres and read as {unit!r} come out {factor:.3g} times too small)"


def _cap_depth(width: float, R: float) -> float:
    """Depth [m] of a sphere of radius ``R`` at the chord ``width`` (inf for width >= 2R)."""
    half = 0.5 * width
    return R - math.sqrt(R * R - half * half) if half < R else math.inf


def check_dent(
    dent: DentMetrics,
    *,
    tip_radius: float,
    rod_length: float,
    scan: HeightMap | None = None,
) -> tuple[str, ...]:
    """Check ``dent`` against the rod that made it (tip radius, length [m]); ``scan`` (the height
    map as read) names its height unit and pixel size in the messages.

    Raises :class:`ScanError` for a dent the rod cannot make; returns the warnings for an
    implausible one (empty when it looks right)."""
    R, rod_l = float(tip_radius), float(rod_length)
    depth, width, length = dent.delta_p.value, dent.width.value, dent.length.value
    heights, pixels = _units(scan)
    src = dent.source or "scan"
    wrong: list[str] = []
    if depth < MIN_DEPTH:
        wrong.append(
            f"delta_p = {depth:.3g} m is below 1 nm, finer than any profilometer resolves: check "
            f"{heights}{_too_small(scan)}"
        )
    elif depth > R:
        wrong.append(
            f"delta_p = {_length(depth)} is deeper than the rod's tip radius R = {_length(R)}: "
            f"check {heights}"
        )
    if width > 2.0 * R:
        wrong.append(
            f"the dent is {_length(width)} wide, wider than the tip's diameter "
            f"2R = {_length(2 * R)}: check {pixels}"
        )
    if length > rod_l:
        wrong.append(
            f"the dent is {_length(length)} long, longer than the rod (L = {_length(rod_l)}): "
            f"check {pixels}"
        )
    cap = _cap_depth(width, R)
    if not wrong and depth > 10.0 * cap:
        wrong.append(
            f"delta_p = {_length(depth)} but the dent is only {_length(width)} wide: a tip of "
            f"radius R = {_length(R)} reaches {_length(cap)} at that width, a residual dent "
            f"never more: check {pixels} (too small?) or {heights}"
        )
    if wrong:
        raise ScanError(f"{src}: impossible dent for this rod: " + "; ".join(wrong))
    warnings: list[str] = []
    if depth < PLAUSIBLE_DEPTH:
        warnings.append(
            f"delta_p = {_length(depth)} is shallower than 0.1 um, implausible for a dent of a "
            f"drop: check {heights}"
        )
    if depth < 0.01 * cap:
        warnings.append(
            f"delta_p = {_length(depth)} is {cap / depth:.3g} times shallower than a tip of radius "
            f"R = {_length(R)} at the dent's width {_length(width)}: check {heights} and {pixels}"
        )
    return tuple(warnings)


#: A dent deeper than this many times the tip's cap at its width is a doubt (a result not ok):
#: a residual dent is no deeper than the tip that made it at that width (the shipped example:
#: 1.0), so a pixel size too small (or heights too large) by 1.4 times or more shows here;
#: beyond 10 times ``check_dent`` refuses it.
NARROW_DOUBT_RATIO = 2.0


def narrow_dent_doubt(
    dent: DentMetrics, *, tip_radius: float, scan: HeightMap | None = None
) -> str:
    """The doubt of a dent deeper than ``NARROW_DOUBT_RATIO`` times the tip's cap at its width
    (``check_dent`` refuses one beyond 10 times); "" otherwise."""
    depth, width = dent.delta_p.value, dent.width.value
    cap = _cap_depth(width, float(tip_radius))
    if not depth > NARROW_DOUBT_RATIO * cap:
        return ""
    heights, pixels = _units(scan)
    return (
        f"delta_p = {_length(depth)} in a dent only {_length(width)} wide, {depth / cap:.3g} "
        f"times deeper than a tip of radius R = {_length(float(tip_radius))} reaches at that "
        f"width ({_length(cap)}), and a residual dent is never deeper: check {pixels} (too "
        f"small?) or {heights}"
    )


def height_unit_doubt(
    dent: DentMetrics, *, tip_radius: float, scan: HeightMap | None = None
) -> str:
    """The doubt (a result not ok) of a dent both shallower than 0.1 um and more than
    ``UNIT_DOUBT_RATIO`` times shallower than the tip's cap at its width: heights read in a unit
    1000 times too small; "" otherwise."""
    depth, width = dent.delta_p.value, dent.width.value
    cap = _cap_depth(width, float(tip_radius))
    if not (depth < PLAUSIBLE_DEPTH and depth * UNIT_DOUBT_RATIO < cap):
        return ""
    heights, _ = _units(scan)
    return (
        f"delta_p = {_length(depth)} in a dent {_length(width)} wide, {cap / depth:.3g} times "
        f"shallower than the tip's cap there ({_length(cap)}): a height unit 1000 times too "
        f"small? check {heights}"
    )


def dent_findings(
    dent: DentMetrics,
    plausible: tuple[str, ...],
    *,
    tip_radius: float,
    scan: HeightMap | None = None,
) -> tuple[list[str], list[str]]:
    """(warnings, doubts) of a measured dent: its own warnings and ``plausible`` (``check_dent``'s)
    as warnings; as doubts (a result not ok) a levelling in doubt (it biases delta_p and L_s
    beyond their +-, in its own words), an outline that changes shape between its levels
    (another mark or a pit at its edge: ``extent.OUTLINE_DOUBT``), a height unit 1000 times too
    small (in place of the two warnings it also raises) and a dent narrower than the tip could
    make."""
    unit = height_unit_doubt(dent, tip_radius=tip_radius, scan=scan)
    levelling = [w for w in dent.warnings if w.startswith((LEVELLING_DOUBT, OUTLINE_DOUBT))]
    said = [w for w in dent.warnings if w not in levelling]
    said += [] if unit else list(plausible)
    narrow = narrow_dent_doubt(dent, tip_radius=tip_radius, scan=scan)
    return said, [*levelling, *(d for d in (unit, narrow) if d)]
