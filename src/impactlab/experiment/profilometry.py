"""Profilometer scans of the dent: reading, levelling, and the dent metrics delta_p and L_s.

Definitions (paper Sec. 5, doi:10.1007/s00419-015-1108-2; details in docs/experiment.md):

* the *deformed area* is the connected region around the deepest point lying more than the edge
  threshold ``t_e`` below the levelled surface (``t_e`` = max(``edge_sigma`` x smoothed noise,
  ``edge_fraction`` x depth); its outline is the contour at -t_e, with sub-pixel interpolation);
* ``delta_p`` = maximum depth below the levelled plane (a local paraboloid fitted around the deepest
  pixel, so the noise does not bias the minimum);
* length = the maximum length of the deformed area (its largest Feret diameter, along the sliding
  axis); width = its width at the deepest point, perpendicular to that axis;
* ``L_s`` = length - width;
* the sliding direction: along the sliding axis towards the *sharper* end, the end where the depth
  falls from 80 % to 20 % of delta_p over the shorter distance (the paper's Figs. 6-7: "wider at
  the centre and sharper at the end of the impact"); flagged ambiguous when both ends are within
  10 %;
* pile-up height = the highest point of the levelled surface in a band around the outline
  (``pileup_band`` x width wide).

Values are magnitudes (delta_p > 0, L_s > 0); the paper prints them negative (y up).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
from scipy import ndimage

from impactlab.experiment.errors import (
    DentCutOffError,
    DentNotFoundError,
    FileFormatError,
    MissingDependencyError,
    ScanError,
)
from impactlab.experiment.markers import length_factor
from impactlab.experiment.textfiles import split_commented
from impactlab.experiment.uncertainty import Estimate, propagate

__all__ = [
    "DentMetrics",
    "HeightMap",
    "Levelled",
    "level_plane",
    "measure_dent",
    "read_scan",
]

_INSTALL = "pip install 'impactlab[profilometry]' (or: pip install SurfaceTopography)"


@dataclass(frozen=True)
class HeightMap:
    """A height map: ``z`` (ny, nx) [m] (NaN = no data; row i is y = i dy, column j is x = j dx),
    pixel sizes ``dx``, ``dy`` [m], ``source`` (file), ``meta`` (reader information)."""

    z: np.ndarray
    dx: float
    dy: float
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        z = np.array(self.z, dtype=np.float64)
        where = f" ({self.source})" if self.source else ""
        if z.ndim != 2 or min(z.shape) < 8:
            raise ValueError(f"a height map must be 2D with at least 8 x 8 pixels, got shape "
                             f"{z.shape}{where}")
        z[~np.isfinite(z)] = np.nan
        for name, v in (("dx", self.dx), ("dy", self.dy)):
            if not (math.isfinite(float(v)) and float(v) > 0):
                raise ValueError(f"{name} (pixel size) must be > 0 m, got {v!r}{where}")
        if np.isnan(z).all():
            raise ValueError(f"the height map has no valid data{where}")
        z.setflags(write=False)
        object.__setattr__(self, "z", z)
        object.__setattr__(self, "dx", float(self.dx))
        object.__setattr__(self, "dy", float(self.dy))

    @property
    def shape(self) -> tuple[int, int]:
        return (int(self.z.shape[0]), int(self.z.shape[1]))

    @property
    def valid(self) -> np.ndarray:
        return np.isfinite(self.z)

    def coords(self) -> tuple[np.ndarray, np.ndarray]:
        """Pixel-centre coordinate grids (X, Y) [m]."""
        ny, nx = self.shape
        return np.meshgrid(np.arange(nx) * self.dx, np.arange(ny) * self.dy)


# ----------------------------------------------------------------------------------------------
# reading
# ----------------------------------------------------------------------------------------------


def _pixel_pair(pixel_size: Any) -> tuple[float, float]:
    from impactlab.units import to_si

    if isinstance(pixel_size, tuple | list):
        if len(pixel_size) != 2:
            raise ValueError(f"pixel_size must be one size or (dx, dy), got {pixel_size!r}")
        dx = to_si(pixel_size[0], "m", name="pixel_size")
        dy = to_si(pixel_size[1], "m", name="pixel_size")
    else:
        dx = dy = to_si(pixel_size, "m", name="pixel_size")
    if not (dx > 0 and dy > 0):
        raise ValueError(f"pixel_size must be > 0, got {pixel_size!r}")
    return dx, dy


def _read_plain(p: Path, pixel_size: Any, height_unit: str | None) -> HeightMap:
    meta: dict[str, str] = {}
    if p.suffix.lower() == ".npy":
        try:
            z = np.load(p, allow_pickle=False)
        except Exception as exc:
            raise FileFormatError(p, f"not a readable NPY array ({type(exc).__name__}: "
                                     f"{str(exc)[:160]})") from None
        if z.ndim != 2 or not np.issubdtype(z.dtype, np.number):
            raise FileFormatError(p, f"expected a 2D numeric array, got shape {z.shape}, dtype "
                                     f"{z.dtype}")
        z = z.astype(np.float64)
    else:
        try:
            text = p.read_text(encoding="utf-8-sig")
        except UnicodeDecodeError:
            raise FileFormatError(p, "not a text (CSV) height map: it is not UTF-8 text") from None
        rows: list[list[float]] = []
        header, lines = split_commented(text)
        meta.update(header)
        for ln, line in lines:
            s = line.strip()
            delim = "," if "," in s else (";" if ";" in s else None)
            cells = s.split(delim) if delim else s.split()
            vals = []
            for c in cells:
                c = c.strip()
                if c == "" or c.lower() in ("nan", "bad", "na"):
                    vals.append(math.nan)
                    continue
                try:
                    vals.append(float(c))
                except ValueError:
                    raise FileFormatError(p, f"line {ln}: {c!r} is not a number") from None
            if rows and len(vals) != len(rows[0]):
                raise FileFormatError(p, f"line {ln}: {len(vals)} values, but the first row has "
                                         f"{len(rows[0])} (truncated or ragged height map)")
            rows.append(vals)
        if not rows:
            raise FileFormatError(p, "no data rows")
        z = np.array(rows)
    if pixel_size is None:
        if "pixel_size" not in meta:
            raise FileFormatError(p, "a plain height map needs the pixel size: pass pixel_size= "
                                     "(e.g. '2 um'; --pixel-size) or add '# pixel_size: 2 um'")
        ps: Any = meta["pixel_size"]
        if "pixel_size_y" in meta:
            ps = (ps, meta["pixel_size_y"])
    else:
        ps = pixel_size
    unit = height_unit if height_unit is not None else meta.get("height_unit")
    if unit is None:
        raise FileFormatError(p, "a plain height map needs the height unit: pass height_unit= "
                                 "(e.g. 'um'; --height-unit) or add '# height_unit: um'")
    try:
        dx, dy = _pixel_pair(ps)
        fac = length_factor(unit, name="height_unit")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    try:
        return HeightMap(z * fac, dx, dy, str(p), {"format": p.suffix.lower().lstrip("."),
                                                    "height_unit": unit})
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None


def _has_pixel_header(p: Path) -> bool:
    try:
        with p.open("r", encoding="utf-8-sig", errors="replace") as fh:
            for _, line in zip(range(50), fh, strict=False):
                s = line.strip().lstrip("#").strip().lower()
                if s.startswith("pixel_size"):
                    return True
    except OSError:
        return False
    return False


def _read_surface_topography(p: Path, pixel_size: Any, height_unit: str | None,
                             channel: int | None) -> HeightMap:
    try:
        from SurfaceTopography import open_topography
        from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor
    except ImportError:
        raise MissingDependencyError(
            f"{p}: reading instrument scan formats needs the optional package SurfaceTopography: "
            f"{_INSTALL}; plain .npy/.csv height maps work without it") from None
    import warnings

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            reader = open_topography(str(p))
            ext_formats = _formats_for_extension(p)
            if ext_formats and reader.format() not in ext_formats:
                # content detection disagrees with the extension (e.g. any file of 2 n^2 bytes
                # passes for a NASA SRTM tile): the extension's reader decides
                detected = reader.name()
                reader = None
                errors = []
                for fmt in ext_formats:
                    try:
                        reader = open_topography(str(p), format=fmt)
                        reader.topography().heights()
                        break
                    except Exception as sub:
                        errors.append(_first_line(sub))
                        reader = None
                if reader is None:
                    raise FileFormatError(
                        p, f"cannot be read as {_format_names(ext_formats)} "
                           f"({p.suffix}): {'; '.join(errors)} (SurfaceTopography's content "
                           f"detection takes it for {detected}; corrupt, truncated or another "
                           "format)")
            channels = reader.channels
            if channel is not None and not 0 <= channel < len(channels):
                raise FileFormatError(p, f"channel {channel} does not exist; the file has "
                                         f"{len(channels)} channels")
            kwargs: dict[str, Any] = {}
            ch = channels[channel if channel is not None else reader.default_channel.index]
            if ch.physical_sizes is None:
                if pixel_size is None:
                    raise FileFormatError(p, f"SurfaceTopography reads it as {reader.name()}, "
                                             "which gives no physical size; if that is the "
                                             "right format pass pixel_size=, else the file is "
                                             "corrupt or in another format")
                dxy = _pixel_pair(pixel_size)
                n = ch.nb_grid_pts
                kwargs["physical_sizes"] = (n[0] * dxy[0], n[1] * dxy[1])
            if ch.unit is None:
                if height_unit is None:
                    raise FileFormatError(p, f"SurfaceTopography reads it as {reader.name()}, "
                                             "which gives no length unit; pass height_unit=")
                kwargs["unit"] = height_unit
            topo = reader.topography(channel_index=channel, **kwargs)
            dim = topo.dim
            if dim != 2:
                raise FileFormatError(p, "the scan is a line profile (1D); a 2D height map of the "
                                         "dent is needed")
            if not topo.is_uniform:
                raise FileFormatError(p, "the scan is not on a uniform grid")
            h = np.ma.array(topo.heights(), dtype=np.float64, copy=True)
            unit = topo.unit
            sizes = topo.physical_sizes
            nx, ny = topo.nb_grid_pts
            del topo
            try:
                reader.close()
            except Exception:  # noqa: S110 - closing is best effort
                pass
    except FileFormatError:
        raise
    except Exception as exc:
        raise FileFormatError(p, _st_problem(p, exc)) from None
    try:
        fac = float(get_unit_conversion_factor(unit, "m"))
    except Exception:
        raise FileFormatError(p, f"unknown length unit {unit!r} in the file") from None
    z = np.ma.filled(np.ma.masked_invalid(np.ma.asarray(h, dtype=np.float64)), np.nan).T * fac
    sx, sy = float(sizes[0]) * fac, float(sizes[1]) * fac
    try:
        return HeightMap(z, sx / nx, sy / ny, str(p),
                         {"format": getattr(reader, "format", lambda: "?")(),
                          "unit": unit, "channels": len(channels)})
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None


def _first_line(exc: BaseException) -> str:
    text = str(exc).strip()
    return (text.splitlines()[0][:200] if text else type(exc).__name__)


def _formats_for_extension(p: Path) -> list[str]:
    from SurfaceTopography.IO import readers

    ext = p.suffix.lower().lstrip(".")
    return [r._format for r in readers if ext and ext in getattr(r, "_file_extensions", [])]


def _format_names(formats: list[str]) -> str:
    from SurfaceTopography.IO import readers

    names = {r._format: r.name() for r in readers}
    return " or ".join(names.get(f, f) for f in formats)


def _st_problem(p: Path, exc: BaseException) -> str:
    """A one-line description of why SurfaceTopography could not read ``p``: when format detection
    failed, the error of the reader that the file's extension names (the useful one)."""
    import warnings

    name = type(exc).__name__
    if name != "CannotDetectFileFormat":
        return f"SurfaceTopography cannot read it ({name}: {_first_line(exc)})"
    from SurfaceTopography import open_topography
    from SurfaceTopography.IO import readers

    ext = p.suffix.lower().lstrip(".")
    for r in readers:
        if ext and ext in getattr(r, "_file_extensions", []):
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    open_topography(str(p), format=r._format).topography().heights()
            except Exception as sub:
                return (f"cannot be read as {r.name()} (.{ext}): {_first_line(sub)} "
                        "(corrupt, truncated or another format)")
    return (f"not a scan format SurfaceTopography recognises (it tried {len(readers)} readers); "
            "the file is corrupt, truncated or in another format")


