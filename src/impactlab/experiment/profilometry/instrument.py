"""Instrument scan formats through SurfaceTopography (an optional extra, imported on use).

Zygo DATX, Keyence VK, Sensofar PLU, Digital Surf SUR, Wyko OPD, X3P, Gwyddion, NetCDF, SDF,
xyz, ... are read with ``SurfaceTopography.open_topography``. A pixel size or height unit given
by the caller supplies what the file lacks; where the file states it, the two must agree. When
its content detection disagrees with the file's extension, the extension's reader decides; when a
file cannot be read, the message names the file and the reader's own error. SurfaceTopography's
readers raise assorted exception types on corrupt or truncated files, so those calls are caught
broadly and re-raised as :class:`~impactlab.experiment.FileFormatError`; a missing package raises
:class:`~impactlab.experiment.MissingDependencyError` naming the extra to install.
"""

from __future__ import annotations

import contextlib
import warnings
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import numpy as np

from impactlab.experiment.errors import FileFormatError, MissingDependencyError
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry.heightmap import HeightMap, pixel_pair
from impactlab.experiment.profilometry.stated import check_height_unit, check_pixel_size

__all__ = ["INSTALL", "read_instrument"]

#: How to install the optional dependency.
INSTALL = "pip install 'impactlab[profilometry]' (or: pip install SurfaceTopography)"

#: Optional packages that SurfaceTopography may need for some formats -> the extra to install.
_EXTRAS = {"netCDF4": "pip install 'impactlab[netcdf]'"}


def _surface_topography(p: Path) -> SimpleNamespace:
    """SurfaceTopography's reader entry points; MissingDependencyError when it is absent."""
    # an optional extra: imported here, so the package and plain height maps work without it
    try:
        from SurfaceTopography import open_topography
        from SurfaceTopography.IO import readers
        from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor
    except ImportError:
        raise MissingDependencyError(
            f"{p}: reading instrument scan formats needs the optional package SurfaceTopography: "
            f"{INSTALL}; plain .npy/.csv height maps work without it"
        ) from None
    return SimpleNamespace(
        open=open_topography, readers=readers, unit_factor=get_unit_conversion_factor
    )


def _first_line(exc: BaseException) -> str:
    """The first line of a reader's error, its control characters escaped (a binary header it
    quotes, ``PK\\x03\\x04``, would print raw on the terminal), at most 200 characters."""
    text = str(exc).strip()
    if not text:
        return type(exc).__name__
    line = text.splitlines()[0]
    line = "".join(c if c.isprintable() else ascii(c)[1:-1] for c in line)
    return line[:200]


def _formats_for_extension(st: SimpleNamespace, p: Path) -> list[str]:
    ext = p.suffix.lower().lstrip(".")
    return [r._format for r in st.readers if ext and ext in getattr(r, "_file_extensions", [])]


def _format_names(st: SimpleNamespace, formats: list[str]) -> str:
    names = {r._format: r.name() for r in st.readers}
    return " or ".join(names.get(f, f) for f in formats)


def _st_problem(st: SimpleNamespace, p: Path, exc: BaseException) -> str:
    """A one-line description of why SurfaceTopography could not read ``p``: when format detection
    failed, the error of the reader that the file's extension names (the useful one)."""
    name = type(exc).__name__
    if name != "CannotDetectFileFormat":
        return f"SurfaceTopography cannot read it ({name}: {_first_line(exc)})"
    ext = p.suffix.lower().lstrip(".")
    for r in st.readers:
        if ext and ext in getattr(r, "_file_extensions", []):
            try:
                with warnings.catch_warnings():
                    warnings.simplefilter("ignore")
                    st.open(str(p), format=r._format).topography().heights()
            except Exception as sub:  # the reader's own error on this file
                return (
                    f"cannot be read as {r.name()} (.{ext}): {_first_line(sub)} "
                    "(corrupt, truncated or another format)"
                )
    return (
        f"not a scan format SurfaceTopography recognises (it tried {len(st.readers)} "
        "readers); the file is corrupt, truncated or in another format"
    )


def _open_reader(st: SimpleNamespace, p: Path, fmt: str | None = None) -> Any:
    """The reader for ``p``: the format ``fmt`` (SurfaceTopography's name) where given, else
    content detection, overruled by the extension's readers when they disagree (e.g. any file
    of 2 n^2 bytes passes for a NASA SRTM tile)."""
    if fmt is not None:
        return st.open(str(p), format=fmt)
    reader = st.open(str(p))
    ext_formats = _formats_for_extension(st, p)
    if not ext_formats or reader.format() in ext_formats:
        return reader
    detected = reader.name()
    errors = []
    for fmt in ext_formats:
        try:
            reader = st.open(str(p), format=fmt)
            reader.topography().heights()
        except Exception as sub:  # this reader cannot read the file: try the next one
            errors.append(_first_line(sub))
        else:
            return reader
    raise FileFormatError(
        p,
        f"cannot be read as {_format_names(st, ext_formats)} ({p.suffix}): "
        f"{'; '.join(errors)} (SurfaceTopography's content detection takes it for {detected}; "
        "corrupt, truncated or another format)",
    )


