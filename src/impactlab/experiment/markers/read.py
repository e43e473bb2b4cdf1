"""One reader for marker files: C3D by its extension (or signature), text by its content."""

from __future__ import annotations

from pathlib import Path

from impactlab.experiment.checks import check_path
from impactlab.experiment.errors import FileFormatError
from impactlab.experiment.markers.c3d import read_c3d
from impactlab.experiment.markers.csv_format import TEXT_LAYOUTS, read_csv_markers
from impactlab.experiment.markers.qualisys_tsv import looks_like_qtm, read_qtm_tsv
from impactlab.experiment.markers.tracks import MarkerTracks, rate_argument
from impactlab.experiment.markers.vicon_csv import looks_like_vicon, read_vicon_csv

__all__ = ["read_markers"]

#: Bytes read to tell the text layouts apart.
_SNIFF = 8192


def _read_text_markers(p: Path, units: str | None, rate: float | None) -> MarkerTracks:
    """A marker text file in the layout its first lines show: a QTM TSV export, a Vicon Nexus
    CSV export, else impactlab's marker CSV."""
    raw = p.read_bytes()[:_SNIFF] if p.is_file() else b""
    if len(raw) >= 512 and raw[1] == 0x50 and b"\x00" in raw:  # a C3D file named as text
        raise FileFormatError(
            p,
            f"a C3D file (the 0x50 signature of its header), not {p.suffix} text: rename it to "
            ".c3d",
        )
    head = raw.decode("utf-8", errors="replace")
    if looks_like_qtm(head):
        return read_qtm_tsv(p, units=units, rate=rate)
    if looks_like_vicon(head):
        return read_vicon_csv(p, units=units, rate=rate)
    return read_csv_markers(p, units=units, rate=rate)


def read_markers(
    path: str | Path, *, units: str | None = None, rate: float | str | None = None
) -> MarkerTracks:
    """Read marker tracks: C3D by extension (.c3d, or the C3D signature), and text (.csv, .txt,
    .tsv) by its content: impactlab's marker CSV, a Qualisys QTM TSV export or a Vicon Nexus
    CSV export (Trajectories).

    ``units``: the coordinates' length unit (a CSV's '# units:' line or a Vicon export's units
    row must agree with it; a C3D file's POINT:UNITS, or the millimetres of a QTM export, are
    replaced by it). ``rate``: the frame rate, a number in Hz or a string with its unit ("500
    Hz", "0.5 kHz", "500 fps"; TypeError or ValueError naming it otherwise); needed for a CSV
    'frame' column without a '# rate:' line; a rate the file states (a C3D header, a '# rate:'
    line, a 'time' column, a QTM FREQUENCY line, a Vicon rate row) must agree with it within
    1 %, and a '# rate:' line with a 'time' column."""
    p = check_path(path, "path")
    rate = rate_argument(rate)
    if p.suffix.lower() == ".c3d":
        return read_c3d(p, units=units, rate=rate)
    if p.suffix.lower() in (".csv", ".txt", ".tsv"):
        return _read_text_markers(p, units, rate)
    if p.is_file():
        head = p.read_bytes()[:512]
        if len(head) >= 2 and head[1] == 0x50:
            return read_c3d(p, units=units, rate=rate)
    raise FileFormatError(
        p,
        f"unknown marker file type {p.suffix!r}; expected C3D (.c3d) or CSV text (.csv, .txt "
        f"or .tsv; {TEXT_LAYOUTS})",
    )
