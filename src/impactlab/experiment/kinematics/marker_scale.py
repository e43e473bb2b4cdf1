"""Signs of marker coordinates read in the wrong length unit (a file in mm read as m, ...), and
of markers in the file that are not on the rod.

A unit mistake scales every coordinate: the markers then lie farther apart than the rod is long,
their noise looks like loose markers (the rigidity check fails) and the rod falls with an
acceleration far from g. These checks name the likely unit mistake first, so that the user
is not sent looking for a loose marker. A marker that is not on the rod (a ghost reflection, a
marker on the table) lies far from, or moves against, markers that do move as one body; without
a marker geometry it is named, with the way to leave it out.
"""

from __future__ import annotations

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.kinematics.frame import G0
from impactlab.experiment.markers import MarkerTracks

__all__ = ["check_marker_spread", "free_fall_units_hint", "not_on_rod_hint", "odd_markers"]

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


def odd_markers(labels: tuple[str, ...], bad: np.ndarray, size: np.ndarray) -> list[str]:
    """The markers to leave out so that no pair of those left is ``bad`` ((m, m) symmetric,
    True for a pair that cannot be on one rigid body), taking first the marker in the most bad
    pairs (ties: the largest summed ``size`` of its bad pairs); empty when fewer than 3 markers
    would be left (no body to tell them from)."""
    bad = np.array(bad, dtype=bool)
    keep = list(range(len(labels)))
    out: list[str] = []
    while True:
        sub = bad[np.ix_(keep, keep)]
        if not sub.any():
            break
        score = np.where(sub, np.asarray(size)[np.ix_(keep, keep)], 0.0).sum(axis=1)
        worst = max(range(len(keep)), key=lambda i: (int(sub[i].sum()), float(score[i])))
        out.append(labels[keep.pop(worst)])
    return out if len(keep) >= 3 else []


def not_on_rod_hint(odd: list[str], labels: tuple[str, ...]) -> str:
    """How to leave the markers ``odd`` out of the analysis (the others of ``labels`` being
    the rod's)."""
    rod = [lab for lab in labels if lab not in odd]
    them = "it is" if len(odd) == 1 else "they are"
    return (
        f"; without a marker geometry every marker in the file is taken as the rod's: if "
        f"{them} not on the rod (a ghost reflection, a marker on the table), give a geometry "
        f"file listing the rod's markers ({', '.join(rod)}: a [markers] table with each one's "
        "position on the rod, docs/experiment.md 'Marker geometry'; impactlab analyze "
        "--geometry markers.toml, geometry= in Python): markers it does not list are left out"
    )


def check_marker_spread(
    tracks: MarkerTracks,
    rod_length: float,
    src: str,
    *,
    all_on_rod: bool = True,
    upv: np.ndarray | None = None,
    g: float = G0,
) -> None:
    """MarkerError when two markers lie, at their median distance, more than
    :data:`MAX_SPREAD_IN_ROD_LENGTHS` rod lengths (``rod_length`` [m]) apart: naming the length
    unit, or, unless ``all_on_rod`` (the markers of a geometry), the markers far from three or
    more others that lie close together and fall with about ``g`` [m/s^2] along ``upv`` (not
    on the rod)."""
    m = tracks.n_markers
    dist = np.zeros((m, m))
    valid = tracks.valid
    for i in range(m):
        for j in range(i + 1, m):
            both = valid[:, i] & valid[:, j]
            if not both.any():
                continue
            d = np.linalg.norm(tracks.positions[both, i] - tracks.positions[both, j], axis=1)
            dist[i, j] = dist[j, i] = float(np.median(d))
    limit = MAX_SPREAD_IN_ROD_LENGTHS * rod_length
    if not np.any(dist > limit):
        return
    a, b = (int(k) for k in np.unravel_index(int(np.argmax(dist)), dist.shape))
    worst, pair = float(dist[a, b]), (tracks.labels[a], tracks.labels[b])
    odd = [] if all_on_rod else odd_markers(tracks.labels, dist > limit, dist)
    rod = tracks.select([lab for lab in tracks.labels if lab not in odd]) if odd else None
    if rod is not None and not (upv is not None and free_fall_units_hint(rod, upv, g)):
        far = ", ".join(odd)
        raise MarkerError(
            f"{src}: marker{'s' if len(odd) > 1 else ''} {far} lie{'' if len(odd) > 1 else 's'} "
            f"more than {limit:.4g} m ({MAX_SPREAD_IN_ROD_LENGTHS:g} rod lengths) from the "
            f"others (markers {pair[0]} and {pair[1]} are {worst:.4g} m apart), which lie "
            f"close together{not_on_rod_hint(odd, tracks.labels)}"
        )
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
