"""Text files as labs write them: a header key stated twice, x,y,z point lists, European
spreadsheets (semicolons and decimal commas, Windows-1252), the marker file types accepted."""

from __future__ import annotations

import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import (
    FileFormatError,
    MarkerTracks,
    read_markers,
    read_scan,
    write_csv_markers,
)


@pytest.fixture(scope="module")
def tracks() -> MarkerTracks:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45), (0.0, -2.18), e=0.5, mu=0.13)
    return S.marker_tracks(PAPER_ROD, truth, after=0.03, seed=2)[0]


@pytest.fixture(scope="module")
def marker_csv(tracks: MarkerTracks, tmp_path_factory: pytest.TempPathFactory) -> str:
    """The tracks as the documented CSV (``# units: mm``), as text."""
    path = tmp_path_factory.mktemp("csv") / "drop.csv"
    return write_csv_markers(tracks, path).read_text()


@pytest.fixture(scope="module")
def heights() -> tuple[np.ndarray, float]:
    z, dx, *_ = S.synthetic_scan(delta_p=22e-6, sliding_length=1400e-6, seed=1, dropouts=0.0)
    return z[:60, :80], dx  # a corner: text files stay small


# -- a header key twice ------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("lines", "needle"),
    [
        (
            "# units: m\n# units: mm\n",
            "lines 1 and 2 state units twice, differently: '# units: m' and '# units: mm'",
        ),
        ("# unit: m\n# units: mm\n", "'# unit: m' and '# units: mm' disagree"),
    ],
)
def test_a_marker_unit_stated_twice_differently_is_refused(
    marker_csv: str, tmp_path: Path, lines: str, needle: str
) -> None:
    """The last line silently won."""
    body = marker_csv.replace("# units: mm\n", "")
    path = tmp_path / "twice.csv"
    path.write_text(lines + body)
    with pytest.raises(FileFormatError, match=needle):
        read_markers(path)


def test_the_same_value_twice_and_other_comments_are_fine(
    marker_csv: str, tracks: MarkerTracks, tmp_path: Path
) -> None:
    path = tmp_path / "same.csv"
    path.write_text("# units: MM\n# note: first\n# note: second\n" + marker_csv)
    got = read_markers(path)
    assert np.allclose(got.positions, tracks.positions, atol=1e-7, equal_nan=True)


def test_a_pixel_size_stated_twice_differently_is_refused(
    heights: tuple[np.ndarray, float], tmp_path: Path
) -> None:
    z, dx = heights
    rows = "\n".join(",".join(f"{v * 1e6:.4f}" for v in row) for row in z)
    same = tmp_path / "same.csv"
    same.write_text(f"# pixel_size: 8 um\n# pixel_size: 8.0 um\n# height_unit: um\n{rows}\n")
    assert read_scan(same).dx == pytest.approx(dx)
    twice = tmp_path / "twice.csv"
    twice.write_text(f"# pixel_size: 8 um\n# height_unit: um\n# pixel_size: 2 um\n{rows}\n")
    with pytest.raises(FileFormatError, match="lines 1 and 3 state pixel_size twice"):
        read_scan(twice)


# -- x,y,z point lists ---------------------------------------------------------------------------


def _xyz(z: np.ndarray, dx: float) -> np.ndarray:
    ny, nx = z.shape
    x, y = np.meshgrid(np.arange(nx) * dx, np.arange(ny) * dx)
    return np.column_stack([x.ravel(), y.ravel(), z.ravel()])


def test_a_point_list_read_as_a_matrix_says_what_it_is(
    heights: tuple[np.ndarray, float], tmp_path: Path
) -> None:
    """It said 'a height map must be 2D ... got shape (4800, 3)'."""
    z, dx = heights
    path = tmp_path / "points.csv"
    np.savetxt(path, _xyz(z, dx), delimiter=",")
    with pytest.raises(FileFormatError, match="looks like an x,y,z point list") as info:
        read_scan(path, pixel_size="8 um", height_unit="m")
    assert "leave out pixel_size= (--pixel-size)" in str(info.value)
    np.save(tmp_path / "points.npy", _xyz(z, dx))
    with pytest.raises(FileFormatError, match=r"point list.*\.xyz"):
        read_scan(tmp_path / "points.npy", pixel_size="8 um", height_unit="m")


