"""The marker cluster of the rod and its pose in every frame (the first steps of
:func:`~impactlab.experiment.kinematics.measure_impact`)."""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab.experiment.errors import MarkerError, RigidityError, TooFewFramesError
from impactlab.experiment.kinematics.marker_scale import check_marker_spread, free_fall_units_hint
from impactlab.experiment.markers import MarkerTracks
from impactlab.experiment.rigid import (
    MarkerGeometry,
    check_rigidity,
    fit_poses,
    never_seen,
    reference_cluster,
)

__all__ = ["marker_poses"]


def _cluster(
    tracks: MarkerTracks, geometry: MarkerGeometry | None, src: str
) -> tuple[MarkerTracks, np.ndarray]:
    """(the tracks of the geometry's markers, the reference cluster in the body frame)."""
    if geometry is None:
        return tracks, reference_cluster(tracks)
    if geometry.labels is not None:
        missing = [lab for lab in geometry.labels if lab not in tracks.labels]
        if missing:
            raise MarkerError(
                f"{src}: the marker geometry names markers {missing} that the "
                f"file does not have (it has {list(tracks.labels)})"
            )
        tracks = tracks.select(list(geometry.labels))
    elif geometry.markers.shape[0] != tracks.n_markers:
        raise MarkerError(
            f"{src}: the marker geometry has {geometry.markers.shape[0]} "
            f"markers {list(geometry.labels or [])} but the file has "
            f"{tracks.n_markers} {list(tracks.labels)}"
        )
    return tracks, np.asarray(geometry.markers, dtype=np.float64)


def _check_geometry(
    tracks: MarkerTracks, reference: np.ndarray, tolerance: float, src: str
) -> None:
    """The given geometry must match the measured cluster shape."""
    if not np.all(tracks.valid, axis=1).any():
        raise MarkerError(
            f"{src}: the marker geometry cannot be checked against the data: no frame shows "
            f"all {tracks.n_markers} markers{never_seen(tracks)}; leave a marker that is never "
            "seen out of the geometry (its labels)"
        )
    meas = reference_cluster(tracks)
    d_meas = np.linalg.norm(meas[:, None] - meas[None], axis=2)
    d_geo = np.linalg.norm(reference[:, None] - reference[None], axis=2)
    mis = float(np.max(np.abs(d_meas - d_geo)))
    if mis > max(2.0 * tolerance, 2e-3):
        raise MarkerError(
            f"{src}: the given marker geometry does not match the markers: "
            f"inter-marker distances differ by up to {mis * 1e3:.2f} mm "
            "(wrong labels, order or units?)"
        )


def marker_poses(
    tracks: MarkerTracks,
    geometry: MarkerGeometry | None,
    rigidity_tolerance: float,
    rigidity_window: int,
    min_fit_frames: int,
    src: str,
    *,
    rod_length: float,
    upv: np.ndarray,
    g: float,
) -> tuple[Any, ...]:
    """(reference cluster, rigidity report, poses, frames with a pose). Coordinates in a wrong
    length unit (markers farther apart than the rod is long, or a rigidity failure with a fall
    far from ``g`` [m/s^2]) are named as such before any loose marker."""
    check_marker_spread(tracks, rod_length, src)
    tracks, reference = _cluster(tracks, geometry, src)
    try:
        rigidity = check_rigidity(tracks, tolerance=rigidity_tolerance, window=rigidity_window)
    except RigidityError as exc:
        hint = free_fall_units_hint(tracks, upv, g)
        if not hint:
            raise
        raise RigidityError(f"{exc}{hint}") from None
    if geometry is not None:
        _check_geometry(tracks, reference, rigidity_tolerance, src)
    poses = fit_poses(tracks, reference)
    ok = np.flatnonzero(poses.ok)
    if ok.size < 2 * min_fit_frames + 1:
        raise TooFewFramesError(
            f"{src}: only {ok.size} frames with a usable pose (3 or more "
            f"markers seen); need at least {2 * min_fit_frames + 1}"
        )
    return reference, rigidity, poses, ok
