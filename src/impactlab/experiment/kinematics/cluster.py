"""The marker cluster of the rod and its pose in every frame (the first steps of
:func:`~impactlab.experiment.kinematics.measure_impact`).

With a marker geometry that names its markers only those are used; the file's other markers (a
ghost reflection, a marker on the table) are left out, and a warning names them. Without one,
every marker is taken as the rod's, and one that lies far from or moves against the others is
named in the error, with the way to leave it out.

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
from impactlab.experiment.kinematics.marker_scale import (
    check_marker_spread,
    free_fall_units_hint,
    not_on_rod_hint,
    odd_markers,
)
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


def _geometry_markers(
    tracks: MarkerTracks, geometry: MarkerGeometry | None, src: str, warnings: list[str]
) -> MarkerTracks:
    """The tracks of the markers the geometry names (all without a geometry or its labels),
    with a warning in ``warnings`` naming the file's other markers."""
    if geometry is None:
        return tracks
    if geometry.labels is None:
        if geometry.markers.shape[0] != tracks.n_markers:
            raise MarkerError(
                f"{src}: the marker geometry has {geometry.markers.shape[0]} "
                f"markers but the file has {tracks.n_markers} {list(tracks.labels)}; name "
                "each marker of the geometry by its label (a [markers] table: the file's other "
                "markers are then left out)"
            )
        return tracks
    missing = [lab for lab in geometry.labels if lab not in tracks.labels]
    if missing:
        prefixed = [lab for lab in tracks.labels if lab.rpartition(":")[2] in missing]
        hint = (
            f"; the file's labels carry a prefix (a subject name): write them as in the file "
            f"({', '.join(repr(lab) for lab in prefixed)}) in the geometry"
            if prefixed
            else ""
        )
        raise MarkerError(
            f"{src}: the marker geometry names markers {missing} that the "
            f"file does not have (it has {list(tracks.labels)}){hint}"
        )
    others = [lab for lab in tracks.labels if lab not in geometry.labels]
    if others:
        warnings.append(
            f"marker{'s' if len(others) > 1 else ''} {', '.join(others)} in the file "
            f"{'are' if len(others) > 1 else 'is'} not in the marker geometry and left out "
            f"(the rod's markers: {', '.join(geometry.labels)})"
        )
    return tracks.select(list(geometry.labels))


def _loose_hint(tracks: MarkerTracks, tolerance: float, window: int) -> str:
    """Without a geometry: the markers that move against three or more others that move as
    one body, and how to leave them out ("" when there are none)."""
    report = check_rigidity(tracks, tolerance=tolerance, window=window, raise_error=False)
    index = {lab: i for i, lab in enumerate(tracks.labels)}
    drift = np.zeros((tracks.n_markers, tracks.n_markers))
    for (a, b), (_med, d) in report.pairs.items():
        drift[index[a], index[b]] = drift[index[b], index[a]] = d
    odd = odd_markers(tracks.labels, drift > tolerance, drift)
    if not odd:
        return ""
    rod = [lab for lab in tracks.labels if lab not in odd]
    return (
        f"; {', '.join(odd)} move{'' if len(odd) > 1 else 's'} against the other markers "
        f"({', '.join(rod)}), which move as one body{not_on_rod_hint(odd, tracks.labels)}"
    )


def _cluster(
    tracks: MarkerTracks, geometry: MarkerGeometry | None
) -> tuple[MarkerTracks, np.ndarray]:
    """(the tracks of the geometry's markers, from :func:`_geometry_markers`; the reference
    cluster in the body frame)."""
    if geometry is None:
        return tracks, reference_cluster(tracks)
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
    out (module docstring) with a warning in ``warnings``, and so are markers the geometry
    does not name."""
    tracks = _geometry_markers(tracks, geometry, src, warnings)
    check_marker_spread(tracks, rod_length, src, all_on_rod=geometry is not None, upv=upv, g=g)
    tracks, reference = _cluster(tracks, geometry)
    span = ABSURD_SPANS * max(rod_length, float(np.ptp(reference, axis=0).max()))
    tracks, absurd = _mask_absurd(tracks, span)
    try:
        rigidity = check_rigidity(tracks, tolerance=rigidity_tolerance, window=rigidity_window)
    except RigidityError as exc:
        hint = free_fall_units_hint(tracks, upv, g)
        if not hint and geometry is None:
            hint = _loose_hint(tracks, rigidity_tolerance, rigidity_window)
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
