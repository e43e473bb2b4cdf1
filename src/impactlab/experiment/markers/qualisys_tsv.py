"""Qualisys Track Manager (QTM) TSV exports of 3D data (tab-separated text)::

    NO_OF_FRAMES	82
    NO_OF_CAMERAS	8
    NO_OF_MARKERS	3
    FREQUENCY	500                 <- the frame rate [Hz]
    ...                             <- other KEY<tab>value lines (EVENT, TIME_STAMP, ...)
    DATA_INCLUDED	3D
    MARKER_NAMES	M1	M2	M3
    Frame	Time	M1 X	M1 Y	M1 Z	...   <- optional column header
    1	0.00000	326.755	-270.025	307.707	...
    2	0.00200	0.000	0.000	0.000	...   <- a gap: (0, 0, 0), or empty cells

The coordinates are in millimetres (QTM's unit for 3D data; ``units=`` replaces it). Without
the column header a row holds the coordinates, after a frame number and a time when it has two
more fields. A marker at exactly (0, 0, 0), or with empty (or NaN) cells, is missing.
"""

from __future__ import annotations

import math
import re
from pathlib import Path

import numpy as np

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers.tracks import (
    MarkerTracks,
    check_rate_agrees,
    duplicate_labels,
    length_factor,
    parse_rate,
    rate_argument,
)
from impactlab.experiment.textfiles import not_a_number, parse_number, read_text

__all__ = ["looks_like_qtm", "read_qtm_tsv"]

#: A header line's key.
_KEY = re.compile(r"^[A-Z][A-Z0-9_]*$")
#: A rate stated and a time column's steps may differ by this fraction.
_TIME_AGREEMENT = 0.01


def looks_like_qtm(text: str) -> bool:
    """True when ``text`` starts with QTM's header lines (``KEY<tab>value``, MARKER_NAMES
    among them)."""
    for line in text.lstrip("\ufeff").splitlines()[:60]:
        key = line.split("\t", 1)[0].strip()
        if not _KEY.match(key):
            return False
        if key == "MARKER_NAMES":
            return True
    return False


def _header(p: Path, lines: list[str]) -> tuple[dict[str, list[str]], int]:
    """(the header's values by key, the index of the first line after it)."""
    head: dict[str, list[str]] = {}
    k = 0
    while k < len(lines):
        fields = lines[k].rstrip("\r\n").split("\t")
        key = fields[0].strip()
        if not _KEY.match(key):
            break
        head.setdefault(key, [f.strip() for f in fields[1:]])
        k += 1
    for key in ("NO_OF_FRAMES", "FREQUENCY", "MARKER_NAMES"):
        if key not in head:
            raise FileFormatError(p, f"QTM TSV export without its {key} line")
    return head, k


def _number(p: Path, head: dict[str, list[str]], key: str) -> float:
    values = [v for v in head[key] if v]
    try:
        return parse_number(values[0], "\t")
    except (IndexError, ValueError):
        raise FileFormatError(p, f"the {key} line holds {head[key]!r}, not a number") from None


def _count(p: Path, head: dict[str, list[str]], key: str) -> int:
    """The whole number of a count line (NO_OF_FRAMES, NO_OF_MARKERS); FileFormatError for a
    fraction or a negative number (a corrupt header)."""
    x = _number(p, head, key)
    if not (x >= 0 and x == int(x)):
        raise FileFormatError(p, f"the {key} line holds {head[key][0]!r}, not a whole number >= 0")
    return int(x)


def _columns(
    p: Path, ln: int, names: list[str], labels: list[str]
) -> tuple[int | None, int | None, list[int]]:
    """(the Frame column, the Time column, the X column of each marker) of a column header."""
    low = [n.strip().lower() for n in names]
    frame = low.index("frame") if "frame" in low else None
    time = low.index("time") if "time" in low else None
    starts = []
    for lab in labels:
        want = [f"{lab} {a}".lower() for a in "xyz"]
        idx = [low.index(w) if w in low else -1 for w in want]
        if min(idx) < 0 or idx != list(range(idx[0], idx[0] + 3)):
            raise FileFormatError(
                p,
                f"line {ln}: the column header has no columns '{lab} X', '{lab} Y', '{lab} Z' "
                "side by side for the marker MARKER_NAMES names",
            )
        starts.append(idx[0])
    return frame, time, starts


def _rows(p: Path, lines: list[str], first: int) -> list[tuple[int, list[str]]]:
    """(line number, fields) of the data lines from ``first`` on (blank lines skipped; trailing
    empty fields dropped)."""
    out = []
    for k in range(first, len(lines)):
        fields = lines[k].rstrip("\r\n").split("\t")
        while fields and not fields[-1].strip():
            fields.pop()
        if fields:
            out.append((k + 1, fields))
    return out


def _value(p: Path, ln: int, col: int, cell: str) -> float:
    cs = cell.strip()
    if cs == "" or cs.lower() in ("nan", "na", "null", "-"):
        return math.nan
    try:
        return parse_number(cs, "\t")
    except ValueError:
        raise FileFormatError(p, f"line {ln}, column {col + 1}: {not_a_number(cs)}") from None


