"""The size a C3D header announces: analog data (header word 3: all channels' samples per frame)
were counted as word 10 (one channel's), so a file with analog channels cut to 70 % passed;
a file cut before its data section was reported as holding no points; a label used twice gave
a bare ValueError without the file."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import ezc3d
import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import FileFormatError, MarkerTracks, read_c3d


@pytest.fixture(scope="module")
def tracks() -> MarkerTracks:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45), (0.0, -2.18), e=0.5, mu=0.13)
    return S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=2)[0]


def _analog_c3d(path: Path, tracks: MarkerTracks, labels: list[str] | None = None) -> bytes:
    """The tracks with 6 force-plate channels at 4 samples per frame (ezc3d, floats)."""
    c = ezc3d.c3d()
    c["parameters"]["POINT"]["RATE"]["value"] = [500]
    c["parameters"]["POINT"]["LABELS"]["value"] = labels or list(tracks.labels)
    pts = np.ones((4, tracks.n_markers, tracks.n_frames))
    pts[:3] = np.transpose(np.nan_to_num(tracks.positions) * 1e3, (2, 1, 0))
    c["data"]["points"] = pts
    c["parameters"]["ANALOG"]["RATE"]["value"] = [2000]
    c["parameters"]["ANALOG"]["LABELS"]["value"] = ["Fx", "Fy", "Fz", "Mx", "My", "Mz"]
    c["data"]["analogs"] = np.random.default_rng(0).random((1, 6, 4 * tracks.n_frames))
    c.add_parameter("POINT", "UNITS", ["mm"])
    c.write(str(path))
    return path.read_bytes()


@pytest.mark.parametrize("backend", ["ezc3d", "c3d"])
def test_a_cut_c3d_with_analog_channels_is_refused(
    tmp_path: Path, tracks: MarkerTracks, backend: str
) -> None:
    raw = _analog_c3d(tmp_path / "whole.c3d", tracks)
    assert read_c3d(tmp_path / "whole.c3d", backend=backend).n_frames == tracks.n_frames
    for share in (0.95, 0.8, 0.7):
        cut = tmp_path / f"cut{share}.c3d"
        cut.write_bytes(raw[: int(len(raw) * share)])
        with pytest.raises(FileFormatError, match="truncated C3D file") as err:
            read_c3d(cut, backend=backend)
        message = str(err.value)
        assert f"announces {tracks.n_frames} frames of 3 points and 24 analog values" in message
        assert "complete frames" in message and str(cut) in message


def test_a_cut_integer_c3d_with_analog_channels_is_refused(tmp_path: Path) -> None:
    """Integer data (a positive POINT:SCALE): 2 bytes a value (the pure-Python reader; 6
    channels at 4 samples per frame)."""
    import c3d

    writer = c3d.Writer(point_rate=500.0, analog_rate=2000.0, point_scale=0.1)
    rng = np.random.default_rng(1)
    for _ in range(50):
        points = np.zeros((3, 5), dtype=np.float32)
        points[:, :3] = rng.uniform(-300, 300, (3, 3))
        writer.add_frames([(points, rng.uniform(-1, 1, (6, 4)).astype(np.float32))])
    writer.set_point_labels(["M1", "M2", "M3"])
    writer.set_analog_labels([f"A{i}" for i in range(6)])
    with (tmp_path / "int.c3d").open("wb") as fh:
        writer.write(fh)
    raw = (tmp_path / "int.c3d").read_bytes()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the c3d package's own notes
        assert read_c3d(tmp_path / "int.c3d", backend="c3d").n_frames == 50
        for share in (0.8, 0.7):
            cut = tmp_path / f"int{share}.c3d"
            cut.write_bytes(raw[: int(len(raw) * share)])
            with pytest.raises(FileFormatError, match="50 frames of 3 points and 24 analog"):
                read_c3d(cut, backend="c3d")


@pytest.mark.parametrize("backend", ["auto", "c3d"])
def test_a_c3d_cut_before_its_data_is_truncated(
    tmp_path: Path, tracks: MarkerTracks, backend: str
) -> None:
    path = S.write_c3d(tracks, tmp_path / "t.c3d")
    raw = path.read_bytes()
    start = (raw[16] + 256 * raw[17] - 1) * 512  # header word 9: the data's first block
    cut = tmp_path / "head.c3d"
    cut.write_bytes(raw[:start])
    with pytest.raises(FileFormatError, match="truncated C3D file") as err:
        read_c3d(cut, backend=backend)
    assert "it ends before its data section" in str(err.value)
    assert "no 3D point data" not in str(err.value)


def test_a_label_used_twice_names_the_c3d_parameter(tmp_path: Path, tracks: MarkerTracks) -> None:
    labels = list(tracks.labels)
    labels[-1] = labels[0]
    _analog_c3d(tmp_path / "dup.c3d", tracks, labels)
    with pytest.raises(FileFormatError, match=r"dup\.c3d: the POINT:LABELS parameter names") as err:
        read_c3d(tmp_path / "dup.c3d")
    n = len(labels)
    assert f"{labels[0]!r} 2 times (point 1, point {n})" in str(err.value)
