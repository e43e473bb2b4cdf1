"""Motion-capture marker tracks: C3D and CSV readers (positions in metres, occlusions masked).

C3D (https://www.c3d.org) is read with ``ezc3d``; when ezc3d is missing or fails on the file, the
pure-Python ``c3d`` package is tried. Point units come from the ``POINT:UNITS`` parameter (e.g.
"mm") unless ``units=`` overrides them; samples with a negative residual (the C3D convention for an
invalid point) or non-finite coordinates are masked (NaN), never used. A file whose data section is
shorter than its header announces (a truncated file) is refused: both readers would otherwise
silently return the frames that happen to be there.

CSV layout (documented in docs/experiment.md)::

    # units: mm                 <- length unit of the coordinates (or pass units=)
    # rate: 500                 <- optional; needed only with a 'frame' column
    time,M1_x,M1_y,M1_z,M2_x,M2_y,M2_z,M3_x,M3_y,M3_z
    0.000,12.31,45.60,301.2,...
    0.002,,,,...                <- empty cells (or NaN) mark an occluded marker

The first column is ``time`` [s] (or ``frame``, a frame number, with a rate); then three columns
per marker named ``<label>_x``, ``<label>_y``, ``<label>_z`` (separators ``_ . :`` or a space,
any case). Commas, semicolons or tabs separate the fields.
"""

from __future__ import annotations

import csv
import math
import re
import struct
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.textfiles import split_commented

__all__ = [
    "MarkerTracks",
    "length_factor",
    "read_c3d",
    "read_csv_markers",
    "read_markers",
    "write_csv_markers",
]


def length_factor(unit: str, *, name: str = "units") -> float:
    """Metres per ``unit`` (e.g. "mm" -> 1e-3). ValueError naming ``name`` for a unit that is not
    a length."""
    from impactlab.units import registry

    text = str(unit).strip().replace("µ", "u").replace("μ", "u")
    if not text:
        raise ValueError(f"{name} is empty; expected a length unit such as 'mm' or 'm'")
    ureg = registry()
    try:
        u = ureg.Unit(text)
    except Exception:
        raise ValueError(f"{name}: {unit!r} is not a known unit; expected a length unit such as "
                         "'mm' or 'm'") from None
    if u.dimensionality != ureg.Unit("m").dimensionality:
        raise ValueError(f"{name}: {unit!r} is not a length unit; expected e.g. 'mm' or 'm'")
    return float((1.0 * u).to("m").magnitude)


@dataclass(frozen=True)
class MarkerTracks:
    """Marker positions over time (SI).

    Attributes
    ----------
    time : (n,) frame times [s], strictly increasing.
    positions : (n, m, 3) marker positions [m] in the camera (lab) frame; NaN where a marker is
        occluded or invalid.
    labels : the m marker labels.
    source : where the data came from (a file path), for messages.
    """

    time: np.ndarray
    positions: np.ndarray
    labels: tuple[str, ...]
    source: str = ""
    meta: dict[str, Any] = field(default_factory=dict, compare=False, repr=False)

    def __post_init__(self) -> None:
        t = np.array(self.time, dtype=np.float64).reshape(-1)
        p = np.array(self.positions, dtype=np.float64)
        where = f" ({self.source})" if self.source else ""
        if p.ndim != 3 or p.shape[2] != 3:
            raise ValueError(f"positions must have shape (frames, markers, 3), got "
                             f"{p.shape}{where}")
        if p.shape[0] != t.size:
            raise ValueError(f"time has {t.size} entries but positions has {p.shape[0]} "
                             f"frames{where}")
        if t.size < 2:
            raise ValueError(f"marker tracks need at least 2 frames, got {t.size}{where}")
        if not np.all(np.isfinite(t)):
            raise ValueError(f"time must be finite{where}")
        if np.any(np.diff(t) <= 0):
            k = int(np.flatnonzero(np.diff(t) <= 0)[0])
            raise ValueError(f"time must increase strictly; frame {k + 1} ({t[k + 1]!r} s) does "
                             f"not follow frame {k} ({t[k]!r} s){where}")
        labels = tuple(str(s) for s in self.labels)
        if len(labels) != p.shape[1]:
            raise ValueError(f"{len(labels)} labels for {p.shape[1]} markers{where}")
        if len(set(labels)) != len(labels):
            raise ValueError(f"marker labels must be unique, got {labels}{where}")
        p = p.copy()
        bad = ~np.all(np.isfinite(p), axis=2)
        p[bad] = np.nan
        t.setflags(write=False)
        p.setflags(write=False)
        object.__setattr__(self, "time", t)
        object.__setattr__(self, "positions", p)
        object.__setattr__(self, "labels", labels)

    @property
    def n_frames(self) -> int:
        return int(self.time.size)

    @property
    def n_markers(self) -> int:
        return int(self.positions.shape[1])

    @property
    def valid(self) -> np.ndarray:
        """(n, m) True where the marker was seen."""
        return np.all(np.isfinite(self.positions), axis=2)

    @property
    def rate(self) -> float:
        """Frame rate [Hz] (median of 1/dt)."""
        return float(1.0 / np.median(np.diff(self.time)))

    def select(self, labels: list[str] | tuple[str, ...]) -> MarkerTracks:
        """The tracks of the named markers only (in that order)."""
        missing = [s for s in labels if s not in self.labels]
        if missing:
            raise ValueError(f"markers {missing} not in {self.source or 'the tracks'}; "
                             f"available: {list(self.labels)}")
        idx = [self.labels.index(s) for s in labels]
        return MarkerTracks(self.time, self.positions[:, idx, :], tuple(labels), self.source,
                            dict(self.meta))


