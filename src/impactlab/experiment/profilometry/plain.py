"""Plain height maps: a 2D ``.npy`` array or a ``.csv`` matrix (rows = y), with the pixel size
and the height unit from ``# pixel_size:`` / ``# height_unit:`` lines or from the caller (who
must agree with such lines)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._validation import read_text_file
from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry.heightmap import HeightMap, pixel_pair
from impactlab.experiment.profilometry.stated import check_height_unit, check_pixel_size
from impactlab.experiment.textfiles import split_commented

__all__ = ["has_pixel_header", "read_plain"]


def _load_npy(p: Path) -> np.ndarray:
    try:
        z = np.load(p, allow_pickle=False)
    except (ValueError, OSError, EOFError) as exc:
        raise FileFormatError(
            p, f"not a readable NPY array ({type(exc).__name__}: {str(exc)[:160]})"
        ) from None
    if isinstance(z, np.lib.npyio.NpzFile):
        z.close()
        raise FileFormatError(
            p, "not a readable NPY array (it is a zip/NPZ archive); save one 2D array with np.save"
        )
    if not isinstance(z, np.ndarray):
        raise FileFormatError(p, f"not a readable NPY array (np.load gives {type(z).__name__})")
    if z.ndim != 2 or not np.issubdtype(z.dtype, np.number):
        raise FileFormatError(
            p, f"expected a 2D numeric array, got shape {z.shape}, dtype {z.dtype}"
        )
    return z.astype(np.float64)


def _load_text(p: Path) -> tuple[np.ndarray, dict[str, str]]:
    """(heights in the file's unit, the '# key: value' header) of a CSV/text matrix; comma,
    semicolon or blank separated, empty cells (or nan, bad, na) are no data."""
    try:
        text = read_text_file(p, "CSV")
    except ValueError as exc:  # not UTF-8 text
        raise FileFormatError(p, str(exc)) from None
    rows: list[list[float]] = []
    header, lines = split_commented(text)
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
            raise FileFormatError(
                p,
                f"line {ln}: {len(vals)} values, but the first row has "
                f"{len(rows[0])} (truncated or ragged height map)",
            )
        rows.append(vals)
    if not rows:
        raise FileFormatError(p, "no data rows")
    return np.array(rows), dict(header)


def read_plain(p: Path, pixel_size: Any, height_unit: str | None) -> HeightMap:
    """A plain ``.npy`` or CSV/text height map; ``pixel_size`` and ``height_unit`` as in
    :func:`impactlab.experiment.read_scan`: needed unless the CSV's header lines state them, and
    refused when they disagree with those lines (:mod:`.stated`)."""
    meta: dict[str, str] = {}
    if p.suffix.lower() == ".npy":
        z = _load_npy(p)
    else:
        z, meta = _load_text(p)
    dx, dy = _pixel_size(p, pixel_size, meta)
    fac, unit = _height_unit(p, height_unit, meta)
    try:
        return HeightMap(
            z * fac, dx, dy, str(p), {"format": p.suffix.lower().lstrip("."), "height_unit": unit}
        )
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None


def _pixel_size(p: Path, pixel_size: Any, meta: dict[str, str]) -> tuple[float, float]:
    """(dx, dy) [m]: the header's ('# pixel_size:', '# pixel_size_y:'), which ``pixel_size``
    must agree with, else ``pixel_size``."""
    if "pixel_size" not in meta:
        if pixel_size is None:
            raise FileFormatError(
                p,
                "a plain height map needs the pixel size: pass pixel_size= "
                "(e.g. '2 um'; --pixel-size) or add '# pixel_size: 2 um'",
            )
        stated: Any = pixel_size
    else:
        stated = meta["pixel_size"]
        if "pixel_size_y" in meta:
            stated = (stated, meta["pixel_size_y"])
    try:
        dxy = pixel_pair(stated)
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    if pixel_size is not None and "pixel_size" in meta:
        lines = [f"# {k}: {meta[k]}" for k in ("pixel_size", "pixel_size_y") if k in meta]
        check_pixel_size(p, pixel_size, dxy, f"'{' and '.join(lines)}'")
    return dxy


def _height_unit(p: Path, height_unit: str | None, meta: dict[str, str]) -> tuple[float, str]:
    """(metres per height unit, the unit): the header's '# height_unit:', which
    ``height_unit`` must agree with, else ``height_unit``."""
    stated = meta.get("height_unit")
    unit = stated if stated is not None else height_unit
    if unit is None:
        raise FileFormatError(
            p,
            "a plain height map needs the height unit: pass height_unit= "
            "(e.g. 'um'; --height-unit) or add '# height_unit: um'",
        )
    try:
        fac = length_factor(unit, name="height_unit")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    if stated is not None and height_unit is not None:
        check_height_unit(p, height_unit, fac, stated, f"'# height_unit: {stated}'")
    return fac, unit


def has_pixel_header(p: Path) -> bool:
    """True when one of the first 50 lines of the text file ``p`` is a pixel_size line."""
    try:
        with p.open("r", encoding="utf-8-sig", errors="replace") as fh:
            for _, line in zip(range(50), fh, strict=False):
                s = line.strip().lstrip("#").strip().lower()
                if s.startswith("pixel_size"):
                    return True
    except OSError:
        return False
    return False