def test_a_point_list_saved_as_txt_is_read(
    heights: tuple[np.ndarray, float], tmp_path: Path
) -> None:
    """It could not be read at all (taken for a matrix without a pixel size)."""
    pytest.importorskip("SurfaceTopography")
    z, dx = heights
    path = tmp_path / "points.txt"
    np.savetxt(path, _xyz(z, dx))
    hm = read_scan(path, height_unit="m")
    assert hm.z.shape == z.shape and hm.dx == pytest.approx(dx, rel=1e-6)
    assert np.allclose(hm.z, z)


# -- European spreadsheets -----------------------------------------------------------------------


def test_a_height_map_with_semicolons_and_decimal_commas_is_read(
    heights: tuple[np.ndarray, float], tmp_path: Path
) -> None:
    """It gave "line 3: '03456;0' is not a number" (the comma taken for the separator)."""
    z, _ = heights
    rows = "\n".join(";".join(f"{v * 1e6:.5f}".replace(".", ",") for v in row) for row in z)
    path = tmp_path / "eu.csv"
    path.write_text(f"# pixel_size: 8 um\n# height_unit: um\n{rows}\n")
    assert np.allclose(read_scan(path).z, z, atol=1e-11)


def test_a_comma_height_map_with_a_stray_tab_is_read(
    heights: tuple[np.ndarray, float], tmp_path: Path
) -> None:
    """A tab or semicolon on one line of a comma file is not its separator (it made every
    line 'not a number')."""
    z, _ = heights
    lines = [",".join(f"{v * 1e6:.5f}" for v in row) for row in z]
    lines[3] += "\t"
    path = tmp_path / "stray.csv"
    path.write_text("# pixel_size: 8 um\n# height_unit: um\n" + "\n".join(lines) + "\n")
    assert np.allclose(read_scan(path).z, z, atol=1e-11)


def test_marker_csv_with_semicolons_and_decimal_commas_is_read(
    marker_csv: str, tracks: MarkerTracks, tmp_path: Path
) -> None:
    lines = marker_csv.splitlines()
    eu = [ln if ln.startswith("#") else ln.replace(",", ";").replace(".", ",") for ln in lines]
    path = tmp_path / "eu.csv"
    path.write_text("\n".join(eu) + "\n")
    got = read_markers(path)
    assert np.allclose(got.positions, tracks.positions, atol=1e-7, equal_nan=True)


def test_decimal_commas_between_commas_get_a_hint(marker_csv: str, tmp_path: Path) -> None:
    lines = marker_csv.splitlines()
    bad = [ln if ln.startswith(("#", "time")) else ln.replace(".", ",") for ln in lines]
    path = tmp_path / "commas.csv"
    path.write_text("\n".join(bad) + "\n")
    with pytest.raises(FileFormatError, match="decimal commas"):
        read_markers(path)


def test_a_windows_1252_file_is_named_as_such(marker_csv: str, tmp_path: Path) -> None:
    """It said 'not a text file (CSV is UTF-8 text; byte 27 is 0xe9)'."""
    path = tmp_path / "latin.csv"
    path.write_bytes(("# operator: Jos\xe9\n" + marker_csv).encode("cp1252"))
    with pytest.raises(FileFormatError, match="not UTF-8 text") as info:
        read_markers(path)
    text = str(info.value)
    assert (
        "line 1, byte 15 is 0xe9, 'é' in Windows-1252" in text and "save the file as UTF-8" in text
    )


# -- the marker file types -----------------------------------------------------------------------


def test_an_unknown_marker_file_type_lists_what_is_read(
    marker_csv: str, tmp_path: Path, cli_main: Callable[..., tuple[int, str, str]]
) -> None:
    path = tmp_path / "drop.dat"
    path.write_text(marker_csv)
    with pytest.raises(
        FileFormatError, match=r"expected C3D \(\.c3d\) or CSV text \(\.csv, \.txt or \.tsv"
    ):
        read_markers(path)
    code, out, _ = cli_main("analyze", "--help")
    assert code == 0 and ".tsv" in out
