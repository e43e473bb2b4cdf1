"""Marker text files as motion-capture software exports them: Qualisys QTM TSV, Vicon Nexus CSV
(Trajectories), a time column with its unit, and the message for a layout that is none of them."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import FileFormatError, MarkerGeometry, measure_impact, read_markers
from impactlab.experiment.markers import MarkerTracks

RATE = 500.0


def _drop(seed: int = 3) -> MarkerTracks:
    """A 45 deg impulse drop at 500 fps, with occlusions."""
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45.0), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, _ = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=seed, rate=RATE)
    return tracks


def _mm(v: float) -> str:
    return f"{v * 1e3:.3f}"


def qtm_text(
    tracks: MarkerTracks,
    *,
    column_header: bool = True,
    frame_time: bool = True,
    gap: str = "zeros",
    announced: int | None = None,
    frequency: str = "500",
) -> str:
    """``tracks`` as QTM writes a TSV export of 3D data (mm); a gap as ``gap``: "zeros"
    (0.000 three times) or "empty" cells."""
    n, labels = tracks.n_frames, tracks.labels
    lines = [
        f"NO_OF_FRAMES\t{n if announced is None else announced}",
        "NO_OF_CAMERAS\t8",
        f"NO_OF_MARKERS\t{len(labels)}",
        f"FREQUENCY\t{frequency}",
        "NO_OF_ANALOG\t0",
        "ANALOG_FREQUENCY\t0",
        "DESCRIPTION\t--",
        "TIME_STAMP\t2024-01-01, 10:00:00.000\t0.0",
        "DATA_INCLUDED\t3D",
        "EVENT\tdrop\t12\t0.022",
        "MARKER_NAMES\t" + "\t".join(labels),
        "TRAJECTORY_TYPES\t" + "\t".join("Measured" for _ in labels),
    ]
    if column_header:
        coords = [f"{lab} {a}" for lab in labels for a in "XYZ"]
        lines.append("\t".join((["Frame", "Time"] if frame_time else []) + coords))
    for k in range(n):
        row = [str(k + 1), f"{k / RATE:.5f}"] if frame_time else []
        for j in range(len(labels)):
            p = tracks.positions[k, j]
            if np.all(np.isfinite(p)):
                row += [_mm(v) for v in p]
            else:
                row += ["0.000"] * 3 if gap == "zeros" else [""] * 3
        lines.append("\t".join(row))
    return "\n".join(lines) + "\n"


def vicon_text(tracks: MarkerTracks, *, unit: str = "mm", sections: bool = True) -> str:
    """``tracks`` as Vicon Nexus writes a CSV export (a Devices section before the Trajectories
    and a Model Outputs section after them when ``sections``); gaps as empty cells."""
    fac = {"mm": 1e3, "m": 1.0}[unit]
    labels = [f"Rod:{lab}" for lab in tracks.labels]
    m = len(labels)
    out = []
    if sections:
        out += [
            "Devices",
            "1000",
            ",,Force Plate::Force",
            "Frame,Sub Frame,Fx",
            ",,N",
            "1,0,0.1",
            "",
        ]
    out += [
        "Trajectories",
        f"{RATE:g}",
        ",," + ",".join(f"{lab},," for lab in labels).rstrip(","),
        "Frame,Sub Frame," + ",".join("X,Y,Z" for _ in range(m)),
        ",," + ",".join(f"{unit},{unit},{unit}" for _ in range(m)),
    ]
    for k in range(tracks.n_frames):
        row = [str(k + 1), "0"]
        for j in range(m):
            p = tracks.positions[k, j]
            row += [f"{v * fac:.6f}" for v in p] if np.all(np.isfinite(p)) else ["", "", ""]
        out.append(",".join(row))
    if sections:
        out += ["", "Model Outputs", "500", ",,Rod:Angle", "Frame,Sub Frame,X", ",,deg", "1,0,3"]
    return "\n".join(out) + "\n"


def _same_tracks(a: MarkerTracks, b: MarkerTracks, atol: float = 1e-6) -> None:
    assert np.array_equal(a.valid, b.valid)
    assert np.allclose(a.positions[a.valid], b.positions[b.valid], atol=atol, rtol=0)
    assert np.allclose(a.time, b.time, atol=1e-12, rtol=0)


# -- Qualisys QTM TSV ---------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("column_header", "frame_time", "gap"),
    [(True, True, "zeros"), (True, True, "empty"), (False, True, "zeros"), (False, False, "zeros")],
)
def test_qtm_tsv_is_read_in_mm_with_its_rate_and_gaps(
    tmp_path: Path, column_header: bool, frame_time: bool, gap: str
) -> None:
    tracks = _drop()
    assert (~tracks.valid).any()  # the gaps are tested
    path = tmp_path / "drop.tsv"
    path.write_text(qtm_text(tracks, column_header=column_header, frame_time=frame_time, gap=gap))
    back = read_markers(path)
    assert back.meta["format"] == "qtm-tsv" and back.meta["units"] == "mm"
    assert back.labels == tracks.labels and back.rate == pytest.approx(RATE)
    _same_tracks(back, tracks)


def test_qtm_tsv_is_told_by_its_content_not_its_extension(tmp_path: Path) -> None:
    path = tmp_path / "drop.txt"
    path.write_text(qtm_text(_drop()))
    assert read_markers(path).meta["format"] == "qtm-tsv"
    assert read_markers(path, units="cm").positions[0, 0, 0] == pytest.approx(
        10 * read_markers(path).positions[0, 0, 0]
    )


def test_qtm_tsv_gives_the_same_impact_as_the_tracks(tmp_path: Path) -> None:
    tracks = _drop()
    path = tmp_path / "drop.tsv"
    path.write_text(qtm_text(tracks))
    geo = MarkerGeometry(S.DEFAULT_MARKERS, tracks.labels)
    a = measure_impact(tracks, PAPER_ROD, geometry=geo)
    b = measure_impact(read_markers(path), PAPER_ROD, geometry=geo)
    assert b.e.value == pytest.approx(a.e.value, abs=2e-3)
    assert b.mu.value == pytest.approx(a.mu.value, abs=2e-3)


@pytest.mark.parametrize(
    ("change", "message"),
    [
        (
            {"announced": 400},
            r"NO_OF_FRAMES announces 400 frames but the file holds \d+ rows "
            r"\(a truncated file\)",
        ),
        ({"frequency": "250"}, r"FREQUENCY 250 Hz contradicts the Time column"),
        ({"announced": "5.7"}, r"the NO_OF_FRAMES line holds '5.7', not a whole number >= 0"),
    ],
)
def test_qtm_tsv_header_that_contradicts_the_data_is_refused(
    tmp_path: Path, change: dict[str, object], message: str
) -> None:
    path = tmp_path / "drop.tsv"
    path.write_text(qtm_text(_drop(), **change))  # type: ignore[arg-type]
    with pytest.raises(FileFormatError, match=message):
        read_markers(path)


def test_qtm_tsv_rate_argument_must_agree(tmp_path: Path) -> None:
    path = tmp_path / "drop.tsv"
    path.write_text(qtm_text(_drop()))
    with pytest.raises(FileFormatError, match=r"rate=250 Hz disagrees .* 500 Hz \(its FREQUENCY"):
        read_markers(path, rate=250)


# -- Vicon Nexus CSV ----------------------------------------------------------------------------


@pytest.mark.parametrize(("unit", "sections"), [("mm", True), ("m", False)])
def test_vicon_csv_trajectories_are_read_with_their_unit_and_rate(
    tmp_path: Path, unit: str, sections: bool
) -> None:
    tracks = _drop()
    path = tmp_path / "drop.csv"
    path.write_text(vicon_text(tracks, unit=unit, sections=sections))
    back = read_markers(path)
    assert back.meta["format"] == "vicon-csv" and back.meta["units"] == unit
    assert back.labels == tuple(f"Rod:{lab}" for lab in tracks.labels)
    assert back.rate == pytest.approx(RATE)
    _same_tracks(back, tracks)


def test_vicon_csv_units_argument_must_agree(tmp_path: Path) -> None:
    path = tmp_path / "drop.csv"
    path.write_text(vicon_text(_drop()))
    assert read_markers(path, units="millimetre").meta["units"] == "mm"
    with pytest.raises(FileFormatError, match=r"units='m' disagrees with the file's unit 'mm'"):
        read_markers(path, units="m")


def test_vicon_csv_without_units_needs_them(tmp_path: Path) -> None:
    path = tmp_path / "drop.csv"
    text = vicon_text(_drop(), sections=False).splitlines()
    text[4] = ",," + "," * 8  # the units row, empty
    path.write_text("\n".join(text) + "\n")
    with pytest.raises(FileFormatError, match=r"line 5: the units row is empty; pass units="):
        read_markers(path)
    assert read_markers(path, units="mm").meta["units"] == "mm"


# -- the time column's unit, and a layout that is none of those read ----------------------------


@pytest.mark.parametrize(
    ("name", "scale"), [("Time (s)", 1.0), ("time [ms]", 1e3), ("Time_ms", 1e3)]
)
def test_a_time_column_with_its_unit(tmp_path: Path, name: str, scale: float) -> None:
    rows = [f"{k / RATE * scale:.6g},{k * 0.1:.3f},0,0,1,0,0,0,1,0" for k in range(20)]
    path = tmp_path / "m.csv"
    path.write_text(f"# units: mm\n{name},A_x,A_y,A_z,B_x,B_y,B_z,C_x,C_y,C_z\n" + "\n".join(rows))
    back = read_markers(path)
    assert back.time[1] == pytest.approx(1 / RATE) and back.rate == pytest.approx(RATE)


def test_a_time_column_in_another_unit_than_time_is_refused(tmp_path: Path) -> None:
    path = tmp_path / "m.csv"
    path.write_text("# units: mm\nTime (mm),A_x,A_y,A_z\n0,1,2,3\n0.002,1,2,3\n")
    with pytest.raises(FileFormatError, match=r"line 2: the first column 'Time \(mm\)' is not in"):
        read_markers(path)


@pytest.mark.parametrize(
    "text",
    [
        "Sample\tM1.X\tM1.Y\tM1.Z\n1\t2\t3\t4\n",  # another program's table
        "frames of a drop\n1\n2\n",  # a single column
    ],
)
def test_a_text_file_in_none_of_the_layouts_names_them_and_c3d(tmp_path: Path, text: str) -> None:
    path = tmp_path / "m.txt"
    path.write_text(text)
    with pytest.raises(FileFormatError) as info:
        read_markers(path)
    msg = str(info.value)
    assert "Qualisys QTM TSV" in msg and "Vicon Nexus CSV" in msg and "export C3D" in msg
