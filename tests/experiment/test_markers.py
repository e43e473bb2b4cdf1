"""Marker readers: C3D (ezc3d and the pure-Python c3d fallback) and CSV."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import (
    FileFormatError,
    MarkerTracks,
    read_c3d,
    read_csv_markers,
    read_markers,
    write_csv_markers,
)
from impactlab.experiment.markers import length_factor


def _tracks(n: int = 30, m: int = 3, seed: int = 0) -> MarkerTracks:
    rng = np.random.default_rng(seed)
    pos = rng.uniform(-0.4, 0.4, (n, m, 3))
    pos[3, 1] = np.nan
    pos[10:13, 2] = np.nan
    return MarkerTracks(np.arange(n) / 500.0, pos, tuple(f"M{i + 1}" for i in range(m)))


@pytest.mark.parametrize("backend", ["ezc3d", "c3d"])
@pytest.mark.parametrize("units", ["mm", "m"])
def test_c3d_round_trip(tmp_path: Path, backend: str, units: str) -> None:
    tr = _tracks()
    p = S.write_c3d(tr, tmp_path / "t.c3d", units=units)
    back = read_c3d(p, backend=backend)
    assert back.labels == tr.labels
    assert back.rate == pytest.approx(500.0)
    np.testing.assert_array_equal(back.valid, tr.valid)  # occlusions masked, nothing else
    # float32 storage: relative precision ~6e-8 of the value in file units
    np.testing.assert_allclose(back.positions[tr.valid], tr.positions[tr.valid], atol=1e-7)
    assert back.meta["backend"] == backend


def test_c3d_falls_back_to_pure_python_reader(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    p = S.write_c3d(_tracks(), tmp_path / "t.c3d")
    monkeypatch.setitem(sys.modules, "ezc3d", None)  # "not installed"
    back = read_c3d(p)
    assert back.meta["backend"] == "c3d"
    assert any("ezc3d" in note for note in back.meta["fallback_notes"])


def test_c3d_units_override(tmp_path: Path) -> None:
    p = S.write_c3d(_tracks(), tmp_path / "t.c3d", units="mm")
    a = read_c3d(p)
    b = read_c3d(p, units="cm")
    np.testing.assert_allclose(b.positions[a.valid], 10.0 * a.positions[a.valid])


@pytest.mark.parametrize("backend", ["auto", "c3d"])
def test_truncated_c3d_is_refused(tmp_path: Path, backend: str) -> None:
    p = S.write_c3d(_tracks(n=300), tmp_path / "t.c3d")
    raw = p.read_bytes()
    bad = tmp_path / "trunc.c3d"
    bad.write_bytes(raw[: len(raw) // 2])
    with pytest.raises(FileFormatError, match=r"trunc\.c3d.*truncated"):
        read_c3d(bad, backend=backend)


@pytest.mark.parametrize(
    ("content", "match"),
    [
        (b"", "empty file"),
        (b"this is not a c3d file" * 40, "not a readable C3D file"),
        (b"\x02P" + b"\x00" * 100, "not a readable C3D file|truncated"),
    ],
)
def test_corrupt_c3d(tmp_path: Path, content: bytes, match: str) -> None:
    p = tmp_path / "bad.c3d"
    p.write_bytes(content)
    with pytest.raises(FileFormatError, match=match) as exc:
        read_c3d(p)
    assert "bad.c3d" in str(exc.value)


def test_missing_file() -> None:
    with pytest.raises(FileFormatError, match="does not exist"):
        read_markers("/nonexistent/drop.c3d")


def test_csv_round_trip(tmp_path: Path) -> None:
    tr = _tracks()
    p = write_csv_markers(tr, tmp_path / "t.csv", units="mm")
    back = read_csv_markers(p)
    np.testing.assert_array_equal(back.valid, tr.valid)
    np.testing.assert_allclose(back.positions[tr.valid], tr.positions[tr.valid], atol=1e-8)
    np.testing.assert_allclose(back.time, tr.time, atol=1e-9)
    assert read_markers(p).labels == tr.labels


def test_csv_units_from_argument_and_conflict(tmp_path: Path) -> None:
    p = tmp_path / "t.csv"
    rows = "\n".join(f"{k / 500:.4f},{k},{k},{k},1,2,3,4,5,{k}" for k in range(5))
    p.write_text("time,A_x,A_y,A_z,B.X,B.Y,B.Z,c:x,c:y,c:z\n" + rows + "\n")
    with pytest.raises(FileFormatError, match="no length unit"):
        read_csv_markers(p)
    t = read_csv_markers(p, units="cm")
    assert t.labels == ("A", "B", "c")
    assert t.positions[2, 0, 0] == pytest.approx(0.02)
    p2 = tmp_path / "t2.csv"
    p2.write_text("# units: mm\n" + p.read_text())
    with pytest.raises(FileFormatError, match="disagrees"):
        read_csv_markers(p2, units="m")


def test_csv_frame_column_needs_rate(tmp_path: Path) -> None:
    """The message says what to put in the file (the command line has no rate option)."""
    p = tmp_path / "f.csv"
    p.write_text("# units: mm\nframe,A_x,A_y,A_z\n1,0,0,0\n2,0,0,1\n3,0,0,2\n")
    with pytest.raises(FileFormatError, match="add a line '# rate: 500 Hz' above the header"):
        read_csv_markers(p)
    t = read_csv_markers(p, rate=250.0)
    np.testing.assert_allclose(t.time, [0.0, 0.004, 0.008])


@pytest.mark.parametrize(
    "rate", ["500", "500 Hz", "0.5 kHz", "500 1/s", "500/s", "500 fps", "500 frames per second"]
)
def test_csv_rate_with_its_unit(tmp_path: Path, rate: str) -> None:
    """The unit of '# rate:' is read, never dropped ('0.5 kHz' was read as 0.5 Hz)."""
    p = tmp_path / "f.csv"
    p.write_text(f"# units: mm\n# rate: {rate}\nframe,A_x,A_y,A_z\n1,0,0,0\n2,0,0,1\n")
    np.testing.assert_allclose(read_csv_markers(p).time, [0.0, 0.002])


@pytest.mark.parametrize(
    ("rate", "needle"),
    [("500 mm", "wrong dimension"), ("fast", "cannot parse"), ("0 Hz", "must be > 0 Hz")],
)
def test_csv_rate_that_is_not_a_frame_rate(tmp_path: Path, rate: str, needle: str) -> None:
    p = tmp_path / "f.csv"
    p.write_text(f"# units: mm\n# rate: {rate}\nframe,A_x,A_y,A_z\n1,0,0,0\n2,0,0,1\n")
    with pytest.raises(FileFormatError, match=f"'# rate: {rate}'") as caught:
        read_csv_markers(p)
    assert needle in str(caught.value)


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("# units: mm\ntime,A_x,A_y,A_z\n0,1,2,3\n0.002,1,2\n", r"line 4: expected 4 fields"),
        ("# units: mm\ntime,A_x,A_y,A_z\n0,1,2,3\n0.002,1,abc,3\n", r"line 4, column 3: 'abc'"),
        ("# units: mm\nstamp,A_x,A_y,A_z\n0,1,2,3\n", "first column must be 'time'"),
        ("# units: mm\ntime,A_x,A_y\n0,1,2\n", "three columns"),
        ("# units: mm\ntime,A_x,A_z,A_y\n0,1,2,3\n0.1,1,2,3\n", "should be '<label>_y'"),
        ("# units: parsec/s\ntime,A_x,A_y,A_z\n0,1,2,3\n0.1,1,2,3\n", "not a length unit"),
        ("# units: mm\ntime,A_x,A_y,A_z\n0,1,2,3\n0,1,2,3\n", r"line 4: the time does not inc"),
    ],
)
def test_csv_errors_name_the_problem(tmp_path: Path, text: str, match: str) -> None:
    p = tmp_path / "bad.csv"
    p.write_text(text)
    with pytest.raises(FileFormatError, match=match) as exc:
        read_csv_markers(p)
    assert "bad.csv" in str(exc.value)


def test_binary_file_as_csv(tmp_path: Path) -> None:
    p = tmp_path / "bin.csv"
    p.write_bytes(bytes(range(256)) * 4)
    with pytest.raises(FileFormatError, match=r"bin.csv"):
        read_csv_markers(p)


def test_unknown_extension(tmp_path: Path) -> None:
    p = tmp_path / "x.trc"
    p.write_text("whatever")
    with pytest.raises(FileFormatError, match="unknown marker file type"):
        read_markers(p)


def test_length_factor() -> None:
    assert length_factor("mm") == pytest.approx(1e-3)
    assert length_factor("µm") == pytest.approx(1e-6)
    assert length_factor("in") == pytest.approx(0.0254)
    with pytest.raises(ValueError, match="not a length"):
        length_factor("s")
