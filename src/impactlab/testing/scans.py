"""Synthetic profilometer scans of a sliding dent with exact metrics, and scan writers.

:func:`groove_surface`: an analytic dent, the envelope of the tip sphere (paraboloid
approximation, valid for depths << R) swept along a straight path while its penetration rises
linearly to ``depth`` and falls to ``end_depth`` (a gentle entry ramp, a sharper end, as the
paper's Figs. 6-7 describe), plus a pile-up rim outside the dent. Its metrics have closed forms
(:class:`GrooveTruth`). :func:`synthetic_scan` lays one out in a tilted, noisy height map with
dropouts. :func:`write_scan` writes height maps as X3P, Gwyddion GWY and NetCDF 3
(SurfaceTopography's writers, the optional extra ``impactlab[profilometry]``), ISO 25178-71 SDF
(ASCII and binary, written here from the standard's layout), NPY and CSV.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.optimize import brentq

from impactlab.experiment.errors import MissingDependencyError
from impactlab.schema import warn_renamed

__all__ = ["GrooveTruth", "ScanTruth", "groove_surface", "synthetic_scan", "write_scan"]


@dataclass(frozen=True)
class GrooveTruth:
    """Exact metrics of :func:`groove_surface` (paraboloid envelope), SI: ``depth`` (delta_p),
    ``length`` (extent of the region z < 0 along the sliding direction), ``width`` (across, at the
    deepest point), ``sliding_length`` (= length - width, the paper's L_s), ``deepest`` (x along
    the groove from the path start [m]), ``x_start``, ``x_end`` (ends of the dent along the groove
    [m]), ``pileup`` (rim height [m])."""

    depth: float
    length: float
    width: float
    sliding_length: float
    deepest: float
    x_start: float
    x_end: float
    pileup: float


def _groove_D(x: np.ndarray, knots_s: np.ndarray, knots_p: np.ndarray, R: float) -> np.ndarray:
    """Centre-line penetration D(x) = max_s [p(s) - (x - s)^2 / (2 R)] for piecewise-linear p."""
    x = np.asarray(x, dtype=np.float64)
    best = np.full(x.shape, -np.inf)
    for i in range(knots_s.size - 1):
        s0, s1 = knots_s[i], knots_s[i + 1]
        p0, p1 = knots_p[i], knots_p[i + 1]
        k = (p1 - p0) / (s1 - s0)
        s = np.clip(x + k * R, s0, s1)
        val = p0 + k * (s - s0) - (x - s) ** 2 / (2.0 * R)
        best = np.maximum(best, val)
    return best


def _groove_truth(knots_s: np.ndarray, knots_p: np.ndarray, R: float, pileup: float) -> GrooveTruth:
    i_m = int(np.argmax(knots_p))
    s_m, p_m = float(knots_s[i_m]), float(knots_p[i_m])

    def D(x: float) -> float:
        return float(_groove_D(np.array([x]), knots_s, knots_p, R)[0])

    span = math.sqrt(2.0 * R * p_m) + 1e-3
    x0 = brentq(D, knots_s[0] - span, s_m, xtol=1e-13)
    x1 = brentq(D, s_m, knots_s[-1] + span, xtol=1e-13)
    width = 2.0 * math.sqrt(2.0 * R * p_m)
    return GrooveTruth(p_m, x1 - x0, width, x1 - x0 - width, s_m, x0, x1, pileup)


def groove_surface(
    X: np.ndarray,
    Y: np.ndarray,
    *,
    depth: float,
    path: float,
    tip_radius: float,
    peak_at: float = 0.7,
    end_depth: float = 0.35,
    start: tuple[float, float] = (0.0, 0.0),
    direction: float = 0.0,
    pileup: float = 0.0,
) -> tuple[np.ndarray, GrooveTruth]:
    """Height [m] of an analytic sliding dent on the grid (X, Y) [m] (flat surface at 0).

    The tip sphere (radius ``tip_radius``, paraboloid approximation) slides a distance ``path``
    from ``start`` in the direction ``direction`` [rad, from the +X axis]; its penetration rises
    linearly to ``depth`` at ``peak_at`` * path and falls linearly to ``end_depth`` * depth at the
    end. The permanent surface is the envelope -max(0, D(x) - y^2 / (2R)) with D the centre-line
    penetration max_s [p(s) - (x - s)^2 / (2 R)] (x along, y across the path). ``pileup`` [m]:
    height of a rim just outside the dent (zero at the dent's edge, so the deformed area is
    unchanged). Returns (height, truth).
    """
    if not (0.0 < peak_at < 1.0) or not (0.0 <= end_depth <= 1.0):
        raise ValueError("peak_at must lie in (0, 1) and end_depth in [0, 1]")
    cphi, sphi = math.cos(direction), math.sin(direction)
    dx = X - start[0]
    dy = Y - start[1]
    xl = dx * cphi + dy * sphi
    yl = -dx * sphi + dy * cphi
    knots_s = np.array([0.0, peak_at * path, path])
    knots_p = np.array([0.0, depth, end_depth * depth])
    D = _groove_D(xl, knots_s, knots_p, tip_radius)
    q = D - yl * yl / (2.0 * tip_radius)
    z = -np.maximum(q, 0.0)
    if pileup > 0:
        q0 = 0.08 * depth
        r = np.clip(-q, 0.0, None) / q0
        z = z + np.where(q < 0, pileup * r * np.exp(1.0 - r), 0.0)
    return z, _groove_truth(knots_s, knots_p, tip_radius, pileup)


@dataclass(frozen=True)
class ScanTruth:
    """A synthetic scan's truth: the groove metrics, its placement (start [m], direction [rad]),
    noise sigma [m], the tilt plane coefficients (a, b, c) and the dropout mask."""

    groove: GrooveTruth
    start: tuple[float, float]
    direction: float
    noise: float
    plane: tuple[float, float, float]
    dropouts: np.ndarray


def _path_for(
    sliding_length: float, depth: float, tip_radius: float, peak_at: float, end_depth: float
) -> float:
    """The path [m] whose groove has the sliding length (length - width) ``sliding_length``."""

    def ls_of(path: float) -> float:
        knots_s = np.array([0.0, peak_at * path, path])
        knots_p = np.array([0.0, depth, end_depth * depth])
        return _groove_truth(knots_s, knots_p, tip_radius, 0.0).sliding_length - sliding_length

    hi = sliding_length * 3 + 3e-3
    return brentq(ls_of, 1e-7, hi, xtol=1e-12) if ls_of(1e-7) < 0 < ls_of(hi) else sliding_length


def synthetic_scan(
    *,
    delta_p: float = 22e-6,
    sliding_length: float = 1400e-6,
    tip_radius: float = 8.8e-3,
    pixel: float = 8e-6,
    margin: float = 0.8e-3,
    direction: float = 0.35,
    peak_at: float = 0.7,
    end_depth: float = 0.35,
    pileup: float = 1.5e-6,
    noise: float = 0.1e-6,
    tilt: tuple[float, float] = (1.5e-3, -0.8e-3),
    offset: float = 3e-6,
    dropouts: float = 0.01,
    seed: int = 0,
    depth: float | None = None,
) -> tuple[np.ndarray, float, float, ScanTruth]:
    """A levelled-then-tilted, noisy height map (ny, nx) [m] with a groove whose paper metrics are
    ``delta_p`` (the permanent depth [m]) and ``sliding_length`` (L_s = length - width [m]), NaN
    dropouts (random pixels plus one cluster inside the dent); returns (heights, dx, dy, truth).
    ``depth`` is the old name of ``delta_p`` (a DeprecationWarning; it goes in 0.4)."""
    if depth is not None:
        warn_renamed("depth", "delta_p", "synthetic_scan argument")
        delta_p = depth
    depth = delta_p
    rng = np.random.default_rng(seed)
    path = _path_for(sliding_length, depth, tip_radius, peak_at, end_depth)
    width = 2.0 * math.sqrt(2.0 * tip_radius * depth)
    # bounding box of the dent in the scan: lay the groove out then add the margin
    probe = _groove_truth(
        np.array([0.0, peak_at * path, path]),
        np.array([0.0, depth, end_depth * depth]),
        tip_radius,
        pileup,
    )
    L = probe.length
    cphi, sphi = math.cos(direction), math.sin(direction)
    ext_x = abs(L * cphi) + abs(width * sphi)
    ext_y = abs(L * sphi) + abs(width * cphi)
    nx = math.ceil((ext_x + 2 * margin) / pixel)
    ny = math.ceil((ext_y + 2 * margin) / pixel)
    x = (np.arange(nx) + 0.5) * pixel
    y = (np.arange(ny) + 0.5) * pixel
    X, Y = np.meshgrid(x, y)
    mid = (probe.x_start + probe.x_end) / 2.0
    cx, cy = nx * pixel / 2.0, ny * pixel / 2.0
    start = (
        cx - mid * cphi + rng.uniform(-0.5, 0.5) * pixel,
        cy - mid * sphi + rng.uniform(-0.5, 0.5) * pixel,
    )
    z, truth = groove_surface(
        X,
        Y,
        depth=depth,
        path=path,
        tip_radius=tip_radius,
        peak_at=peak_at,
        end_depth=end_depth,
        start=start,
        direction=direction,
        pileup=pileup,
    )
    plane = (offset, tilt[0], tilt[1])
    z = z + plane[0] + plane[1] * X + plane[2] * Y + noise * rng.standard_normal(z.shape)
    drop = rng.random(z.shape) < dropouts
    if dropouts > 0:
        # a small cluster of lost pixels on the dent's flank (steep walls lose light)
        xc = start[0] + (truth.deepest * 0.5) * cphi - 0.3 * width * sphi
        yc = start[1] + (truth.deepest * 0.5) * sphi + 0.3 * width * cphi
        drop |= (X - xc) ** 2 + (Y - yc) ** 2 < (3.0 * pixel) ** 2
    z[drop] = np.nan
    return z, pixel, pixel, ScanTruth(truth, start, direction, noise, plane, drop)


# ----------------------------------------------------------------------------------------------
# scan writers
# ----------------------------------------------------------------------------------------------


def _write_sdf_ascii(z: np.ndarray, dx: float, dy: float, path: Path) -> None:
    ny, nx = z.shape
    lines = [
        "aISO-1.0",
        "ManufacID   = impactlab",
        "CreateDate  = 010120250000",
        "ModDate     = 010120250000",
        f"NumPoints   = {nx}",
        f"NumProfiles = {ny}",
        f"Xscale      = {dx:.10e}",
        f"Yscale      = {dy:.10e}",
        "Zscale      = 1.0e-6",
        "Zresolution = -1",
        "Compression = 0",
        "DataType    = 7",
        "CheckType   = 0",
        "*",
    ]
    zu = z * 1e6
    lines.extend(" ".join("BAD" if not np.isfinite(v) else f"{v:.6f}" for v in row) for row in zu)
    lines.append("*")
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def _write_sdf_binary(z: np.ndarray, dx: float, dy: float, path: Path) -> None:
    ny, nx = z.shape
    head = struct.pack(
        "<8s10s12s12sHHddddBBB",
        b"bISO-1.0",
        b"impactlab",
        b"010120250000",
        b"010120250000",
        nx,
        ny,
        dx,
        dy,
        1.0e-6,
        -1.0,
        0,
        7,
        0,
    )
    data = (z * 1e6).astype("<f8").tobytes()  # NaN marks invalid points for floating types
    path.write_bytes(head + data)


def _write_csv(z: np.ndarray, dx: float, dy: float, path: Path) -> None:
    with path.open("w", encoding="utf-8") as fh:
        fh.write(f"# pixel_size: {dx * 1e6:.6g} um\n# height_unit: um\n")
        if dy != dx:
            fh.write(f"# pixel_size_y: {dy * 1e6:.6g} um\n")
        for row in z * 1e6:
            fh.write(",".join("" if not np.isfinite(v) else f"{v:.5f}" for v in row) + "\n")


def _write_surface_topography(z: np.ndarray, dx: float, dy: float, path: Path, fmt: str) -> None:
    # SurfaceTopography is an optional extra: imported only here (NetCDF3 through scipy)
    try:
        from SurfaceTopography import Topography
    except ImportError:
        raise MissingDependencyError(
            f"{path}: writing {fmt.upper()} needs the optional package SurfaceTopography: "
            "pip install 'impactlab[profilometry]'"
        ) from None
    ny, nx = z.shape
    topo = Topography(np.ma.masked_invalid(z.T), (nx * dx, ny * dy), unit="m")
    {"x3p": topo.to_x3p, "gwy": topo.to_gwy, "nc": topo.to_netcdf}[fmt](str(path))


def write_scan(
    z: np.ndarray, dx: float, dy: float, path: str | Path, *, fmt: str | None = None
) -> Path:
    """Write a height map (ny, nx) [m], pixel sizes dx, dy [m] (NaN = no data).

    ``fmt`` (default from the extension): "x3p", "gwy", "nc" (SurfaceTopography's writers),
    "sdf" (ISO 25178-71 ASCII), "sdf-binary", "npy" (metres), "csv" (micrometres, with
    '# pixel_size' and '# height_unit' comment lines)."""
    p = Path(path)
    fmt = (fmt or p.suffix.lstrip(".")).lower()
    z = np.asarray(z, dtype=np.float64)
    if fmt in ("x3p", "gwy", "nc"):
        _write_surface_topography(z, dx, dy, p, fmt)
    elif fmt == "sdf":
        _write_sdf_ascii(z, dx, dy, p)
    elif fmt == "sdf-binary":
        _write_sdf_binary(z, dx, dy, p)
    elif fmt == "npy":
        np.save(p, z)
    elif fmt == "csv":
        _write_csv(z, dx, dy, p)
    else:
        raise ValueError(
            f"unknown scan format {fmt!r}; use x3p, gwy, nc, sdf, sdf-binary, npy or csv"
        )
    return p
