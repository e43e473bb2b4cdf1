"""The marker cluster of the rod and its pose in every frame (the first steps of
:func:`~impactlab.experiment.kinematics.measure_impact`).

Wrong samples are left out before any fit: a coordinate absurdly far from its marker's track
(garbage bytes) is masked, and a frame whose pose leaves a marker far off the rigid cluster
(Kabsch residual above ``OUTLIER_TOLERANCES`` times the rigidity tolerance: a glitch, labels
swapped for a few frames) gets no pose; a warning names those frames.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import numpy as np

from impactlab.experiment.errors import MarkerError, RigidityError, TooFewFramesError
from impactlab.experiment.kinematics.marker_scale import check_marker_spread, free_fall_units_hint
from impactlab.experiment.kinematics.mirror import check_not_mirrored_shape
from impactlab.experiment.markers import MarkerTracks
from impactlab.experiment.rigid import (
    MarkerGeometry,
    Poses,
    check_rigidity,
    fit_poses,
    never_seen,
    reference_cluster,
)

__all__ = ["OUTLIER_TOLERANCES", "marker_poses"]

#: A pose whose Kabsch residual (rms over the markers) exceeds this many rigidity tolerances is
#: left out as a wrong sample.
OUTLIER_TOLERANCES = 2.0
#: A coordinate farther than this many rod lengths (or cluster sizes) from its marker's median
#: position is garbage and masked.
ABSURD_SPANS = 1.0e3
#: Frames and times named in the warning about left-out frames.
_NAMED = 5


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
    tracks: MarkerTracks,
    geometry: MarkerGeometry,
    reference: np.ndarray,
    tolerance: float,
    src: str,
) -> None:
    """The given geometry must match the measured cluster shape, and not as its mirror image."""
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
        read = f"; the geometry was read in {geometry.units_note}" if geometry.units_note else ""
        raise MarkerError(
            f"{src}: the given marker geometry does not match the markers: "
            f"inter-marker distances differ by up to {mis * 1e3:.2f} mm "
            f"(wrong labels, order or units?){read}"
        )
    check_not_mirrored_shape(meas, reference, tolerance, src)


def _mask_absurd(tracks: MarkerTracks, span: float) -> tuple[MarkerTracks, np.ndarray]:
    """(the tracks with coordinates farther than ``span`` [m] from their marker's median
    position masked, (n,) True for the frames that had such a sample)."""
    pos = np.array(tracks.positions)
    seen = tracks.valid.any(axis=0)
    centre = np.zeros((tracks.n_markers, 3))
    centre[seen] = np.nanmedian(pos[:, seen], axis=0)  # a marker never seen has no samples
    with np.errstate(over="ignore", invalid="ignore"):
        dist = np.linalg.norm(pos - centre, axis=2)
    bad = tracks.valid & ~(dist <= span)
    if not bad.any():
        return tracks, np.zeros(tracks.n_frames, dtype=bool)
    pos[bad] = np.nan
    masked = MarkerTracks(tracks.time, pos, tracks.labels, tracks.source, dict(tracks.meta))
    return masked, bad.any(axis=1)


def _mask_outliers(
    poses: Poses, absurd: np.ndarray, tolerance: float, warnings: list[str]
) -> Poses:
    """The poses with those of residual above ``OUTLIER_TOLERANCES`` x ``tolerance`` [m] left
    out (and a warning naming them with the frames of garbage coordinates ``absurd``)."""
    limit = OUTLIER_TOLERANCES * tolerance
    with np.errstate(invalid="ignore"):
        wrong = poses.ok & ~(poses.rms <= limit)
    out = absurd | wrong
    if not out.any():
        return poses
    ok = poses.ok & ~wrong
    frames = np.flatnonzero(out)
    named = ", ".join(f"{k} (t = {poses.time[k]:.4f} s)" for k in frames[:_NAMED])
    more = f" and {frames.size - _NAMED} more" if frames.size > _NAMED else ""
    worst = float(np.max(poses.rms[wrong])) if wrong.any() else np.inf
    size = f"up to {worst * 1e3:.3g} mm" if np.isfinite(worst) else "absurd coordinates"
    warnings.append(
        f"{frames.size} frame(s) with a marker far off the rigid cluster ({size}; limit "
        f"{limit * 1e3:.3g} mm, {OUTLIER_TOLERANCES:g} x rigidity_tolerance) left out as wrong "
        f"samples: frame {named}{more}"
    )
    return dataclasses.replace(poses, ok=ok)


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
    warnings: list[str],
) -> tuple[Any, ...]:
    """(reference cluster, rigidity report, poses, frames with a pose). Coordinates in a wrong
    length unit (markers farther apart than the rod is long, or a rigidity failure with a fall
    far from ``g`` [m/s^2]) are named as such before any loose marker; wrong samples are left
    out (module docstring) with a warning in ``warnings``."""
    check_marker_spread(tracks, rod_length, src)
    tracks, reference = _cluster(tracks, geometry, src)
    span = ABSURD_SPANS * max(rod_length, float(np.ptp(reference, axis=0).max()))
    tracks, absurd = _mask_absurd(tracks, span)
    try:
        rigidity = check_rigidity(tracks, tolerance=rigidity_tolerance, window=rigidity_window)
    except RigidityError as exc:
        hint = free_fall_units_hint(tracks, upv, g)
        if not hint:
            raise
        raise RigidityError(f"{exc}{hint}") from None
    if geometry is not None:
        _check_geometry(tracks, geometry, reference, rigidity_tolerance, src)
    poses = _mask_outliers(fit_poses(tracks, reference), absurd, rigidity_tolerance, warnings)
    ok = np.flatnonzero(poses.ok)
    if ok.size < 2 * min_fit_frames + 1:
        raise TooFewFramesError(
            f"{src}: only {ok.size} frames with a usable pose (3 or more "
            f"markers seen); need at least {2 * min_fit_frames + 1}"
        )
    return reference, rigidity, poses, ok