# ----------------------------------------------------------------------------------------------
# C3D
# ----------------------------------------------------------------------------------------------


def _c3d_header_check(path: Path, n_points: int, n_frames_read: int, scale: float) -> None:
    """Refuse a C3D file whose data section is shorter than its header announces.

    Reads the 512-byte header directly (C3D spec: word 1 byte 2 = 0x50; words 2, 4, 5, 9, 10 =
    points, first frame, last frame, data-start block, analog samples per frame); the byte order
    comes from the processor type in the parameter section (84 Intel, 85 DEC: little endian;
    86 MIPS: big).
    """
    raw = path.read_bytes()
    if len(raw) < 512 or raw[1] != 0x50:
        raise FileFormatError(path, "not a C3D file (bad header: no 0x50 signature)")
    pblock = raw[0]
    off = (pblock - 1) * 512
    if pblock < 2 or len(raw) < off + 4:
        raise FileFormatError(path, "truncated C3D file: the parameter section is missing")
    proc = raw[off + 3]
    end = ">" if proc == 86 else "<"
    words = struct.unpack(end + "12H", raw[:24])
    first, last = words[3], words[4]
    data_start = words[8]
    analog_per_frame = words[9]
    header_frames = last - first + 1 if last >= first else 0
    bytes_per = 4 if scale < 0 else 2
    frame_bytes = n_points * 4 * bytes_per + analog_per_frame * bytes_per
    # Files with more than 65535 frames store the count in a parameter (not in the header); the
    # size check then compares against what the reader found.
    frames = max(header_frames, n_frames_read)
    expected = (data_start - 1) * 512 + frames * frame_bytes
    if len(raw) < expected:
        have = max(0, (len(raw) - (data_start - 1) * 512) // max(frame_bytes, 1))
        raise FileFormatError(
            path,
            f"truncated C3D file: the header announces {frames} frames "
            f"({expected} bytes) but the file has {len(raw)} bytes (about {have} complete frames)",
        )


def _read_ezc3d(path: Path) -> dict[str, Any]:
    import ezc3d

    c = ezc3d.c3d(str(path), extract_forceplat_data=False)
    params = c["parameters"]["POINT"]
    pts = np.asarray(c["data"]["points"], dtype=np.float64)  # (4, m, n)
    if pts.ndim != 3 or pts.shape[0] < 3:
        raise ValueError(f"unexpected point array shape {pts.shape}")
    xyz = np.transpose(pts[:3], (2, 1, 0)).copy()  # (n, m, 3)
    res = c["data"]["meta_points"].get("residuals") if "meta_points" in c["data"] else None
    if res is not None and np.size(res):
        r = np.asarray(res, dtype=np.float64)[0].T  # (n, m)
        xyz[~(np.isfinite(r) & (r >= 0.0))] = np.nan
    labels = list(params["LABELS"]["value"]) if "LABELS" in params else []
    units = None
    if "UNITS" in params and params["UNITS"]["value"]:
        units = str(params["UNITS"]["value"][0]).strip() or None
    scale = float(params["SCALE"]["value"][0]) if "SCALE" in params else -1.0
    rate = float(c["header"]["points"]["frame_rate"])
    return {"xyz": xyz, "labels": labels, "units": units, "rate": rate, "scale": scale,
            "backend": "ezc3d"}


def _read_pyc3d(path: Path) -> dict[str, Any]:
    import warnings

    import c3d

    with path.open("rb") as fh, warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = c3d.Reader(fh)
        frames = []
        for _i, points, _analog in r.read_frames(copy=True):
            p = np.asarray(points, dtype=np.float64)
            xyz = p[:, :3].copy()
            if p.shape[1] > 3:
                resid = p[:, 3]
                xyz[~(np.isfinite(resid) & (resid >= 0.0))] = np.nan
            frames.append(xyz)
        labels = [str(s).strip() for s in r.point_labels]
        try:
            units = r.get("POINT:UNITS").string_value.strip() or None
        except (AttributeError, KeyError):
            units = None
        scale = float(r.point_scale)
        rate = float(r.point_rate)
    xyz_all = np.stack(frames, axis=0) if frames else np.zeros((0, len(labels), 3))
    return {"xyz": xyz_all, "labels": labels, "units": units, "rate": rate, "scale": scale,
            "backend": "c3d"}


def read_c3d(path: str | Path, *, units: str | None = None, backend: str = "auto") -> MarkerTracks:
    """Read the 3D points of a C3D file.

    Parameters
    ----------
    path : the .c3d file.
    units : length unit of the stored coordinates; overrides ``POINT:UNITS`` (needed only when the
        file lacks it).
    backend : "auto" (ezc3d, then the pure-Python ``c3d`` package), "ezc3d" or "c3d".

    Returns :class:`MarkerTracks` in metres, time from 0 at the first frame. Raises
    :class:`FileFormatError` naming the file for a missing, corrupt, truncated or empty file.
    """
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    if backend not in ("auto", "ezc3d", "c3d"):
        raise ValueError(f"backend must be 'auto', 'ezc3d' or 'c3d', got {backend!r}")
    if p.stat().st_size == 0:
        raise FileFormatError(p, "empty file")
    problems: list[str] = []
    data: dict[str, Any] | None = None
    order = ["ezc3d", "c3d"] if backend == "auto" else [backend]
    for name in order:
        try:
            data = _read_ezc3d(p) if name == "ezc3d" else _read_pyc3d(p)
            break
        except ImportError as exc:
            problems.append(f"{name} is not installed ({exc})")
        except Exception as exc:  # both libraries raise assorted types on bad files
            problems.append(f"{name}: {type(exc).__name__}: {str(exc).strip()[:200]}")
    if data is None:
        raise FileFormatError(p, "not a readable C3D file (" + "; ".join(problems) + ")")
    xyz = data["xyz"]
    if xyz.shape[0] == 0 or xyz.shape[1] == 0:
        raise FileFormatError(p, f"the C3D file holds no 3D point data ({xyz.shape[0]} frames, "
                                 f"{xyz.shape[1]} points)")
    _c3d_header_check(p, xyz.shape[1], xyz.shape[0], data["scale"])
    rate = data["rate"]
    if not (math.isfinite(rate) and rate > 0):
        raise FileFormatError(p, f"invalid point rate {rate!r} Hz in the C3D header")
    unit = units if units is not None else data["units"]
    if unit is None:
        raise FileFormatError(p, "the C3D file has no POINT:UNITS parameter; pass units= "
                                 "(e.g. units='mm')")
    try:
        fac = length_factor(unit, name="POINT:UNITS" if units is None else "units")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    labels = list(data["labels"])[: xyz.shape[1]]
    labels += [f"P{i + 1}" for i in range(len(labels), xyz.shape[1])]
    labels = [s.strip() or f"P{i + 1}" for i, s in enumerate(labels)]
    t = np.arange(xyz.shape[0], dtype=np.float64) / rate
    return MarkerTracks(t, xyz * fac, tuple(labels), str(p),
                        {"format": "c3d", "backend": data["backend"], "units": unit,
                         "rate": rate, "fallback_notes": problems})


# ----------------------------------------------------------------------------------------------
# CSV
# ----------------------------------------------------------------------------------------------

_COORD = re.compile(r"^(?P<label>.+?)[\s_.:]+(?P<axis>[xyzXYZ])$")


def read_csv_markers(
    path: str | Path, *, units: str | None = None, rate: float | None = None
) -> MarkerTracks:
    """Read marker tracks from a CSV file (layout in the module docstring and docs/experiment.md).

    ``units`` (length unit of the coordinates) is needed unless the file has a ``# units:`` line;
    if both are given they must agree. ``rate`` [Hz] is needed only for a ``frame`` column without
    a ``# rate:`` line. Raises :class:`FileFormatError` naming the file and line for bad content.
    """
    p = Path(path)
    if not p.is_file():
        raise FileFormatError(p, "file does not exist" if not p.exists() else "not a file")
    try:
        text = p.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise FileFormatError(p, "not a text (CSV) file: it is not UTF-8 text") from None
    meta, rows = split_commented(text)
    if not rows:
        raise FileFormatError(p, "no header and no data rows")
    header_ln, header = rows[0]
    delim = max([",", ";", "\t"], key=header.count)
    if header.count(delim) == 0:
        raise FileFormatError(p, f"line {header_ln}: the header has a single column; expected "
                                 "'time,<label>_x,<label>_y,<label>_z,...' separated by commas")
    names = [c.strip() for c in next(csv.reader([header], delimiter=delim))]
    first = names[0].lower()
    if first not in ("time", "t", "time_s", "time [s]", "frame"):
        raise FileFormatError(p, f"line {header_ln}: the first column must be 'time' (seconds) "
                                 f"or 'frame', got {names[0]!r}")
    coord_cols = names[1:]
    if len(coord_cols) == 0 or len(coord_cols) % 3:
        raise FileFormatError(p, f"line {header_ln}: expected three columns (x, y, z) per marker "
                                 f"after the time column, got {len(coord_cols)} columns")
    labels: list[str] = []
    for i in range(0, len(coord_cols), 3):
        trip = []
        for j, axis in enumerate("xyz"):
            m = _COORD.match(coord_cols[i + j])
            if m is None or m.group("axis").lower() != axis:
                raise FileFormatError(
                    p, f"line {header_ln}: column {i + j + 2} ({coord_cols[i + j]!r}) should be "
                       f"'<label>_{axis}'")
            trip.append(m.group("label"))
        if len(set(trip)) != 1:
            raise FileFormatError(p, f"line {header_ln}: columns {coord_cols[i:i + 3]} do not name "
                                     "one marker")
        labels.append(trip[0])
    ncol = len(names)
    data = np.full((len(rows) - 1, ncol), np.nan)
    for r, (ln, line) in enumerate(rows[1:]):
        cells = next(csv.reader([line], delimiter=delim))
        if len(cells) != ncol:
            raise FileFormatError(p, f"line {ln}: expected {ncol} fields, found {len(cells)} "
                                     "(truncated or malformed row)")
        for c, cell in enumerate(cells):
            cs = cell.strip()
            if cs == "" or cs.lower() in ("nan", "na", "null"):
                if c == 0:
                    raise FileFormatError(p, f"line {ln}: the time/frame value is missing")
                continue
            try:
                data[r, c] = float(cs)
            except ValueError:
                raise FileFormatError(p, f"line {ln}, column {c + 1}: {cs!r} is not a "
                                         "number") from None
    if data.shape[0] < 2:
        raise FileFormatError(p, f"only {data.shape[0]} data rows; need at least 2 frames")
    file_units = meta.get("units") or meta.get("unit")
    if units is not None and file_units is not None:
        if not math.isclose(length_factor(units), length_factor(file_units)):
            raise FileFormatError(p, f"units={units!r} disagrees with the file's "
                                     f"'# units: {file_units}'")
    unit = units if units is not None else file_units
    if unit is None:
        raise FileFormatError(p, "no length unit: add a '# units: mm' line to the file or pass "
                                 "units= (e.g. --marker-units mm)")
    try:
        fac = length_factor(unit, name="units")
    except ValueError as exc:
        raise FileFormatError(p, str(exc)) from None
    tcol = data[:, 0]
    if first == "frame":
        fr = rate
        if fr is None and "rate" in meta:
            try:
                fr = float(meta["rate"].split()[0])
            except ValueError:
                raise FileFormatError(p, f"'# rate: {meta['rate']}' is not a number") from None
        if fr is None or not (math.isfinite(fr) and fr > 0):
            raise FileFormatError(p, "a 'frame' column needs the frame rate: add '# rate: 500' "
                                     "or pass rate=")
        tcol = (tcol - tcol[0]) / fr
    if np.any(np.diff(tcol) <= 0):
        row = int(np.flatnonzero(np.diff(tcol) <= 0)[0])
        raise FileFormatError(p, f"time does not increase at data row {row + 2}")
    xyz = data[:, 1:].reshape(data.shape[0], len(labels), 3) * fac
    return MarkerTracks(tcol, xyz, tuple(labels), str(p),
                        {"format": "csv", "units": unit})


def write_csv_markers(tracks: MarkerTracks, path: str | Path, *, units: str = "mm") -> Path:
    """Write ``tracks`` in the documented CSV layout (occluded samples as empty cells)."""
    fac = length_factor(units)
    p = Path(path)
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


def read_markers(
    path: str | Path, *, units: str | None = None, rate: float | None = None
) -> MarkerTracks:
    """Read marker tracks, choosing the reader by extension (.c3d, else CSV/text)."""
    p = Path(path)
    if p.suffix.lower() == ".c3d":
        return read_c3d(p, units=units)
    if p.suffix.lower() in (".csv", ".txt", ".tsv"):
        return read_csv_markers(p, units=units, rate=rate)
    if p.is_file():
        head = p.read_bytes()[:512]
        if len(head) >= 2 and head[1] == 0x50:
            return read_c3d(p, units=units)
    raise FileFormatError(p, f"unknown marker file type {p.suffix!r}; expected .c3d or .csv")
