"""Markers in the file that are not on the rod (a ghost reflection, markers on the table), and
gaps written as (0, 0, 0) in C3D files."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerError, MarkerGeometry, measure_impact, read_c3d
from impactlab.experiment.errors import RigidityError
from impactlab.experiment.markers import MarkerTracks


def _drop() -> tuple[MarkerTracks, MarkerGeometry]:
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(45.0), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=5)
    return tracks, MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])


def _with(tracks: MarkerTracks, extra: dict[str, np.ndarray]) -> MarkerTracks:
    """``tracks`` with the markers ``extra`` (label -> (n, 3) positions [m], NaN: not seen)."""
    pos = np.concatenate([tracks.positions, *(v[:, None, :] for v in extra.values())], axis=1)
    return MarkerTracks(
        tracks.time, pos, (*tracks.labels, *extra), tracks.source, dict(tracks.meta)
    )


def _ghost(tracks: MarkerTracks, distance: float) -> np.ndarray:
    """A reflection seen in 3 frames, ``distance`` [m] from the first marker."""
    g = np.full((tracks.n_frames, 3), np.nan)
    g[40:43] = np.nanmedian(tracks.positions[:, 0], axis=0) + np.array([distance, 0.0, 0.0])
    return g


def _table(tracks: MarkerTracks, offset: float) -> np.ndarray:
    """A static marker on the table, ``offset`` [m] from the rod's markers."""
    where = np.nanmedian(tracks.positions[:, 2], axis=0) + np.array([offset, 0.0, -0.05])
    return np.tile(where, (tracks.n_frames, 1))


def test_markers_the_geometry_does_not_name_are_left_out_and_named() -> None:
    tracks, geo = _drop()
    plain = measure_impact(tracks, PAPER_ROD, geometry=geo)
    extra = _with(tracks, {"*7": _ghost(tracks, 1.2), "Table:T1": _table(tracks, 0.15)})
    k = measure_impact(extra, PAPER_ROD, geometry=geo)
    assert k.e.value == plain.e.value and k.mu.value == plain.mu.value
    named = [w for w in k.warnings if "not in the marker geometry" in w]
    assert named == [
        "markers *7, Table:T1 in the file are not in the marker geometry and left out "
        "(the rod's markers: M1, M2, M3)"
    ]


def test_without_a_geometry_a_far_marker_is_named_not_a_length_unit() -> None:
    tracks, _ = _drop()
    with pytest.raises(MarkerError) as info:
        measure_impact(_with(tracks, {"*7": _ghost(tracks, 1.2)}), PAPER_ROD)
    msg = str(info.value)
    assert "marker *7 lies more than 0.6096 m (2 rod lengths) from the others" in msg
    assert "length unit" not in msg
    assert "geometry file listing the rod's markers (M1, M2, M3" in msg and "--geometry" in msg


def test_without_a_geometry_a_static_marker_nearby_is_named() -> None:
    tracks, _ = _drop()
    with pytest.raises(RigidityError) as info:
        measure_impact(_with(tracks, {"Table:T1": _table(tracks, 0.15)}), PAPER_ROD)
    msg = str(info.value)
    assert "Table:T1 moves against the other markers (M1, M2, M3), which move as one body" in msg
    assert "--geometry markers.toml" in msg


def test_coordinates_in_a_wrong_unit_are_still_named_as_such() -> None:
    tracks, _ = _drop()
    scaled = MarkerTracks(tracks.time, tracks.positions * 10.0, tracks.labels, "x", {"units": "m"})
    with pytest.raises(MarkerError, match=r"likely in another length unit"):
        measure_impact(scaled, PAPER_ROD)


def _write_zero_gaps(tracks: MarkerTracks, path: Path) -> Path:
    """``tracks`` as a C3D file (mm) whose gaps are written as (0, 0, 0) with a valid residual,
    as BTK and several exporters write them."""
    import ezc3d

    c = ezc3d.c3d()
    c["parameters"]["POINT"]["RATE"]["value"] = [float(round(tracks.rate, 6))]
    c["parameters"]["POINT"]["LABELS"]["value"] = tuple(tracks.labels)
    c.add_parameter("POINT", "UNITS", "mm")
    pts = np.ones((4, tracks.n_markers, tracks.n_frames))
    xyz = np.transpose(tracks.positions * 1e3, (2, 1, 0))
    pts[:3] = np.where(np.isfinite(xyz), xyz, 0.0)
    c["data"]["points"] = pts
    c["data"]["meta_points"]["residuals"] = np.full((1, tracks.n_markers, tracks.n_frames), 0.8)
    c.write(str(path))
    return path


@pytest.mark.parametrize("backend", ["ezc3d", "c3d"])
def test_c3d_points_at_exactly_zero_are_gaps(tmp_path: Path, backend: str) -> None:
    tracks, geo = _drop()
    pos = np.array(tracks.positions)
    pos[46:54, 0] = np.nan  # M1 lost for 8 frames around the impact
    gappy = MarkerTracks(tracks.time, pos, tracks.labels)
    back = read_c3d(_write_zero_gaps(gappy, tmp_path / "zeros.c3d"), backend=backend)
    assert np.array_equal(back.valid, gappy.valid)
    k = measure_impact(back, PAPER_ROD, geometry=geo)
    assert abs(k.e.value - 0.49) < 4 * k.e.sigma + 2e-3
