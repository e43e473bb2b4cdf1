"""Files in a format other than their name says: a C3D file named as a text file (.csv) is named
as C3D, not as text that is not UTF-8; a height matrix cell that is not finite is refused."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import FileFormatError, read_markers, read_scan


def test_a_c3d_file_named_csv_says_so(tmp_path: Path) -> None:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(20), (0.0, -1.41), e=0.5, mu=0.2)
    tracks, _ = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=3)
    S.write_c3d(tracks, tmp_path / "drop.c3d")
    named = tmp_path / "drop.csv"
    (tmp_path / "drop.c3d").rename(named)
    with pytest.raises(FileFormatError, match=r"drop\.csv: a C3D file .*rename it to \.c3d"):
        read_markers(named)


@pytest.mark.parametrize("cell", ["inf", "-inf", "1e400"])
def test_a_height_that_is_not_finite_is_refused(tmp_path: Path, cell: str) -> None:
    path = tmp_path / "h.csv"
    path.write_text(f"1,2,3\n4,{cell},6\n7,8,9\n", encoding="utf-8")
    with pytest.raises(FileFormatError, match=rf"line 2: the cell '{cell}' is not a finite height"):
        read_scan(path, pixel_size="1 um", height_unit="um")
