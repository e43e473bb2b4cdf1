"""A pixel size, height unit or frame rate given as an argument and stated in the file must
agree: --pixel-size "6 um" silently overrode a CSV's '# pixel_size: 8 um' (L_s 1048 um for
1398), an X3P's own pixel size and unit silently won over the options, and read_markers(c3d,
rate=250) returned the file's 500 Hz. A disagreement is refused naming both; an equal value
(in any unit) passes and the file's value is used."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import (
    FileFormatError,
    analyze,
    read_markers,
    read_scan,
    write_csv_markers,
)
from impactlab.experiment.markers import MarkerTracks


@pytest.fixture(scope="module")
def csv_scan(tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, S.ScanTruth]:
    """A CSV height map whose header states '# pixel_size: 8 um' and '# height_unit: um'."""
    z, dx, dy, truth = S.synthetic_scan(seed=4)
    path = tmp_path_factory.mktemp("stated") / "dent.csv"
    S.write_scan(z, dx, dy, path)
    assert "# pixel_size: 8 um" in path.read_text()[:200]
    return path, truth


def test_a_pixel_size_that_disagrees_with_the_csv_header_is_refused(
    csv_scan: tuple[Path, Any],
) -> None:
    path, truth = csv_scan
    with pytest.raises(FileFormatError) as caught:
        read_scan(path, pixel_size="6 um")
    message = str(caught.value)
    assert "pixel_size '6 um' (--pixel-size) disagrees" in message
    assert "the file's pixel size 8 um ('# pixel_size: 8 um')" in message
    res = analyze(None, path, pixel_size="6 um")
    assert res.dent is None and "--pixel-size" in res.errors["scan"]
    for same in ("8 um", "0.008 mm", 8e-6, ("8 um", "8 um")):
        assert read_scan(path, pixel_size=same).dx == pytest.approx(8e-6)
    good = analyze(None, path, pixel_size="8 um")
    assert good.dent is not None
    ls = good.dent.sliding_length
    assert abs(ls.value - truth.groove.sliding_length) < 0.02 * truth.groove.sliding_length


def test_a_height_unit_that_disagrees_with_the_csv_header_is_refused(
    csv_scan: tuple[Path, Any],
) -> None:
    path, _ = csv_scan
    with pytest.raises(FileFormatError) as caught:
        read_scan(path, height_unit="mm")
    message = str(caught.value)
    assert "height_unit 'mm' (--height-unit) disagrees with the file's height unit 'um'" in message
    assert "'# height_unit: um'" in message
    base = read_scan(path)
    for same in ("um", "µm", "micrometer"):
        np.testing.assert_array_equal(read_scan(path, height_unit=same).z, base.z)


def test_a_rectangular_header_is_compared_both_ways(tmp_path: Path) -> None:
    z, dx, _, _ = S.synthetic_scan(seed=5, pixel=8e-6)
    path = S.write_scan(z, dx, 1.5 * dx, tmp_path / "rect.csv")
    assert read_scan(path, pixel_size="8 um, 12 um").dy == pytest.approx(12e-6)
    with pytest.raises(FileFormatError, match=r"8 um x 12 um"):
        read_scan(path, pixel_size="8 um")


def test_an_instrument_files_own_pixel_size_and_unit_must_agree(scans: dict) -> None:
    path = scans[20].files["x3p"]
    dx = scans[20].dx
    with pytest.raises(FileFormatError) as caught:
        read_scan(path, pixel_size="6 um")
    message = str(caught.value)
    assert "pixel_size '6 um' (--pixel-size) disagrees with the file's pixel size 8 um" in message
    assert "X3P" in message
    with pytest.raises(FileFormatError, match=r"height_unit 'um' \(--height-unit\) disagrees"):
        read_scan(path, height_unit="um")
    same = read_scan(path, pixel_size=f"{dx * 1e3} mm", height_unit="m")
    np.testing.assert_array_equal(same.z, read_scan(path).z)


def test_a_frame_rate_that_disagrees_with_a_c3d_header_is_refused(drops: dict) -> None:
    path = drops[20].c3d
    with pytest.raises(FileFormatError) as caught:
        read_markers(path, rate=250)
    message = str(caught.value)
    assert "rate=250 Hz disagrees with the file's frame rate 500 Hz" in message
    assert read_markers(path, rate=500).rate == pytest.approx(500.0)
    assert read_markers(path, rate="500").rate == pytest.approx(500.0)
    assert read_markers(path, rate="500 Hz").rate == pytest.approx(500.0)
    with pytest.raises(ValueError, match=r"rate must be a finite frame rate > 0 Hz, got -1"):
        read_markers(path, rate=-1)


def test_a_frame_rate_that_disagrees_with_a_rate_line_is_refused(tmp_path: Path) -> None:
    n = 40
    pos = np.zeros((n, 3, 3))
    pos[:, :, 0] = np.arange(3) * 0.05
    pos[:, :, 2] = 1.0 - 0.5 * 9.81 * (np.arange(n) / 500.0)[:, None] ** 2
    tracks = MarkerTracks(np.arange(n) / 500.0, pos, ("M1", "M2", "M3"))
    times = write_csv_markers(tracks, tmp_path / "times.csv")
    body = [ln for ln in times.read_text().splitlines() if not ln.startswith("#")]
    path = tmp_path / "frames.csv"
    body[0] = body[0].replace("time", "frame")
    rows = [f"{k}," + ",".join(r.split(",")[1:]) for k, r in enumerate(body[1:])]
    path.write_text("\n".join(["# units: mm", "# rate: 500 Hz", body[0], *rows]) + "\n")
    with pytest.raises(FileFormatError, match=r"rate=250 Hz disagrees .* \('# rate: 500 Hz'\)"):
        read_markers(path, rate=250)
    assert math.isclose(read_markers(path, rate=500).rate, 500.0, rel_tol=1e-9)
    assert math.isclose(read_markers(path).rate, 500.0, rel_tol=1e-9)