def _meta(p: Path, head: dict[str, list[str]], rate: float | None) -> tuple[list[str], float]:
    """(the marker labels, the frame rate [Hz]) of the header, checked (``rate``: the one
    given)."""
    if head.get("DATA_INCLUDED", ["3D"])[:1] not in (["3D"], []):
        raise FileFormatError(
            p, f"DATA_INCLUDED is {head['DATA_INCLUDED'][0]!r}: export the 3D data (3D)"
        )
    labels = [s for s in head["MARKER_NAMES"] if s]
    twice = duplicate_labels(labels, lambda i: f"name {i + 1}")
    if twice:
        raise FileFormatError(p, f"MARKER_NAMES names {twice}")
    if "NO_OF_MARKERS" in head and _count(p, head, "NO_OF_MARKERS") != len(labels):
        raise FileFormatError(
            p, f"NO_OF_MARKERS is {head['NO_OF_MARKERS'][0]} but MARKER_NAMES names {len(labels)}"
        )
    try:
        fr = parse_rate(head["FREQUENCY"][0] if head["FREQUENCY"] else "", "FREQUENCY")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    if rate is not None:
        check_rate_agrees(p, rate, fr, "its FREQUENCY line")
    return labels, fr


def _layout(
    p: Path, rows: list[tuple[int, list[str]]], labels: list[str]
) -> tuple[int | None, int | None, list[int], bool]:
    """(the Frame column, the Time column, each marker's X column, whether the first row is a
    column header) of the data rows."""
    if not rows:
        return None, None, [], False
    ln, first = rows[0]
    if first[0].strip().lower() in ("frame", "time"):
        return (*_columns(p, ln, first, labels), True)
    extra = len(first) - 3 * len(labels)
    if extra not in (0, 2):
        raise FileFormatError(
            p,
            f"line {ln}: {len(first)} fields, but {len(labels)} markers need "
            f"{3 * len(labels)} (or {3 * len(labels) + 2} with a frame number and a time)",
        )
    starts = [extra + 3 * j for j in range(len(labels))]
    return (0, 1, starts, False) if extra else (None, None, starts, False)


def read_qtm_tsv(
    path: str | Path, *, units: str | None = None, rate: float | str | None = None
) -> MarkerTracks:
    """Read a QTM TSV export of 3D data (layout in the module docstring): positions in metres
    (QTM writes mm; ``units`` replaces that unit), time [s] from the frame numbers over
    FREQUENCY, which ``rate`` [Hz] and a Time column must agree with (1 %). A file with fewer or
    more rows than NO_OF_FRAMES is refused; :class:`FileFormatError` names the file and line."""
    rate = rate_argument(rate)
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    lines = read_text(p, "QTM TSV").lstrip("\ufeff").splitlines()
    head, k = _header(p, lines)
    labels, fr = _meta(p, head, rate)
    rows = _rows(p, lines, k)
    frame_col, time_col, starts, has_header = _layout(p, rows, labels)
    rows = rows[1:] if has_header else rows
    n_announced = _count(p, head, "NO_OF_FRAMES")
    if len(rows) != n_announced:
        cut = " (a truncated file)" if len(rows) < n_announced else ""
        raise FileFormatError(
            p,
            f"NO_OF_FRAMES announces {n_announced} frames but the file holds {len(rows)} rows{cut}",
        )
    if len(rows) < 2:
        raise FileFormatError(p, f"only {len(rows)} data rows; need at least 2 frames")
    width = max(starts) + 3
    xyz = np.full((len(rows), len(labels), 3), np.nan)
    frames = np.arange(len(rows), dtype=np.float64)
    times = np.full(len(rows), np.nan)
    for r, (ln, fields) in enumerate(rows):
        if len(fields) < width:
            fields = fields + [""] * (width - len(fields))
        for j, c in enumerate(starts):
            xyz[r, j] = [_value(p, ln, c + a, fields[c + a]) for a in range(3)]
        if frame_col is not None:
            frames[r] = _value(p, ln, frame_col, fields[frame_col])
        if time_col is not None:
            times[r] = _value(p, ln, time_col, fields[time_col])
    return _tracks(p, xyz, frames, times, [ln for ln, _ in rows], labels, fr, units)


def _tracks(
    p: Path,
    xyz: np.ndarray,
    frames: np.ndarray,
    times: np.ndarray,
    lines: list[int],
    labels: list[str],
    fr: float,
    units: str | None,
) -> MarkerTracks:
    """The tracks from the parsed rows: gaps masked, time from the frames, both checked."""
    bad = ~np.isfinite(frames)
    bad[1:] |= ~(np.diff(frames) > 0)
    if bad.any():
        ln = lines[int(np.flatnonzero(bad)[0])]
        raise FileFormatError(p, f"line {ln}: the frame number is missing or does not increase")
    t = (frames - frames[0]) / fr
    dt = np.diff(times)
    if np.isfinite(dt).any():
        med = float(np.nanmedian(dt))
        if abs(med * fr - 1.0) > _TIME_AGREEMENT:
            raise FileFormatError(
                p,
                f"FREQUENCY {fr:g} Hz contradicts the Time column, whose steps are {med:.6g} s",
            )
    xyz[np.all(xyz == 0.0, axis=2)] = np.nan  # QTM writes a gap as (0, 0, 0)
    unit = units if units is not None else "mm"
    try:
        fac = length_factor(unit, name="units")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    return MarkerTracks(
        t, xyz * fac, tuple(labels), str(p), {"format": "qtm-tsv", "units": unit, "rate": fr}
    )
