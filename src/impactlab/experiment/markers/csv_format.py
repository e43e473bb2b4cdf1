"""Marker tracks as CSV text (the layout documented in docs/experiment.md)::

    # units: mm                 <- length unit of the coordinates (or pass units=)
    # rate: 500 Hz              <- optional; needed only with a 'frame' column (Hz, kHz, fps)
    time,M1_x,M1_y,M1_z,M2_x,M2_y,M2_z,M3_x,M3_y,M3_z
    0.000,12.31,45.60,301.2,...
    0.002,,,,...                <- empty cells (or NaN) mark an occluded marker

The first column is ``time`` [s] (``t``; a unit in brackets or after an underscore is read:
``Time (s)``, ``time [ms]``, ``time_ms``) or ``frame`` (a frame number, with a rate); then three
columns per marker named ``<label>_x``, ``<label>_y``, ``<label>_z`` (separators ``_ . :`` or a
space, any case). Commas, semicolons or tabs separate the fields.
"""

from __future__ import annotations

import csv
import math
import re
from pathlib import Path

import numpy as np

from impactlab.experiment.checks import check_instance, check_path
from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers.tracks import (
    MarkerTracks,
    check_rate_agrees,
    duplicate_labels,
    length_factor,
    parse_rate,
    rate_argument,
)
from impactlab.experiment.textfiles import (
    not_a_number,
    parse_number,
    read_text,
    split_commented,
)
from impactlab.units import to_si

__all__ = ["TEXT_LAYOUTS", "read_csv_markers", "write_csv_markers"]

#: The marker text layouts read (by :func:`~impactlab.experiment.markers.read_markers`), for
#: messages.
TEXT_LAYOUTS = (
    "the text layouts read are impactlab's marker CSV ('time,<label>_x,<label>_y,<label>_z,...' "
    "under a '# units: mm' line: docs/experiment.md, Marker tracks), a Qualisys QTM TSV export "
    "of 3D data (header lines NO_OF_FRAMES, FREQUENCY, ..., MARKER_NAMES) and a Vicon Nexus CSV "
    "export of 'Trajectories'; from other software, export C3D (.c3d)"
)

#: A time column's name: ``time`` or ``t``, its unit in brackets or after an underscore.
_TIME = re.compile(
    r"(?i)^(?:time|t)(?:\s*[\[(]\s*(?P<unit>[^\])]*?)\s*[\])]|_(?P<bare>[a-zµμ]+))?$"
)

#: The separators' names, for messages.
_SEPARATOR_NAMES = {",": "comma", ";": "semicolon", "\t": "tab"}

_COORD = re.compile(r"^(?P<label>.+?)[\s_.:]+(?P<axis>[xyzXYZ])$")


def time_unit(p: Path, header_ln: int, name: str) -> float | None:
    """Seconds per unit of the first column named ``name`` (``time``, ``t``, ``Time (s)``, ``time
    [ms]``, ``time_ms``: 1 without a unit); None for ``frame``; FileFormatError otherwise."""
    if name.lower() == "frame":
        return None
    m = _TIME.match(name)
    if m is None:
        raise FileFormatError(
            p,
            f"line {header_ln}: the first column must be 'time' (seconds; 'Time (s)', 'time "
            f"(ms)' with its unit) or 'frame', got {name!r}; {TEXT_LAYOUTS}",
        )
    unit = m.group("unit") or m.group("bare")
    if unit is None:
        return 1.0
    try:
        return to_si(f"1 {unit}", "s", name=f"the time column {name!r}")
    except ValueError:
        raise FileFormatError(
            p,
            f"line {header_ln}: the first column {name!r} is not in a unit of time ({unit!r}); "
            "write 'time' (seconds), 'time (ms)' or 'frame'",
        ) from None


