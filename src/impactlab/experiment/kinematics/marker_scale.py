"""Signs of marker coordinates read in the wrong length unit (a file in mm read as m, ...).

A unit mistake scales every coordinate: the markers then lie farther apart than the rod is long,
their noise looks like loose markers (the rigidity check fails) and the rod falls with an
acceleration far from g. These checks name the likely unit mistake first, so that the user
is not sent looking for a loose marker.
"""

from __future__ import annotations

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.markers import MarkerTracks

__all__ = ["check_marker_spread", "free_fall_units_hint"]

#: Markers on the rod lie closer together than this many rod lengths.
MAX_SPREAD_IN_ROD_LENGTHS = 2.0

#: Frames before the impact (the largest upward jump of a marker's velocity) used for its
#: free-fall acceleration.
FALL_FRAMES = 20

#: Frames next to the impact left out (the contact).
FALL_GUARD = 3


def _units_read(tracks: MarkerTracks) -> str:
    unit = tracks.meta.get("units")
    return f" (read as {unit!r})" if unit else ""


def check_marker_spread(tracks: MarkerTracks, rod_length: float, src: str) -> None:
    """MarkerError naming the length unit when two markers lie, at their median distance, more
    than :data:`MAX_SPREAD_IN_ROD_LENGTHS` rod lengths (``rod_length`` [m]) apart."""
    worst, pair = 0.0, ("", "")
    valid = tracks.valid
    for i in range(tracks.n_markers):
        for j in range(i + 1, tracks.n_markers):
            both = valid[:, i] & valid[:, j]
            if not both.any():
                continue
            d = np.linalg.norm(tracks.positions[both, i] - tracks.positions[both, j], axis=1)
            if float(np.median(d)) > worst:
                worst, pair = float(np.median(d)), (tracks.labels[i], tracks.labels[j])
    if worst > MAX_SPREAD_IN_ROD_LENGTHS * rod_length:
        raise MarkerError(
            f"{src}: markers {pair[0]} and {pair[1]} are {worst:.4g} m apart, but the rod is "
            f"{rod_length:.4g} m long: the marker coordinates are likely in another length unit "
            f"than the one used{_units_read(tracks)}; pass the file's unit (marker_units=, "
            "--marker-units, or the file's units header)"
        )


def _fall_acceleration(tracks: MarkerTracks, upv: np.ndarray) -> float | None:
    """The upward acceleration [m/s^2] of the best-seen marker over the frames before the
    largest upward jump of its velocity (the free fall before the impact); None when too few
    frames or too noisy."""
    k = int(np.argmax(tracks.valid.sum(axis=0)))
    seen = tracks.valid[:, k]
    t = tracks.time[seen]
    height = tracks.positions[seen, k] @ upv
    if t.size < FALL_FRAMES:
        return None
    velocity = np.diff(height) / np.diff(t)
    last = int(np.argmax(np.diff(velocity))) - FALL_GUARD
    first = max(0, last - FALL_FRAMES)
    if last - first < 8:
        return None
    tau = t[first:last] - t[last]
    A = np.column_stack([np.ones_like(tau), tau, 0.5 * tau * tau])
    coef, *_ = np.linalg.lstsq(A, height[first:last], rcond=None)
    resid = height[first:last] - A @ coef
    s2 = float(resid @ resid) / max(tau.size - 3, 1)
    sig = float(np.sqrt(np.linalg.inv(A.T @ A)[2, 2] * s2))
    accel = float(coef[2])
    return accel if sig < 0.3 * abs(accel) else None


def free_fall_units_hint(tracks: MarkerTracks, upv: np.ndarray, g: float) -> str:
    """A sentence on the length unit when the markers fall with an acceleration more than twice
    or less than half ``g`` [m/s^2] (``upv``: the lab's upward unit vector), else ""."""
    accel = _fall_acceleration(tracks, upv)
    if accel is None or 0.5 * g < -accel < 2.0 * g:
        return ""
    return (
        f"; but the markers fall with {-accel:.3g} m/s^2, not g = {g:.4g} m/s^2: the marker "
        f"coordinates are likely in another length unit than the one used{_units_read(tracks)} "
        "(a scaled noise looks like a drift); pass the file's unit (marker_units=, "
        "--marker-units, or the file's units header)"
    )