def read_scan(path: str | Path, *, pixel_size: Any = None, height_unit: str | None = None,
              channel: int | None = None) -> HeightMap:
    """Read a profilometer scan into a :class:`HeightMap` (SI).

    Instrument formats (Zygo DATX, Keyence VK, Sensofar PLU, Digital Surf SUR, Wyko OPD, X3P,
    Gwyddion, NetCDF, SDF, xyz, ...) go through ``SurfaceTopography.read_topography`` (optional
    dependency; imported here, lazily). Plain ``.npy`` (2D array) and ``.csv`` (rows = y, comma,
    semicolon or blank separated, empty cells = no data) height maps are read directly and need
    ``pixel_size`` (e.g. "2 um", metres for a bare number, or a (dx, dy) pair) and
    ``height_unit`` (e.g. "um"), unless the CSV has '# pixel_size: 2 um' / '# height_unit: um'
    lines. ``channel``: data channel of multi-channel instrument files.

    Raises :class:`FileFormatError` naming the file for a missing, corrupt, truncated or
    unrecognised file, :class:`MissingDependencyError` when SurfaceTopography is needed but absent.
    """
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    if p.stat().st_size == 0:
        raise FileFormatError(p, "empty file")
    suffix = p.suffix.lower()
    if suffix == ".npy" or (suffix in (".txt", ".asc") and pixel_size is not None):
        return _read_plain(p, pixel_size, height_unit)
    if suffix == ".csv":
        if pixel_size is not None or _has_pixel_header(p):
            return _read_plain(p, pixel_size, height_unit)
        # no pixel size: an x,y,z point list (SurfaceTopography's xyz reader) or an error
        try:
            return _read_surface_topography(p, None, height_unit, channel)
        except MissingDependencyError:
            raise
        except FileFormatError as exc:
            raise FileFormatError(p, "neither an x,y,z point list nor a height matrix with a "
                                     "known pixel size: pass pixel_size= and height_unit= (or "
                                     "add '# pixel_size: 2 um' and '# height_unit: um' lines); "
                                     f"xyz reader: {exc.problem}") from None
    return _read_surface_topography(p, pixel_size, height_unit, channel)


