"""Cells of a plain text height map: a tab-separated map lost its empty (no-data) cells, which
shifted the columns (L_s 1364 um instead of 1406 um) or refused the file as ragged."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import FileFormatError, measure_dent, read_scan

HEADER = "# pixel_size: 10 um\n# height_unit: um\n"


def _write(path: Path, z: np.ndarray, sep: str) -> Path:
    rows = [sep.join("" if not np.isfinite(v) else f"{v * 1e6:.5f}" for v in row) for row in z]
    path.write_text(HEADER + "\n".join(rows) + "\n", encoding="utf-8")
    return path


@pytest.fixture(scope="module")
def scan() -> np.ndarray:
    z, *_ = S.synthetic_scan(delta_p=22e-6, sliding_length=400e-6, pixel=10e-6, seed=1, dropouts=0)
    return z


def test_empty_cells_between_tabs_are_no_data(tmp_path: Path, scan: np.ndarray) -> None:
    """The same columns empty in every row: read as the comma-separated file is."""
    z = scan.copy()
    z[:, 40:46] = np.nan
    comma = read_scan(_write(tmp_path / "map.csv", z, ","))
    tab = read_scan(_write(tmp_path / "map.txt", z, "\t"))
    assert tab.shape == comma.shape == z.shape
    np.testing.assert_array_equal(np.isnan(tab.z), np.isnan(z))
    np.testing.assert_allclose(tab.z, comma.z, equal_nan=True)
    assert measure_dent(tab).sliding_length.value == measure_dent(comma).sliding_length.value


def test_empty_cells_in_other_columns_per_row_are_not_ragged(
    tmp_path: Path, scan: np.ndarray
) -> None:
    """Empty cells at different places per row, the first and the last cell among them, and a
    row of empty cells only."""
    z = scan.copy()
    rng = np.random.default_rng(4)
    z[rng.random(z.shape) < 0.03] = np.nan
    z[3, 0] = z[5, -1] = z[6, :2] = z[7, -3:] = np.nan
    z[9, :] = np.nan  # a line of tabs only
    hm = read_scan(_write(tmp_path / "map.txt", z, "\t"))
    assert hm.shape == z.shape
    np.testing.assert_array_equal(np.isnan(hm.z), np.isnan(z))
    np.testing.assert_allclose(hm.z, z, rtol=0, atol=1e-11, equal_nan=True)


def test_blanks_are_one_separator(tmp_path: Path) -> None:
    """Spaces for alignment: a run of them separates two cells (no empty cells; nan marks one)."""
    rows = ["  1.5    2.0  nan 4", "5   6    7   8  "] * 4
    p = tmp_path / "blanks.txt"
    p.write_text(HEADER + "\n".join(r + "  9" * 4 for r in rows) + "\n", encoding="utf-8")
    hm = read_scan(p)
    assert hm.shape == (8, 8)
    assert np.isnan(hm.z[0, 2]) and hm.z[1, 3] == pytest.approx(8e-6)


def test_a_really_ragged_tab_file_is_still_refused(tmp_path: Path) -> None:
    rows = ["\t".join(["1"] * 8)] * 7 + ["\t".join(["1"] * 6)]
    p = tmp_path / "ragged.txt"
    p.write_text(HEADER + "\n".join(rows) + "\n", encoding="utf-8")
    with pytest.raises(FileFormatError, match="line 10: 6 values, but the first row has 8"):
        read_scan(p)
