"""One reader for marker files: the format from the extension (or the C3D signature)."""

from __future__ import annotations

from pathlib import Path

from impactlab.experiment.checks import check_path
from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers.c3d import read_c3d
from impactlab.experiment.markers.csv_format import read_csv_markers
from impactlab.experiment.markers.tracks import MarkerTracks, rate_argument

__all__ = ["read_markers"]


def read_markers(
    path: str | Path, *, units: str | None = None, rate: float | str | None = None
) -> MarkerTracks:
    """Read marker tracks, choosing the reader by extension (.c3d, else CSV/text).

    ``units``: the coordinates' length unit (a CSV's '# units:' line must agree with it; a C3D
    file's POINT:UNITS is replaced by it). ``rate``: the frame rate, a number in Hz or a string
    with its unit ("500 Hz", "0.5 kHz", "500 fps"; TypeError or ValueError naming it otherwise);
    needed for a CSV 'frame' column without a '# rate:' line; a rate the file states (a C3D
    header, a '# rate:' line, a 'time' column) must agree with it within 1 %, and a '# rate:'
    line with a 'time' column."""
    p = check_path(path, "path")
    rate = rate_argument(rate)
    if p.suffix.lower() == ".c3d":
        return read_c3d(p, units=units, rate=rate)
    if p.suffix.lower() in (".csv", ".txt", ".tsv"):
        return read_csv_markers(p, units=units, rate=rate)
    if p.is_file():
        head = p.read_bytes()[:512]
        if len(head) >= 2 and head[1] == 0x50:
            return read_c3d(p, units=units, rate=rate)
    raise FileFormatError(
        p,
        f"unknown marker file type {p.suffix!r}; expected C3D (.c3d) or CSV text (.csv, .txt or "
        ".tsv: the layout of docs/experiment.md, Marker tracks)",
    )