def _header(p: Path, header_ln: int, header: str) -> tuple[str, list[str], list[str]]:
    """(delimiter, column names, marker labels) from the header line."""
    delim = max([",", ";", "\t"], key=header.count)
    if header.count(delim) == 0:
        raise FileFormatError(
            p,
            f"line {header_ln}: the header has a single column; expected "
            f"'time,<label>_x,<label>_y,<label>_z,...' separated by commas; {TEXT_LAYOUTS}",
        )
    names = [c.strip() for c in next(csv.reader([header], delimiter=delim))]
    time_unit(p, header_ln, names[0])
    coord_cols = names[1:]
    if len(coord_cols) == 0 or len(coord_cols) % 3:
        empty = (
            f"; its last column has no name (a trailing {_SEPARATOR_NAMES[delim]} at the end "
            "of the line): remove it from the header and the rows"
            if coord_cols and coord_cols[-1] == ""
            else ""
        )
        raise FileFormatError(
            p,
            f"line {header_ln}: expected three columns (x, y, z) per marker "
            f"after the time column, got {len(coord_cols)} columns{empty}",
        )
    labels: list[str] = []
    for i in range(0, len(coord_cols), 3):
        trip = []
        for j, axis in enumerate("xyz"):
            m = _COORD.match(coord_cols[i + j])
            if m is None or m.group("axis").lower() != axis:
                raise FileFormatError(
                    p,
                    f"line {header_ln}: column {i + j + 2} ({coord_cols[i + j]!r}) should be "
                    f"'<label>_{axis}'",
                )
            trip.append(m.group("label"))
        if len(set(trip)) != 1:
            raise FileFormatError(
                p, f"line {header_ln}: columns {coord_cols[i : i + 3]} do not name one marker"
            )
        labels.append(trip[0])
    twice = duplicate_labels(labels, lambda i: f"columns {3 * i + 2}-{3 * i + 4}")
    if twice:
        raise FileFormatError(p, f"line {header_ln}: the header names {twice}")
    return delim, names, labels


def _data(p: Path, rows: list[tuple[int, str]], delim: str, ncol: int) -> np.ndarray:
    """(rows, ncol) values of the data lines; NaN for empty cells."""
    data = np.full((len(rows), ncol), np.nan)
    for r, (ln, line) in enumerate(rows):
        cells = next(csv.reader([line], delimiter=delim))
        if len(cells) != ncol:
            why = (
                "its last field is empty: a trailing separator at the end of the line"
                if len(cells) == ncol + 1 and not cells[-1].strip()
                else "truncated or malformed row"
            )
            if delim == "," and len(cells) > ncol:  # 0,002,352,76 for 0.002;352.76
                why += (
                    "; decimal commas? Where commas separate the fields, write decimal "
                    "points, or separate the fields with semicolons"
                )
            raise FileFormatError(
                p, f"line {ln}: expected {ncol} fields, found {len(cells)} ({why})"
            )
        for c, cell in enumerate(cells):
            cs = cell.strip()
            if cs == "" or cs.lower() in ("nan", "na", "null"):
                if c == 0:
                    raise FileFormatError(p, f"line {ln}: the time/frame value is missing")
                continue
            try:
                data[r, c] = parse_number(cs, delim)
            except ValueError:
                raise FileFormatError(p, f"line {ln}, column {c + 1}: {not_a_number(cs)}") from None
    return data


def _unit(p: Path, units: str | None, meta: dict[str, str]) -> tuple[str, float]:
    """(the coordinates' length unit, metres per unit) from ``units=`` and ``# units:``."""
    file_units = meta.get("units") or meta.get("unit")
    if "units" in meta and "unit" in meta and not _same_unit(meta["units"], meta["unit"]):
        raise FileFormatError(
            p,
            f"'# unit: {meta['unit']}' and '# units: {meta['units']}' disagree; keep the right one",
        )
    if (
        units is not None
        and file_units is not None
        and not math.isclose(length_factor(units), length_factor(file_units))
    ):
        raise FileFormatError(
            p, f"units={units!r} disagrees with the file's '# units: {file_units}'"
        )
    unit = units if units is not None else file_units
    if unit is None:
        raise FileFormatError(
            p,
            "no length unit: add a '# units: mm' line to the file or pass "
            "units= (e.g. --marker-units mm)",
        )
    try:
        return unit, length_factor(unit, name="units")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None


def _same_unit(a: str, b: str) -> bool:
    """True when the length units ``a`` and ``b`` are the same (or one is not a unit: the
    reader names it)."""
    try:
        return math.isclose(length_factor(a), length_factor(b))
    except ValueError:
        return a.strip().lower() == b.strip().lower()


def frame_rate(p: Path, text: str) -> float:
    """The frame rate [Hz] of a '# rate:' line (:func:`parse_rate`); FileFormatError naming the
    line otherwise (a unit is never dropped)."""
    try:
        return parse_rate(text)
    except ValueError as exc:
        raise FileFormatError(p, f"'# rate: {text}': {exc}") from None


