"""UTF-16 text (Excel's "Unicode Text", a byte order mark FF FE or FE FF) is named as such, with
how to save it as UTF-8: a scan CSV was said to lack the pixel size lines it holds, or to be
"not a text file"."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab._validation import read_text_file
from impactlab.experiment import FileFormatError, read_markers, read_scan

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
UTF16 = "UTF-16 text: save the file as UTF-8"


@pytest.mark.parametrize("codec", ["utf-16", "utf-16-be"])
def test_the_text_reader_names_it(tmp_path: Path, codec: str) -> None:
    path = tmp_path / "a.csv"
    bom = b"\xfe\xff" if codec == "utf-16-be" else b""
    path.write_bytes(bom + "x,y\n1,2\n".encode(codec))
    with pytest.raises(ValueError, match=f"^{UTF16} \\(CSV is read as UTF-8; Excel: 'CSV UTF-8'"):
        read_text_file(path, "CSV")


@pytest.mark.parametrize("options", [{}, {"pixel_size": "12 um", "height_unit": "um"}])
def test_a_scan_csv(tmp_path: Path, options: dict[str, str]) -> None:
    z = np.load(DATA / "dent.npy")[:20, :30]
    lines = ["# pixel_size: 12 um", "# height_unit: um"]
    lines += [",".join(f"{v:.4f}" for v in row) for row in z]
    path = tmp_path / "scan.csv"
    path.write_bytes("\n".join(lines).encode("utf-16"))
    with pytest.raises(FileFormatError, match=UTF16):
        read_scan(path, **options)


def test_a_marker_csv(tmp_path: Path) -> None:
    path = tmp_path / "drop.csv"
    path.write_bytes((DATA / "drop.csv").read_text().encode("utf-16"))
    with pytest.raises(FileFormatError, match=UTF16):
        read_markers(path)
