"""rate= of read_markers is read once, the same for every kind of file: a number in Hz or a
string with its unit; a boolean, a NaN, zero or a negative rate refused naming rate=; a
'# rate:' line always checked against a time column. A .txt height map with '# pixel_size:'
lines is read without --pixel-size."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import FileFormatError, read_markers, read_scan, write_csv_markers


@pytest.fixture(scope="module")
def files(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Path]:
    """The same 500 fps drop as a time-column CSV, a frame CSV with '# rate: 500 Hz', a frame
    CSV without a rate, and a C3D file."""
    out = tmp_path_factory.mktemp("frame_rates")
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, _ = S.marker_tracks(PAPER_ROD, truth, rate=500.0, seed=4)
    time = write_csv_markers(tracks, out / "time.csv")
    frames = time.read_text().splitlines()
    head = next(i for i, ln in enumerate(frames) if not ln.startswith("#"))
    rows = [f"{i},{ln.split(',', 1)[1]}" for i, ln in enumerate(frames[head + 1 :])]
    header = "frame," + frames[head].split(",", 1)[1]
    (out / "frame_rate.csv").write_text(
        "\n".join([*frames[:head], "# rate: 500 Hz", header, *rows]) + "\n"
    )
    (out / "frame.csv").write_text("\n".join([*frames[:head], header, *rows]) + "\n")
    c3d = out / "drop.c3d"
    S.write_c3d(tracks, c3d)
    return {"time": time, "frame_rate": out / "frame_rate.csv", "frame": out / "frame.csv",
            "c3d": c3d}  # fmt: skip


KINDS = ["time", "frame_rate", "frame", "c3d"]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize(
    "rate", [500, 500.0, "500", "500 Hz", "0.5 kHz", "500 fps", np.float32(500), np.int64(500)]
)
def test_a_rate_is_read_alike_for_every_kind_of_file(
    files: dict[str, Path], kind: str, rate: object
) -> None:
    tracks = read_markers(files[kind], rate=rate)
    assert tracks.rate == pytest.approx(500.0, rel=1e-3)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize(
    ("rate", "error", "says"),
    [
        (True, TypeError, "rate must be a frame rate (a number in Hz or a string"),
        ([500], TypeError, "got list [500]"),
        (0, ValueError, "rate must be a finite frame rate > 0 Hz, got 0"),
        (-500, ValueError, "rate must be a finite frame rate > 0 Hz, got -500"),
        (math.nan, ValueError, "rate must be a finite frame rate > 0 Hz, got nan"),
        (math.inf, ValueError, "rate must be a finite frame rate > 0 Hz, got inf"),
        ("0 Hz", ValueError, "rate must be > 0 Hz, got '0 Hz'"),
        ("500 mm", ValueError, "rate '500 mm' is not a frame rate"),
        ("fast", ValueError, "rate 'fast' is not a frame rate"),
    ],
)
def test_a_bad_rate_is_refused_alike_for_every_kind_of_file(
    files: dict[str, Path], kind: str, rate: object, error: type, says: str
) -> None:
    with pytest.raises(error) as caught:
        read_markers(files[kind], rate=rate)
    assert says in str(caught.value)
    assert "contradicts" not in str(caught.value)


@pytest.mark.parametrize("kind", ["time", "frame_rate", "c3d"])
def test_a_rate_the_file_contradicts_is_refused(files: dict[str, Path], kind: str) -> None:
    with pytest.raises(FileFormatError, match=r"rate=250 Hz (contradicts|disagrees)"):
        read_markers(files[kind], rate="250 Hz")


@pytest.mark.parametrize("rate", [None, 500, 1000])
def test_a_rate_line_is_checked_against_the_time_column_with_or_without_rate(
    files: dict[str, Path], tmp_path: Path, rate: int | None
) -> None:
    """'# rate: 1000' above steps of 2 ms was refused without rate= but taken with rate=500."""
    p = tmp_path / "lying.csv"
    p.write_text(files["time"].read_text().replace("# units: mm\n", "# units: mm\n# rate: 1000\n"))
    with pytest.raises(FileFormatError, match=r"'# rate: 1000' contradicts the time column"):
        read_markers(p, rate=rate)


def test_a_frame_column_without_a_rate_needs_one(files: dict[str, Path]) -> None:
    with pytest.raises(FileFormatError, match="a 'frame' column needs the frame rate"):
        read_markers(files["frame"])


@pytest.mark.parametrize("suffix", [".txt", ".asc"])
def test_a_text_height_map_with_its_pixel_size_needs_no_option(tmp_path: Path, suffix: str) -> None:
    """Leaving --pixel-size out, as the disagreement's message says, failed: 'Could not find
    any topography data'."""
    z = np.arange(120.0).reshape(10, 12)
    body = "\n".join(",".join(f"{v:g}" for v in row) for row in z)
    p = tmp_path / f"scan{suffix}"
    p.write_text(f"# pixel_size: 8 um\n# height_unit: um\n{body}\n")
    hm = read_scan(p)
    assert hm.dx == pytest.approx(8e-6) and hm.z.shape == (10, 12)
    np.testing.assert_allclose(hm.z, z * 1e-6)
    with pytest.raises(FileFormatError, match="leave the option out"):
        read_scan(p, pixel_size="6 um")