# ----------------------------------------------------------------------------------------------
# levelling
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class Levelled:
    """A levelled height map: ``z`` (ny, nx) [m] (NaN = no data) after subtracting the plane
    ``plane`` = (a, b, c) [m, -, -] (z_plane = a + b x + c y), the ``inliers`` used for the plane,
    the robust noise ``sigma`` [m] of the inliers, ``iterations``."""

    z: np.ndarray
    plane: tuple[float, float, float]
    inliers: np.ndarray
    sigma: float
    iterations: int


def level_plane(hm: HeightMap, *, k: float = 3.0, border: float = 0.12, max_iter: int = 30,
                exclude_dilation: int = 3) -> Levelled:
    """Fit and subtract a plane, robustly, so the dent and its pile-up do not bias it.

    Start from the pixels of a border frame (``border`` x the size on each side, outside the dent
    in a centred scan); then iterate: least-squares plane on the inliers, robust sigma of their
    residuals (1.4826 x median absolute deviation), new inliers = pixels within ``k`` sigma,
    with the outliers' neighbourhood (``exclude_dilation`` pixels) excluded too; stop when the
    inlier set no longer changes."""
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
        sigma = float(1.4826 * np.median(np.abs(r_in - np.median(r_in))))
        if sigma == 0.0:
            sigma = float(np.std(r_in)) or 1e-15
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
    return Levelled(zl, (float(coef[0]), float(coef[1]), float(coef[2])), inl, sigma, it)