def _topography_kwargs(
    st: SimpleNamespace, p: Path, reader: Any, ch: Any, pixel_size: Any, height_unit: str | None
) -> dict[str, Any]:
    """The physical size and unit that the file lacks, from the caller; a pixel size or height
    unit the file states as well must agree with it (:mod:`.stated`)."""
    kwargs: dict[str, Any] = {}
    if ch.unit is None:
        if height_unit is None:
            raise FileFormatError(
                p,
                f"SurfaceTopography reads it as {reader.name()}, which gives "
                "no length unit; pass height_unit=",
            )
        kwargs["unit"] = height_unit
    elif height_unit is not None:
        check_height_unit(p, height_unit, _to_m(st, p, ch.unit), str(ch.unit), _stated(reader))
    if ch.physical_sizes is None:
        if pixel_size is None:
            raise FileFormatError(
                p,
                f"SurfaceTopography reads it as {reader.name()}, which gives "
                "no physical size; if that is the right format pass "
                "pixel_size=, else the file is corrupt or in another format",
            )
        try:
            dxy = pixel_pair(pixel_size, "pixel_size (--pixel-size)")
        except ValueError as exc:
            raise FileFormatError(p, str(exc)) from None
        # SurfaceTopography takes the sizes in the heights' unit (the file's, else the given
        # one), which the reader then turns into m with the heights
        try:
            fac = _to_m(st, p, ch.unit) if ch.unit else length_factor(str(height_unit))
        except ValueError as exc:
            raise FileFormatError(p, str(exc)) from None
        n = ch.nb_grid_pts
        kwargs["physical_sizes"] = (n[0] * dxy[0] / fac, n[1] * dxy[1] / fac)
    elif pixel_size is not None and len(ch.nb_grid_pts) == 2:
        # the sizes are in the file's unit, else in the given one (an x,y,z list has none)
        try:
            fac = _to_m(st, p, ch.unit) if ch.unit else length_factor(str(height_unit))
        except ValueError as exc:
            raise FileFormatError(p, str(exc)) from None
        sizes, n = ch.physical_sizes, ch.nb_grid_pts
        stated = (float(sizes[0]) * fac / n[0], float(sizes[1]) * fac / n[1])
        check_pixel_size(p, pixel_size, stated, _stated(reader))
    return kwargs


def _stated(reader: Any) -> str:
    return f"stated in this {reader.name()} file"


def _to_m(st: SimpleNamespace, p: Path, unit: Any) -> float:
    """Metres per the file's length ``unit``; FileFormatError for a unit SurfaceTopography does
    not know."""
    try:
        return float(st.unit_factor(unit, "m"))
    except Exception:  # an unknown unit string in the file: SurfaceTopography's error types vary
        raise FileFormatError(p, f"unknown length unit {unit!r} in the file") from None


def _read(
    st: SimpleNamespace,
    p: Path,
    pixel_size: Any,
    height_unit: str | None,
    channel: int | None,
    fmt: str | None = None,
) -> tuple[Any, dict[str, Any]]:
    """(reader, the topography's heights, unit, sizes and grid) of one channel."""
    reader = _open_reader(st, p, fmt)
    channels = reader.channels
    if channel is not None and not 0 <= channel < len(channels):
        raise FileFormatError(
            p, f"channel {channel} does not exist; the file has {len(channels)} channels"
        )
    ch = channels[channel if channel is not None else reader.default_channel.index]
    kwargs = _topography_kwargs(st, p, reader, ch, pixel_size, height_unit)
    topo = reader.topography(channel_index=channel, **kwargs)
    if topo.dim != 2:
        raise FileFormatError(
            p, "the scan is a line profile (1D); a 2D height map of the dent is needed"
        )
    if not topo.is_uniform:
        raise FileFormatError(p, "the scan is not on a uniform grid")
    data = {
        "heights": np.ma.array(topo.heights(), dtype=np.float64, copy=True),
        "unit": topo.unit,
        "sizes": topo.physical_sizes,
        "grid": topo.nb_grid_pts,
        "channels": len(channels),
    }
    del topo
    with contextlib.suppress(Exception):
        reader.close()
    return reader, data


def read_instrument(
    p: Path,
    pixel_size: Any,
    height_unit: str | None,
    channel: int | None,
    fmt: str | None = None,
) -> HeightMap:
    """Read an instrument scan with SurfaceTopography into a :class:`HeightMap` (SI); ``fmt``:
    SurfaceTopography's format name (``"xyz"``), default from the file."""
    st = _surface_topography(p)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            reader, data = _read(st, p, pixel_size, height_unit, channel, fmt)
    except FileFormatError:
        raise
    except ImportError as exc:  # a package that SurfaceTopography needs for this format
        hint = _EXTRAS.get(exc.name or "", f"pip install {exc.name}")
        raise MissingDependencyError(
            f"{p}: SurfaceTopography needs the optional package {exc.name} to read it: {hint}"
        ) from None
    except Exception as exc:  # SurfaceTopography raises assorted types on corrupt files
        raise FileFormatError(p, _st_problem(st, p, exc)) from None
    unit = data["unit"]
    fac = _to_m(st, p, unit)
    h, sizes = data["heights"], data["sizes"]
    nx, ny = data["grid"]
    z = np.ma.filled(np.ma.masked_invalid(np.ma.asarray(h, dtype=np.float64)), np.nan).T * fac
    sx, sy = float(sizes[0]) * fac, float(sizes[1]) * fac
    try:
        return HeightMap(
            z,
            sx / nx,
            sy / ny,
            str(p),
            {
                "format": getattr(reader, "format", lambda: "?")(),
                "unit": unit,
                "channels": data["channels"],
            },
        )
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
