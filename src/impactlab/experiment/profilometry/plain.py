"""Plain height maps: a 2D ``.npy`` array or a ``.csv`` matrix (rows = y), with the pixel size
and the height unit from ``# pixel_size:`` / ``# height_unit:`` lines or from the caller (who
must agree with such lines)."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers import length_factor
from impactlab.experiment.profilometry.heightmap import HeightMap, pixel_pair
from impactlab.experiment.profilometry.stated import check_height_unit, check_pixel_size
from impactlab.experiment.textfiles import (
    not_a_number,
    parse_number,
    read_text,
    split_commented,
)

__all__ = ["has_pixel_header", "looks_like_xyz", "read_plain"]


#: How a .npy file starts (numpy's format) and how an .npz (a zip archive) does.
_NPY_MAGIC = b"\x93NUMPY"
_ZIP_MAGIC = b"PK\x03\x04"


def _load_npy(p: Path) -> np.ndarray:
    try:
        with p.open("rb") as fh:
            head = fh.read(len(_NPY_MAGIC))
    except OSError as exc:
        raise FileFormatError(p, f"cannot be read ({exc.strerror or exc})") from None
    if head != _NPY_MAGIC and not head.startswith(_ZIP_MAGIC):
        raise FileFormatError(
            p,
            "not a .npy file: it does not start with the NPY signature (\\x93NUMPY); a damaged "
            "file or another format (save the height map with np.save)",
        )
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
    if np.iscomplexobj(z):  # a cast would drop the imaginary part silently
        raise FileFormatError(
            p,
            f"not a real height map: dtype {z.dtype} is complex; save the real heights "
            "(np.save(path, z.real) where the imaginary part is zero)",
        )
    return z.astype(np.float64)


def _separator(lines: list[tuple[int, str]]) -> str | None:
    """The cells' separator of a text matrix: a semicolon, else a tab, else a comma that every
    line has (a comma beside semicolons or tabs is a decimal comma; a stray tab or semicolon on
    a few lines of a comma file is not a separator); where none is on every line, the one on
    most lines; None: blanks."""
    seps = (";", "\t", ",")
    counts = [sum(sep in line for _, line in lines) for sep in seps]
    for sep, n in zip(seps, counts, strict=True):
        if lines and n == len(lines):
            return sep
    best = max(range(len(seps)), key=lambda i: counts[i])  # ties: the order above
    return seps[best] if counts[best] else None


def _cells(line: str, sep: str | None) -> list[str]:
    """The cells of one line: one cell between two separators (an empty one is no data), the
    leading and trailing ones kept; blanks: a run of them is one separator (no empty cells)."""
    if sep is None:
        return line.split()
    if sep == "\t":
        return line.split("\t")  # a blank around a cell is not a separator here
    return line.strip().split(sep)


def _load_text(p: Path) -> tuple[np.ndarray, dict[str, str]]:
    """(heights in the file's unit, the '# key: value' header) of a CSV/text matrix; comma,
    semicolon, tab or blank separated (decimal commas read where the cells are not separated
    by commas), empty cells (or nan, bad, na) are no data (one cell between two commas,
    semicolons or tabs; blanks cannot mark an empty cell)."""
    text = read_text(p, "CSV")
    rows: list[list[float]] = []
    try:
        header, lines = split_commented(text, keep_tab_lines=True)
    except ValueError as exc:  # a key stated twice, differently
        raise FileFormatError(p, str(exc)) from None
    sep = _separator(lines)
    for ln, line in lines:
        cells = _cells(line, sep)
        vals = []
        for c in cells:
            c = c.strip()
            if c == "" or c.lower() in ("nan", "bad", "na"):
                vals.append(math.nan)
                continue
            try:
                value = parse_number(c, sep)
            except ValueError:
                raise FileFormatError(p, f"line {ln}: {not_a_number(c)}") from None
            if not math.isfinite(value):  # 'inf', '1e400': not a height, nor a mark of none
                raise FileFormatError(
                    p,
                    f"line {ln}: the cell {c!r} is not a finite height; mark a pixel without "
                    "data by an empty cell, nan, bad or na",
                )
            vals.append(value)
        if rows and len(vals) != len(rows[0]):
            raise FileFormatError(
                p,
                f"line {ln}: {len(vals)} values, but the first row has "
                f"{len(rows[0])} (truncated or ragged height map)",
            )
        rows.append(vals)
    if not rows:
        raise FileFormatError(p, "no data rows")
    z = np.array(rows)
    _refuse_axes(p, z)
    return z, dict(header)


def _refuse_axes(p: Path, z: np.ndarray) -> None:
    """FileFormatError for a matrix exported with its coordinates, as spreadsheets and some scan
    software write them: an empty corner cell, then a first row (the x axis) and a first column
    (y) that each run evenly, up or down, to the precision they were printed at, and are not
    both continued by the second row and column as a tilted map's edges are; read as heights
    they make a ridge."""
    if z.shape[0] < 4 or z.shape[1] < 4 or not math.isnan(z[0, 0]):
        return
    x, y = z[0, 1:], z[1:, 0]
    bx, by = _axis_step(x), _axis_step(y)
    if bx is None or by is None or (_continued(x, z[1, 1:]) and _continued(y, z[1:, 1])):
        return
    raise FileFormatError(
        p,
        f"its first row ({x[0]:g}, {x[1]:g}, {x[2]:g}, ...) and first column ({y[0]:g}, "
        f"{y[1]:g}, ...) run evenly from an empty corner: coordinates, not heights; export "
        "the heights alone (no axes), or delete that row and column, and give the pixel "
        f"size (here {abs(bx):g} in the coordinates' unit)",
    )


def _axis_step(v: np.ndarray) -> float | None:
    """The step of ``v`` as a coordinate axis, in the fewest digits that fit: values strictly
    rising or falling that a line fits to within 1 % of the step or, from 8 values on, one
    unit of their last printed decimal (0.013, 0.025, 0.038: 0.0125); None where ``v`` is no
    such axis."""
    step = np.diff(v)
    if not np.all(np.isfinite(v)) or not (np.all(step > 0) or np.all(step < 0)):
        return None
    i = np.arange(v.size, dtype=np.float64)
    b = float(np.polyfit(i, v, 1)[0])
    tol = max(0.01 * abs(b), _last_digit(v) if v.size >= 8 else 0.0)
    for digits in range(1, 18):  # v - short * i spreads 2 tol at most: a line within tol
        short = float(f"{b:.{digits}g}")
        if np.ptp(v - short * i) <= 2.0 * tol:
            return short
    return None


def _last_digit(v: np.ndarray) -> float:
    """One unit of the last decimal that the values were printed with (1e-3 for 0.013, 0.025;
    1 for 16, 32), found from the parsed values; 0 where they carry more than 12 decimals."""
    for d in range(13):
        scaled = v * 10.0**d
        if np.max(np.abs(scaled)) > 1e12:
            break
        if np.all(np.abs(scaled - np.rint(scaled)) <= 1e-6):
            return 10.0**-d
    return 0.0


def _continued(edge: np.ndarray, nxt: np.ndarray) -> bool:
    """True where ``nxt`` (the second row or column) follows ``edge`` at a near-constant
    offset (its 10-90 % spread within 5 % of the edge's range), as a map's neighbouring rows
    do (a tilted plane); coordinates are not continued, unless the heights rise at nearly
    their rate."""
    d = edge - nxt
    d = d[np.isfinite(d)]
    if d.size < 2:
        return False
    lo, hi = np.percentile(d, [10.0, 90.0])  # a spike or two in a row is no trend
    return bool(hi - lo < 0.05 * np.ptp(edge))


def read_plain(p: Path, pixel_size: Any, height_unit: str | None) -> HeightMap:
    """A plain ``.npy`` or CSV/text height map; ``pixel_size`` and ``height_unit`` as in
    :func:`impactlab.experiment.read_scan`: needed unless the CSV's header lines state them, and
    refused when they disagree with those lines (:mod:`.stated`)."""
    meta: dict[str, str] = {}
    if p.suffix.lower() == ".npy":
        z = _load_npy(p)
    else:
        z, meta = _load_text(p)
    _check_not_xyz(p, z, pixel_size)
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
        name = "pixel_size (--pixel-size)"
    else:
        stated = meta["pixel_size"]
        name = "the file's '# pixel_size:'"
        if "pixel_size_y" in meta:
            stated = (stated, meta["pixel_size_y"])
            name = "the file's '# pixel_size:' and '# pixel_size_y:'"
    for value, named in ((pixel_size, "pixel_size (--pixel-size)"), (stated, name)):
        if isinstance(value, str) and not value.strip():  # the general hint, '1.0 m', is too big
            raise FileFormatError(
                p, f"{named} is empty; write one length and its unit, e.g. '12.5 um'"
            )
    try:
        dxy = pixel_pair(stated, name)
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


def _check_not_xyz(p: Path, z: np.ndarray, pixel_size: Any) -> None:
    """FileFormatError for a matrix of three columns and many rows: an x,y,z point list, which
    a height matrix (rows = y, at least 8 x 8) is not; says how to read it."""
    if z.ndim != 2 or z.shape[1] != 3 or z.shape[0] < 8:
        return
    if p.suffix.lower() == ".npy":
        how = "save it as text with the extension .xyz (np.savetxt), which is read as such"
    elif pixel_size is not None:
        how = "leave out pixel_size= (--pixel-size): a point list gives its own positions"
        if p.suffix.lower() not in (".csv", ".txt", ".asc"):
            how += ", and save it as .xyz"
    else:  # its '# pixel_size:' line makes it a matrix
        how = "remove its '# pixel_size:' line (a point list gives its own positions)"
    raise FileFormatError(
        p,
        f"{z.shape[0]} rows of 3 values: it looks like an x,y,z point list, not a height "
        f"matrix (rows = y, one column per x); to read it as a point list {how}",
    )


def looks_like_xyz(p: Path) -> bool:
    """True when the first data lines of the text file ``p`` (up to 20, at least 3; '#' lines
    skipped) each hold three numbers: an x,y,z point list."""
    found = 0
    try:
        with p.open("r", encoding="utf-8-sig", errors="replace") as fh:
            for line in fh:
                s = line.strip()
                if not s or s.startswith("#"):
                    continue
                cells = s.replace(",", " ").replace(";", " ").split()
                try:
                    [float(c) for c in cells]
                except ValueError:
                    return False
                if len(cells) != 3:
                    return False
                found += 1
                if found == 20:
                    break
    except OSError:
        return False
    return found >= 3
