"""Reading a profilometer scan: instrument formats or plain height maps, by extension."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from impactlab.experiment.checks import check_path
from impactlab.experiment.errors import FileFormatError, MissingDependencyError
from impactlab.experiment.profilometry.heightmap import HeightMap
from impactlab.experiment.profilometry.instrument import read_instrument
from impactlab.experiment.profilometry.plain import has_pixel_header, looks_like_xyz, read_plain
from impactlab.experiment.textfiles import read_text

__all__ = ["read_scan"]


def read_scan(
    path: str | Path,
    *,
    pixel_size: Any = None,
    height_unit: str | None = None,
    channel: int | None = None,
) -> HeightMap:
    """Read a profilometer scan into a :class:`HeightMap` (SI).

    Instrument formats (Zygo DATX, Keyence VK, Sensofar PLU, Digital Surf SUR, Wyko OPD, X3P,
    Gwyddion, NetCDF, SDF, xyz, ...) go through SurfaceTopography (the optional dependency
    ``impactlab[profilometry]``, imported on use). Plain ``.npy`` (2D array) and ``.csv`` (rows =
    y, comma, semicolon or blank separated, empty cells = no data) height maps are read directly
    and need ``pixel_size`` (e.g. "2 um", metres for a bare number, or a (dx, dy) pair) and
    ``height_unit`` (e.g. "um"), unless the file has '# pixel_size: 2 um' / '# height_unit: um'
    lines (a .txt or .asc file with such lines is such a map too; one without them whose lines
    hold three numbers is read as an x,y,z point list, as .xyz). A pixel size or height unit
    that the file states (such lines, an instrument file's own) is the file's: one given as well
    must agree with it (FileFormatError naming both otherwise). ``channel``: data channel of
    multi-channel instrument files.

    Raises :class:`FileFormatError` naming the file for a missing, corrupt, truncated or
    unrecognised file, :class:`MissingDependencyError` when SurfaceTopography is needed but absent.
    """
    p = check_path(path, "path")
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    if p.stat().st_size == 0:
        raise FileFormatError(p, "empty file")
    suffix = p.suffix.lower()
    if suffix in (".csv", ".txt", ".asc"):
        with open(p, "rb") as f:
            if f.read(2) in (b"\xff\xfe", b"\xfe\xff"):  # UTF-16: named before any reader
                read_text(p, "CSV" if suffix == ".csv" else "text")
    plain_text = suffix in (".txt", ".asc") and (pixel_size is not None or has_pixel_header(p))
    if suffix == ".npy" or plain_text:
        return read_plain(p, pixel_size, height_unit)
    if suffix in (".txt", ".asc") and looks_like_xyz(p):  # an x,y,z point list saved as text
        return read_instrument(p, None, height_unit, channel, fmt="xyz")
    if suffix == ".csv":
        if pixel_size is not None or has_pixel_header(p):
            return read_plain(p, pixel_size, height_unit)
        # no pixel size: an x,y,z point list (SurfaceTopography's xyz reader) or an error
        try:
            return read_instrument(p, None, height_unit, channel)
        except MissingDependencyError:
            raise
        except FileFormatError as exc:
            raise FileFormatError(
                p,
                "neither an x,y,z point list nor a height matrix with a "
                "known pixel size: pass pixel_size= and height_unit= (or "
                "add '# pixel_size: 2 um' and '# height_unit: um' lines); "
                f"xyz reader: {exc.problem}",
            ) from None
    return read_instrument(p, pixel_size, height_unit, channel)
