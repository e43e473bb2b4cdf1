"""Kabsch fit, poses with occlusions, reference cluster, rigidity check, marker geometry."""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.spatial.transform import Rotation

from impactlab.experiment import (
    MarkerError,
    MarkerGeometry,
    MarkerTracks,
    RigidityError,
    check_rigidity,
    fit_poses,
    kabsch,
    reference_cluster,
)

REF = np.array([[0.0, 0.0, 0.0], [0.1, 0.0, 0.01], [0.05, 0.04, -0.02], [-0.03, 0.02, 0.05]])


@settings(max_examples=25, deadline=None)
@given(st.integers(0, 2**31 - 1))
def test_kabsch_recovers_rotation_and_translation(seed: int) -> None:
    rng = np.random.default_rng(seed)
    R = Rotation.random(random_state=seed).as_matrix()
    t = rng.uniform(-1, 1, 3)
    pts = REF @ R.T + t
    R2, t2, rms = kabsch(REF, pts)
    np.testing.assert_allclose(R2, R, atol=1e-10)
    np.testing.assert_allclose(t2, t, atol=1e-10)
    assert rms < 1e-12
    assert np.linalg.det(R2) == pytest.approx(1.0)


def test_kabsch_never_returns_a_reflection() -> None:
    mirrored = REF * np.array([1.0, 1.0, -1.0])
    R, _, rms = kabsch(REF, mirrored)
    assert np.linalg.det(R) == pytest.approx(1.0)
    assert rms > 1e-3  # a mirror image cannot be fitted by a rotation


def _moving(n: int = 60, noise: float = 0.0, seed: int = 0) -> tuple[MarkerTracks, np.ndarray]:
    rng = np.random.default_rng(seed)
    rots = Rotation.from_rotvec(np.outer(np.linspace(0, 1.2, n), [0.2, 0.3, 0.9])).as_matrix()
    trans = np.outer(np.linspace(0, 1, n), [0.3, -0.1, 0.2])
    pos = np.einsum("nij,mj->nmi", rots, REF) + trans[:, None, :]
    pos = pos + noise * rng.standard_normal(pos.shape)
    return MarkerTracks(np.arange(n) / 500.0, pos, ("A", "B", "C", "D")), rots


def test_poses_with_occlusions() -> None:
    tr, rots = _moving()
    pos = np.array(tr.positions)
    pos[5, 1] = np.nan  # one of four missing: still a pose
    pos[9, 1:3] = np.nan  # two of four missing: no pose
    tr = MarkerTracks(tr.time, pos, tr.labels)
    poses = fit_poses(tr, REF)
    assert poses.ok[5] and not poses.ok[9]
    np.testing.assert_allclose(poses.rotation[5], rots[5], atol=1e-10)
    assert np.all(np.isnan(poses.apply(np.zeros(3))[9]))


def test_reference_cluster_recovers_shape() -> None:
    tr, _ = _moving(noise=1e-4, seed=3)
    ref = reference_cluster(tr)
    d_true = np.linalg.norm(REF[:, None] - REF[None], axis=2)
    d = np.linalg.norm(ref[:, None] - ref[None], axis=2)
    np.testing.assert_allclose(d, d_true, atol=1e-4)


def test_rigidity_check_passes_for_noise_and_catches_a_loose_marker() -> None:
    tr, _ = _moving(n=200, noise=0.15e-3, seed=1)
    rep = check_rigidity(tr)
    assert rep.worst_drift < 1e-3
    pos = np.array(tr.positions)
    pos[120:, 2] += np.array([0.003, 0.0, 0.0])  # marker C slips by 3 mm
    loose = MarkerTracks(tr.time, pos, tr.labels, "loose.c3d")
    with pytest.raises(RigidityError, match=r"loose\.c3d.*C.*not rigidly attached"):
        check_rigidity(loose)


def test_marker_geometry() -> None:
    g = MarkerGeometry.from_mapping(
        {"units": "mm", "M1": [-30, 18, 0], "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    )
    np.testing.assert_allclose(g.markers[0], [-0.03, 0.018, 0.0])
    assert g.labels == ("M1", "M2", "M3")
    with pytest.raises(MarkerError, match="one line"):
        MarkerGeometry(np.array([[0, 0, 0], [0.1, 0, 0], [0.2, 0, 0.0]]))
    with pytest.raises(ValueError, match="at least 3"):
        MarkerGeometry.from_mapping({"M1": [0, 0, 0], "M2": [1, 0, 0]})


@pytest.mark.parametrize(
    "value", ["a", [1.0, 2.0], [1.0, "b", 3.0], [1.0, 2.0, float("nan")], [True, 0, 0]]
)
def test_marker_geometry_names_a_bad_entry(value: object) -> None:
    table = {"units": "mm", "M1": value, "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    with pytest.raises(ValueError, match=r"^markers\.M1 must be \[x, y, z\], three numbers"):
        MarkerGeometry.from_mapping(table)


def test_marker_geometry_says_in_which_unit_it_was_read() -> None:
    rows = {"M1": [-30, 18, 0], "M2": [-90, 0, 22], "M3": [-130, -20, 4]}
    assert MarkerGeometry.from_mapping(rows).units_note == "m (no units key)"
    assert MarkerGeometry.from_mapping({"units": "mm", **rows}).units_note == "mm"
    assert MarkerGeometry.from_mapping(rows, units="cm").units_note == "cm (units=)"


def test_reference_cluster_ignores_wrong_frames() -> None:
    """A glitch of 50 mm and garbage coordinates in some frames leave the shape unchanged."""
    tracks, _ = _moving(n=60, noise=1e-5, seed=2)
    pos = tracks.positions.copy()
    pos[5, 1, 0] += 0.05
    pos[20, 2] = 1e27
    bad = MarkerTracks(tracks.time, pos, tracks.labels)
    shape = reference_cluster(bad)
    assert kabsch(REF - REF.mean(axis=0), shape)[2] < 1e-4