# ----------------------------------------------------------------------------------------------
# the dent
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class DentMetrics:
    """The dent measured on a scan (SI; definitions in the module docstring).

    ``delta_p`` (maximum depth, > 0), ``L_s`` (length - width), ``length``, ``width``:
    :class:`Estimate` [m]. ``deepest`` (x, y) [m] in the scan; ``axis`` unit vector of the sliding
    axis (scan x, y) oriented along ``sliding_direction``; ``sliding_angle`` [deg] of that
    direction from the scan's +x axis; ``direction_ambiguous``; ``end_sharpness`` (80 %-to-20 %
    fall distance [m] at the start and at the end); ``deepest_fraction`` (position of the deepest
    point from the start, 0..1); ``pileup`` [m] and ``pileup_at`` (x, y); ``outline`` (k, 2) [m];
    ``edge_threshold``, ``noise`` [m]; ``plane``; ``dropout_fraction`` (whole scan) and
    ``filled_in_dent`` (fraction of the dent area interpolated); ``profile`` (s [m] along the axis
    from the deepest point, height [m]) and ``cross_profile`` (the same across it).
    """

    delta_p: Estimate
    L_s: Estimate
    length: Estimate
    width: Estimate
    deepest: tuple[float, float]
    axis: tuple[float, float]
    sliding_angle: float
    direction_ambiguous: bool
    end_sharpness: tuple[float, float]
    deepest_fraction: float
    pileup: float
    pileup_at: tuple[float, float]
    outline: np.ndarray = field(repr=False)
    edge_threshold: float = 0.0
    noise: float = 0.0
    plane: tuple[float, float, float] = (0.0, 0.0, 0.0)
    dropout_fraction: float = 0.0
    filled_in_dent: float = 0.0
    profile: tuple[np.ndarray, np.ndarray] = field(default=(np.zeros(0), np.zeros(0)),
                                                   repr=False)
    cross_profile: tuple[np.ndarray, np.ndarray] = field(default=(np.zeros(0), np.zeros(0)),
                                                         repr=False)
    levelled: HeightMap | None = field(default=None, repr=False)
    source: str = ""
    warnings: tuple[str, ...] = ()

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready summary (SI)."""
        return {
            "delta_p": self.delta_p.to_dict(),
            "L_s": self.L_s.to_dict(),
            "length": self.length.to_dict(),
            "width": self.width.to_dict(),
            "deepest_xy_m": list(self.deepest),
            "sliding_axis": list(self.axis),
            "sliding_angle_deg": self.sliding_angle,
            "direction_ambiguous": self.direction_ambiguous,
            "end_fall_distance_m": {"start": self.end_sharpness[0], "end": self.end_sharpness[1]},
            "deepest_fraction": self.deepest_fraction,
            "pileup_height_m": self.pileup,
            "pileup_xy_m": list(self.pileup_at),
            "edge_threshold_m": self.edge_threshold,
            "noise_m": self.noise,
            "plane": list(self.plane),
            "dropout_fraction": self.dropout_fraction,
            "filled_in_dent": self.filled_in_dent,
            "outline_points": int(self.outline.shape[0]),
            "source": self.source,
            "warnings": list(self.warnings),
        }


def _fill_nan(z: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Fill NaN pixels by normalised convolution (Gaussian-weighted mean of the valid
    neighbours), widening the kernel until every pixel is filled. Returns (filled, was_nan)."""
    nan = ~np.isfinite(z)
    if not nan.any():
        return z.copy(), nan
    w = (~nan).astype(np.float64)
    z0 = np.where(nan, 0.0, z)
    out = z.copy()
    todo = nan.copy()
    s = 1.0
    while todo.any() and s < max(z.shape):
        num = ndimage.gaussian_filter(z0, s, mode="nearest")
        den = ndimage.gaussian_filter(w, s, mode="nearest")
        ok = todo & (den > 0.05)
        out[ok] = num[ok] / den[ok]
        todo &= ~ok
        s *= 2.0
    out[todo] = np.nanmedian(z)
    return out, nan


