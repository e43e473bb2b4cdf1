"""Vicon Nexus CSV exports: the ``Trajectories`` section (comma-separated text)::

    Trajectories
    500                                 <- the frame rate [Hz]
    ,,Rod:M1,,,Rod:M2,,,...             <- the marker names, above each one's X column
    Frame,Sub Frame,X,Y,Z,X,Y,Z,...
    ,,mm,mm,mm,mm,mm,mm,...             <- the units
    1,0,326.755,-270.025,307.707,...
    2,0,326.994,-270.173,305.109,,,,... <- empty cells: a gap
                                        <- a blank line ends the section

Other sections (``Devices``, ``Model Outputs``, ...) before or after it are skipped; a marker's
columns other than X, Y and Z (velocities, ...) are ignored. The unit comes from the units row
(``units=`` must agree with it) and the time from the frame numbers over the rate. A marker at
exactly (0, 0, 0) is missing, as are empty (or NaN) cells.
"""

from __future__ import annotations

import csv
import itertools
import math
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

__all__ = ["looks_like_vicon", "read_vicon_csv"]

#: The section names of a Nexus CSV export.
SECTIONS = ("Trajectories", "Devices", "Model Outputs", "Segments", "Joints")


def _fields(line: str) -> list[str]:
    return [c.strip() for c in next(csv.reader([line]))] if line.strip() else []


def _section(line: str) -> str:
    """The section a line starts (its one non-empty field, one of ``SECTIONS``), else ""."""
    f = [c for c in _fields(line) if c]
    return f[0] if len(f) == 1 and f[0] in SECTIONS else ""


def looks_like_vicon(text: str) -> bool:
    """True when the first non-blank line of ``text`` starts a Nexus CSV section."""
    for line in text.lstrip("\ufeff").splitlines()[:5]:
        if line.strip(" ,\t"):
            return bool(_section(line))
    return False


def _columns(p: Path, ln: int, names: list[str], axes: list[str]) -> list[tuple[str, list[int]]]:
    """(label, its X, Y, Z columns) of each marker from the names and axes rows (line ``ln``:
    the names row)."""
    starts = [c for c, n in enumerate(names) if n] + [max(len(names), len(axes))]
    out = []
    for c0, c1 in itertools.pairwise(starts):
        group = [a.upper() for a in axes[c0:c1]]
        if not all(a in group for a in "XYZ"):
            raise FileFormatError(
                p,
                f"line {ln + 1}: marker {names[c0]!r} has no X, Y and Z columns (got "
                f"{axes[c0:c1]!r})",
            )
        out.append((names[c0], [c0 + group.index(a) for a in "XYZ"]))
    if not out:
        raise FileFormatError(p, f"line {ln}: the Trajectories section names no marker")
    twice = duplicate_labels([lab for lab, _ in out], lambda i: f"marker {i + 1}")
    if twice:
        raise FileFormatError(p, f"line {ln}: the Trajectories section names {twice}")
    return out


def _unit(p: Path, ln: int, row: list[str], cols: list[int], units: str | None) -> str:
    """The length unit of the units row (line ``ln``) over the coordinate columns ``cols``;
    ``units`` must agree with it (it is needed where the row is empty)."""
    stated = {row[c] for c in cols if c < len(row) and row[c]}
    if len(stated) > 1:
        raise FileFormatError(p, f"line {ln}: the coordinates have several units {sorted(stated)}")
    unit = stated.pop() if stated else None
    chosen = unit if unit is not None else units
    if chosen is None:
        raise FileFormatError(
            p, f"line {ln}: the units row is empty; pass units= (e.g. --marker-units mm)"
        )
    try:
        fac = length_factor(chosen, name="the units row" if unit is not None else "units")
        agree = units is None or math.isclose(length_factor(units), fac)
    except ValueError as exc:
        raise FileFormatError(p, f"line {ln}: {exc}") from None
    if not agree:
        raise FileFormatError(p, f"units={units!r} disagrees with the file's unit {unit!r}")
    return chosen


def read_vicon_csv(
    path: str | Path, *, units: str | None = None, rate: float | str | None = None
) -> MarkerTracks:
    """Read the ``Trajectories`` section of a Vicon Nexus CSV export (layout in the module
    docstring): positions in metres, time [s] from the frame numbers over the section's rate,
    which ``rate`` [Hz] must agree with (1 %). :class:`FileFormatError` names the file and
    line."""
    rate = rate_argument(rate)
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    lines = read_text(p, "Vicon CSV").lstrip("\ufeff").splitlines()
    top = next((k for k, line in enumerate(lines) if _section(line) == "Trajectories"), None)
    if top is None:
        raise FileFormatError(
            p, "a Vicon Nexus CSV export without a 'Trajectories' section: export the trajectories"
        )
    if len(lines) < top + 6:
        raise FileFormatError(
            p,
            f"line {top + 1}: the Trajectories section ends before its rate, names, axes and "
            "units rows and its data",
        )
    head = [_fields(lines[top + k]) for k in range(1, 5)]
    try:
        fr = parse_rate(head[0][0] if head[0] else "", f"line {top + 2}: the rate")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    if rate is not None:
        check_rate_agrees(p, rate, fr, f"the rate on line {top + 2}")
    if not head[2] or head[2][0].lower() != "frame":
        raise FileFormatError(
            p,
            f"line {top + 4}: the Trajectories section's axes row should start with 'Frame' "
            f"(then 'Sub Frame', X, Y, Z, ...), got {lines[top + 3][:60]!r}",
        )
    markers = _columns(p, top + 3, head[1], head[2])
    cols = [c for _, trip in markers for c in trip]
    unit = _unit(p, top + 5, head[3], cols, units)
    data: list[tuple[int, list[str]]] = []
    for k in range(top + 5, len(lines)):
        fields = _fields(lines[k])
        if not any(fields):  # a blank line ends the section
            break
        data.append((k + 1, fields))
    if len(data) < 2:
        raise FileFormatError(p, f"only {len(data)} data rows; need at least 2 frames")
    xyz = np.full((len(data), len(markers), 3), np.nan)
    frames = np.full(len(data), np.nan)
    for r, (ln, fields) in enumerate(data):
        if len(fields) > len(head[2]):
            raise FileFormatError(
                p, f"line {ln}: {len(fields)} fields, more than the {len(head[2])} columns named"
            )
        cells = fields + [""] * (len(head[2]) - len(fields))
        values = [_value(p, ln, c, cells[c]) for c in [0, *cols]]
        frames[r] = values[0]
        xyz[r] = np.reshape(values[1:], (len(markers), 3))
    bad = ~np.isfinite(frames)
    bad[1:] |= ~(np.diff(frames) > 0)
    if bad.any():
        ln = data[int(np.flatnonzero(bad)[0])][0]
        raise FileFormatError(p, f"line {ln}: the frame number is missing or does not increase")
    xyz[np.all(xyz == 0.0, axis=2)] = np.nan
    return MarkerTracks(
        (frames - frames[0]) / fr,
        xyz * length_factor(unit),
        tuple(lab for lab, _ in markers),
        str(p),
        {"format": "vicon-csv", "units": unit, "rate": fr},
    )


def _value(p: Path, ln: int, col: int, cell: str) -> float:
    if cell == "" or cell.lower() in ("nan", "na", "null"):
        return math.nan
    try:
        return parse_number(cell, ",")
    except ValueError:
        raise FileFormatError(p, f"line {ln}, column {col + 1}: {not_a_number(cell)}") from None