def _time(
    p: Path,
    tcol: np.ndarray,
    is_frame: bool,
    rate: float | None,
    meta: dict[str, str],
    lines: list[int],
) -> np.ndarray:
    """Frame times [s] from the first column (times, or frame numbers with a rate); ``lines``:
    the file line of each data row, for messages."""
    if is_frame:
        fr = rate
        if "rate" in meta:  # the file's rate, which a given one must agree with
            fr = frame_rate(p, meta["rate"])
            if rate is not None:
                check_rate_agrees(p, rate, fr, f"'# rate: {meta['rate']}'")
        if fr is None:
            raise FileFormatError(
                p,
                "a 'frame' column needs the frame rate: add a line '# rate: 500 Hz' above the "
                "header (or, from Python, pass rate= to read_markers)",
            )
        tcol = (tcol - tcol[0]) / fr
    if np.any(np.diff(tcol) <= 0):
        row = int(np.flatnonzero(np.diff(tcol) <= 0)[0]) + 1
        name = "the frame number" if is_frame else "the time"
        raise FileFormatError(
            p,
            f"line {lines[row]}: {name} does not increase (line {lines[row - 1]} has the same "
            "or a later one)",
        )
    if not is_frame:
        _check_rate_against_times(p, tcol, rate, meta)
    return tcol


#: A stated frame rate and the time column's steps may differ by this fraction.
RATE_TOLERANCE = 0.01


def _check_rate_against_times(
    p: Path, tcol: np.ndarray, rate: float | None, meta: dict[str, str]
) -> None:
    """FileFormatError when a frame rate (``rate=``, a '# rate:' line: each is checked)
    contradicts the time column: its typical step (the median, so that gaps do not count)
    differs from 1 / rate by more than ``RATE_TOLERANCE``."""
    stated: list[tuple[str, float]] = []
    if "rate" in meta:
        stated.append((f"'# rate: {meta['rate']}'", frame_rate(p, meta["rate"])))
    if rate is not None:
        stated.append((f"rate={rate:g} Hz", rate))
    step = float(np.median(np.diff(tcol)))
    for where, fr in stated:
        if abs(step * fr - 1.0) > RATE_TOLERANCE:
            raise FileFormatError(
                p,
                f"{where} contradicts the time column, whose steps are {step:.6g} s "
                f"({1.0 / step:.6g} frames per second): correct the rate or the times, or "
                "remove the rate (a 'time' column needs none)",
            )


def read_csv_markers(
    path: str | Path, *, units: str | None = None, rate: float | str | None = None
) -> MarkerTracks:
    """Read marker tracks from a CSV file (layout in the module docstring and docs/experiment.md).

    ``units`` (length unit of the coordinates) is needed unless the file has a ``# units:`` line;
    if both are given they must agree. ``rate`` [Hz] is needed only for a ``frame`` column without
    a ``# rate:`` line (``500``, ``"500 Hz"``, ``"0.5 kHz"``, ``"500 fps"``: its unit is read,
    never dropped); a rate given or stated must agree with a ``time`` column.
    Raises :class:`FileFormatError` naming the file and line for bad content.
    """
    rate = rate_argument(rate)
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    text = read_text(p, "CSV")
    try:
        meta, rows = split_commented(text)
    except ValueError as exc:  # a key stated twice, differently
        raise FileFormatError(p, str(exc)) from None
    if not rows:
        raise FileFormatError(p, "no header and no data rows")
    header_ln, header = rows[0]
    delim, names, labels = _header(p, header_ln, header)
    data = _data(p, rows[1:], delim, len(names))
    if data.shape[0] < 2:
        raise FileFormatError(p, f"only {data.shape[0]} data rows; need at least 2 frames")
    unit, fac = _unit(p, units, meta)
    lines = [ln for ln, _ in rows[1:]]
    seconds = time_unit(p, header_ln, names[0])
    first = data[:, 0] if seconds is None else data[:, 0] * seconds
    tcol = _time(p, first, seconds is None, rate, meta, lines)
    xyz = data[:, 1:].reshape(data.shape[0], len(labels), 3) * fac
    return MarkerTracks(tcol, xyz, tuple(labels), str(p), {"format": "csv", "units": unit})


def write_csv_markers(tracks: MarkerTracks, path: str | Path, *, units: str = "mm") -> Path:
    """Write ``tracks`` in the documented CSV layout (occluded samples as empty cells)."""
    check_instance(tracks, MarkerTracks, "tracks")
    fac = length_factor(units)
    p = check_path(path, "path")
    with p.open("w", newline="", encoding="utf-8") as fh:
        fh.write(f"# impactlab marker tracks\n# units: {units}\n")
        w = csv.writer(fh)
        w.writerow(["time"] + [f"{lab}_{a}" for lab in tracks.labels for a in "xyz"])
        pos = tracks.positions / fac
        for k in range(tracks.n_frames):
            row = [f"{tracks.time[k]:.6f}"]
            for j in range(tracks.n_markers):
                if np.all(np.isfinite(pos[k, j])):
                    row += [f"{v:.5f}" for v in pos[k, j]]
                else:
                    row += ["", "", ""]
            w.writerow(row)
    return p