def _outline(zs: np.ndarray, dx: float, dy: float, level: float, inside: tuple[float, float]
             ) -> np.ndarray | None:
    """The closed contour of ``zs`` at ``level`` that encloses the point ``inside`` (x, y) [m]
    (largest such); None if there is none."""
    import contourpy
    from matplotlib.path import Path as MplPath

    ny, nx = zs.shape
    gen = contourpy.contour_generator(np.arange(nx) * dx, np.arange(ny) * dy, zs,
                                      line_type=contourpy.LineType.Separate)
    best, best_area = None, -1.0
    for line in gen.lines(level):
        line = np.asarray(line)
        if line.shape[0] < 4 or not np.allclose(line[0], line[-1]):
            continue
        if not MplPath(line).contains_point(inside):
            continue
        x, y = line[:, 0], line[:, 1]
        area = 0.5 * abs(float(np.dot(x, np.roll(y, 1)) - np.dot(y, np.roll(x, 1))))
        if area > best_area:
            best, best_area = line, area
    return best


def _feret(outline: np.ndarray) -> tuple[float, np.ndarray]:
    """Largest Feret diameter of a polygon [m] and its direction (unit vector)."""
    from scipy.spatial import ConvexHull

    pts = outline[:-1] if np.allclose(outline[0], outline[-1]) else outline
    try:
        hull = pts[ConvexHull(pts).vertices]
    except Exception:
        hull = pts
    d = hull[:, None, :] - hull[None, :, :]
    dist = np.einsum("ijk,ijk->ij", d, d)
    i, j = np.unravel_index(int(np.argmax(dist)), dist.shape)
    vec = hull[j] - hull[i]
    length = float(np.linalg.norm(vec))
    return length, vec / length


def _chord(outline: np.ndarray, point: np.ndarray, direction: np.ndarray) -> tuple[float, float]:
    """Distances (negative side, positive side) from ``point`` along ``direction`` to the nearest
    crossings of the closed polygon ``outline``."""
    p0 = outline[:-1] - point
    p1 = outline[1:] - point
    n = np.array([-direction[1], direction[0]])
    s0 = p0 @ n
    s1 = p1 @ n
    cross = (s0 == 0) | (s0 * s1 < 0)
    if not cross.any():
        return math.nan, math.nan
    f = s0[cross] / (s0[cross] - s1[cross])
    pts = p0[cross] + f[:, None] * (p1[cross] - p0[cross])
    t = pts @ direction
    neg = t[t < 0]
    pos = t[t >= 0]
    return (float(-neg.max()) if neg.size else math.nan,
            float(pos.min()) if pos.size else math.nan)


def _sample(zs: np.ndarray, dx: float, dy: float, pts: np.ndarray) -> np.ndarray:
    return ndimage.map_coordinates(zs, [pts[:, 1] / dy, pts[:, 0] / dx], order=1, mode="nearest")


def _quadric_min(zl: np.ndarray, valid: np.ndarray, i0: int, j0: int, dx: float, dy: float,
                 radius: int, recentre: bool = False
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
    return float(y0[0]), float(math.sqrt(max(cy[0, 0], 0.0))), j0 * dx + float(y0[1]), \
        i0 * dy + float(y0[2]), inside


def _fall_distance(s: np.ndarray, z: np.ndarray, depth: float) -> float:
    """Distance along a profile (s >= 0 from the deepest point, z heights) over which the depth
    falls from 80 % to 20 % of ``depth`` (first crossings)."""
    d = -z

    def first_below(level: float) -> float:
        idx = np.flatnonzero(d < level)
        if idx.size == 0:
            return math.nan
        k = int(idx[0])
        if k == 0:
            return float(s[0])
        f = (d[k - 1] - level) / (d[k - 1] - d[k])
        return float(s[k - 1] + f * (s[k] - s[k - 1]))

    return first_below(0.2 * depth) - first_below(0.8 * depth)


def _edges_touched(region: np.ndarray) -> list[str]:
    names = []
    if region[:, 0].any():
        names.append("left (x = 0)")
    if region[:, -1].any():
        names.append("right (x max)")
    if region[0, :].any():
        names.append("bottom (y = 0)")
    if region[-1, :].any():
        names.append("top (y max)")
    return names


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
    """Level the scan, find the dent and measure it (definitions in the module docstring).

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
    src = hm.source or "scan"
    lev = level_plane(hm)
    zl = np.asarray(lev.z)
    valid = np.isfinite(zl)
    dropout_fraction = float(1.0 - valid.mean())
    zf, was_nan = _fill_nan(zl)
    zs = ndimage.gaussian_filter(zf, smooth, mode="nearest") if smooth > 0 else zf
    # noise of the smoothed map on the plane's inliers
    r = zs[lev.inliers]
    sig_s = float(1.4826 * np.median(np.abs(r - np.median(r)))) if r.size else lev.sigma
    sig_s = max(sig_s, 1e-15)
    # detection
    cand = zs < -detect_sigma * sig_s
    lab, nlab = ndimage.label(cand, structure=np.ones((3, 3)))
    deepest_val = float(np.min(zs))
    if nlab == 0:
        raise DentNotFoundError(
            f"{src}: no dent found: the deepest point is {-deepest_val * 1e6:.3g} um below the "
            f"levelled surface, less than the detection threshold {detect_sigma:g} x noise = "
            f"{detect_sigma * sig_s * 1e6:.3g} um")
    sizes = ndimage.sum(np.ones_like(zs), lab, index=np.arange(1, nlab + 1))
    depths = ndimage.minimum(zs, lab, index=np.arange(1, nlab + 1))
    good = [i for i in range(nlab) if sizes[i] >= min_pixels]
    if not good:
        raise DentNotFoundError(
            f"{src}: no dent found: the depressions below the detection threshold "
            f"({detect_sigma * sig_s * 1e6:.3g} um) cover at most {int(max(sizes))} pixels "
            f"(need {min_pixels}); dust or noise, not a dent")
    best = min(good, key=lambda i: depths[i])
    comp = lab == best + 1
    idx = int(np.argmin(np.where(comp, zs, np.inf)))
    i0, j0 = np.unravel_index(idx, zs.shape)
    depth_rough = -float(zs[i0, j0])
    thr = max(edge_sigma * sig_s, edge_fraction * depth_rough)
    lab2, _ = ndimage.label(zs < -thr, structure=np.ones((3, 3)))
    region = ndimage.binary_fill_holes(lab2 == lab2[i0, j0])
    edges = _edges_touched(region)
    if edges:
        raise DentCutOffError(
            f"{src}: the dent is cut off by the scan's {' and '.join(edges)} edge: its outline "
            f"(depth {thr * 1e6:.3g} um) reaches the edge, so its length cannot be measured; "
            "scan a larger area around the dent")
    filled = float(was_nan[region].mean())
    if filled > max_filled:
        raise ScanError(f"{src}: {filled:.0%} of the dent area has no data (dropouts); at most "
                        f"{max_filled:.0%} can be interpolated")
    warnings: list[str] = []
    if filled > 0.05:
        warnings.append(f"{filled:.0%} of the dent area was interpolated over dropouts")
    dx, dy = hm.dx, hm.dy
    p_rough = (float(j0 * dx), float(i0 * dy))
    outline = _outline(zs, dx, dy, -thr, p_rough)
    if outline is None:
        raise ScanError(f"{src}: no closed outline around the deepest point at {-thr * 1e6:.3g} "
                        "um; the dent is too irregular to measure")
    # delta_p: a paraboloid at the deepest pixel, over a disc where the bottom's curvature (radius
    # R_c ~ width^2 / (8 depth), a spherical cap) rises ~10 noise sigmas above the noise
    _, ax0 = _feret(outline)
    a0, b0 = _chord(outline, np.array(p_rough), np.array([-ax0[1], ax0[0]]))
    w0 = (a0 + b0) if math.isfinite(a0 + b0) else 0.0
    r_c = w0 * w0 / (8.0 * max(depth_rough, 1e-12)) if w0 > 0 else 0.0
    rad_phys = math.sqrt(20.0 * r_c * lev.sigma) if r_c > 0 else 0.0
    rad0 = int(min(max(quad_radius, math.ceil(rad_phys / min(dx, dy))), 40))
    q = None
    for rad in (rad0, 2 * rad0, 3 * rad0):
        ic, jc = int(i0), int(j0)
        for _ in range(3):
            q = _quadric_min(zl, valid, ic, jc, dx, dy, rad, recentre=True)
            if q is None or q[4]:
                break
            ic = min(max(int(round(q[3] / dy)), 0), zl.shape[0] - 1)
            jc = min(max(int(round(q[2] / dx)), 0), zl.shape[1] - 1)
        if q is not None and q[4]:
            break
        q = None
    if q is None:
        zmin, zsig, xm, ym = float(zs[i0, j0]), lev.sigma, float(j0 * dx), float(i0 * dy)
        warnings.append("no paraboloid minimum at the deepest point; delta_p is the smoothed "
                        "minimum")
    else:
        zmin, zsig, xm, ym = q[:4]
    depth = -zmin
    deepest = np.array([xm, ym])

    def metrics_at(level: float) -> tuple[float, float, np.ndarray] | None:
        ol = _outline(zs, dx, dy, -level, (xm, ym))
        if ol is None:
            return None
        L, ax = _feret(ol)
        perp = np.array([-ax[1], ax[0]])
        a, b = _chord(ol, deepest, perp)
        return L, a + b, ax

    m1 = metrics_at(thr)
    assert m1 is not None
    length, width, axis = m1
    if not math.isfinite(width):
        raise ScanError(f"{src}: the outline does not cross the line through the deepest point")
    m2 = metrics_at(2.0 * thr) if depth > 4.0 * thr else None
    length_t, width_t = length, width  # at the threshold
    if m2 is not None:
        # the outline shrinks about linearly with the threshold near the dent's edge: extrapolate
        # the length and the width to the threshold 0 (the deformed area's true edge)
        length = 2.0 * length_t - m2[0]
        width = 2.0 * width_t - m2[1]
    # profiles through the deepest point, along and across the axis
    step = 0.5 * min(dx, dy)
    half_len = length + 2 * width
    s = np.arange(-half_len, half_len + step, step)
    line = deepest[None, :] + s[:, None] * axis[None, :]
    inside = (line[:, 0] >= 0) & (line[:, 0] <= (zs.shape[1] - 1) * dx) & \
        (line[:, 1] >= 0) & (line[:, 1] <= (zs.shape[0] - 1) * dy)
    s, line = s[inside], line[inside]
    prof = _sample(zs, dx, dy, line)
    perp = np.array([-axis[1], axis[0]])
    sc = np.arange(-width * 1.5, width * 1.5 + step, step)
    cl = deepest[None, :] + sc[:, None] * perp[None, :]
    okc = (cl[:, 0] >= 0) & (cl[:, 0] <= (zs.shape[1] - 1) * dx) & (cl[:, 1] >= 0) & \
        (cl[:, 1] <= (zs.shape[0] - 1) * dy)
    sc, cl = sc[okc], cl[okc]
    cprof = _sample(zs, dx, dy, cl)
    # the sharper end = the end of the sliding
    fwd = s >= 0
    bwd = s <= 0
    d_plus = _fall_distance(s[fwd], prof[fwd], depth)
    d_minus = _fall_distance(-s[bwd][::-1], prof[bwd][::-1], depth)
    if math.isfinite(d_plus) and math.isfinite(d_minus) and d_plus > d_minus:
        axis = -axis  # the sharper end lies on the minus side
        s = -s[::-1]
        prof = prof[::-1]
        d_plus, d_minus = d_minus, d_plus
    ambiguous = not (math.isfinite(d_plus) and math.isfinite(d_minus)) or \
        abs(d_minus - d_plus) < 0.1 * max(d_minus, d_plus)
    # extent along the axis from the outline, for the deepest point's position
    proj = (outline - deepest) @ axis
    s_start, s_end = float(proj.min()), float(proj.max())
    frac = -s_start / (s_end - s_start) if s_end > s_start else 0.5
    # uncertainties: threshold sensitivity (t_e -> 2 t_e) and the outline noise at the crossings
    slope_terms = []
    for sv, pv in ((s, prof), (sc, cprof)):
        g = np.gradient(pv, sv)
        for target in (s_start, s_end) if sv is s else (-0.5 * width, 0.5 * width):
            k = int(np.argmin(np.abs(sv - target)))
            sl = abs(float(g[k]))
            if sl > 0:
                slope_terms.append((sig_s / sl) ** 2)
    noise_len = math.sqrt(sum(slope_terms[:2])) if len(slope_terms) >= 2 else 0.0
    noise_wid = math.sqrt(sum(slope_terms[2:])) if len(slope_terms) >= 4 else 0.0
    if m2 is not None:
        # a quarter of the extrapolation's correction (its non-linearity) and the outline noise,
        # amplified by the extrapolation (2 x1 - x2: about sqrt(5))
        d_len = 0.25 * abs(length - length_t)
        d_wid = 0.25 * abs(width - width_t)
        d_ls = 0.25 * abs((length - width) - (length_t - width_t))
        amp = math.sqrt(5.0)
    else:
        d_len, d_wid, d_ls = abs(0.5 * thr / max(depth, 1e-30) * length), 0.0, 0.0
        amp = 1.0
        warnings.append("the dent is too shallow to extrapolate its outline to the zero "
                        "threshold; length and width are taken at the threshold")
    sig_len = math.hypot(d_len, amp * noise_len)
    sig_wid = math.hypot(d_wid, amp * noise_wid)
    sig_ls = math.sqrt(d_ls ** 2 + amp ** 2 * (noise_len ** 2 + noise_wid ** 2))
    # fit noise, plus an allowance of a quarter of the noise sigma for the levelling plane and the
    # paraboloid's model error (validated on the synthetic grooves of the tests)
    sig_depth = math.sqrt(zsig ** 2 + (0.25 * lev.sigma) ** 2)
    # pile-up
    band_px = max(2, int(round(pileup_band * width / min(dx, dy))))
    band = ndimage.binary_dilation(region, iterations=band_px) & ~region & valid
    if band.any():
        zb = np.where(band, zs, -np.inf)
        kb = int(np.argmax(zb))
        ib, jb = np.unravel_index(kb, zs.shape)
        pileup = max(float(zs[ib, jb]), 0.0)
        pile_at = (float(jb * dx), float(ib * dy))
    else:
        pileup, pile_at = 0.0, (math.nan, math.nan)
    ang = math.degrees(math.atan2(axis[1], axis[0]))
    lev_map = HeightMap(zl, dx, dy, hm.source, {"levelled": True})
    return DentMetrics(
        delta_p=Estimate(depth, sig_depth, "m"),
        L_s=Estimate(length - width, sig_ls, "m"),
        length=Estimate(length, sig_len, "m"),
        width=Estimate(width, sig_wid, "m"),
        deepest=(float(deepest[0]), float(deepest[1])),
        axis=(float(axis[0]), float(axis[1])),
        sliding_angle=ang,
        direction_ambiguous=bool(ambiguous),
        end_sharpness=(float(d_minus), float(d_plus)),
        deepest_fraction=float(frac),
        pileup=pileup,
        pileup_at=pile_at,
        outline=outline,
        edge_threshold=thr,
        noise=lev.sigma,
        plane=lev.plane,
        dropout_fraction=dropout_fraction,
        filled_in_dent=filled,
        profile=(s, prof),
        cross_profile=(sc, cprof),
        levelled=lev_map,
        source=hm.source,
        warnings=tuple(warnings),
    )
