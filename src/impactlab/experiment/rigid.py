"""Rigid-body fit of a marker cluster (Kabsch/SVD) and the rigidity check.

Per frame, the rotation R and translation t that map the reference cluster onto the seen markers
in the least-squares sense, ``x_j ~ R r_j + t``, come from the SVD of the cross-covariance of the
centred point sets (W. Kabsch, Acta Cryst. A32 (1976) 922, doi:10.1107/S0567739476001873), with
the sign correction that excludes reflections. Three non-collinear markers are needed per frame;
frames with fewer valid markers get no pose (masked).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.experiment.checks import check_instance
from impactlab.experiment.errors import MarkerError, RigidityError
from impactlab.experiment.markers import MarkerTracks, length_factor

__all__ = [
    "MarkerGeometry",
    "Poses",
    "RigidityReport",
    "check_rigidity",
    "fit_poses",
    "kabsch",
    "reference_cluster",
]


def kabsch(reference: np.ndarray, points: np.ndarray) -> tuple[np.ndarray, np.ndarray, float]:
    """Least-squares rigid transform with ``points ~ R @ reference + t``.

    ``reference``, ``points``: (k, 3) arrays of corresponding, finite points (k >= 3, not all on a
    line). Returns (R (3, 3) proper rotation, t (3,), rms residual [same unit as the points]).
    """
    a = np.asarray(reference, dtype=np.float64)
    b = np.asarray(points, dtype=np.float64)
    if a.shape != b.shape or a.ndim != 2 or a.shape[1] != 3 or a.shape[0] < 3:
        raise ValueError(f"kabsch needs two (k, 3) arrays with k >= 3, got {a.shape}, {b.shape}")
    ca = a.mean(axis=0)
    cb = b.mean(axis=0)
    H = (a - ca).T @ (b - cb)
    U, _, Vt = np.linalg.svd(H)
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    D = np.diag([1.0, 1.0, d if d != 0 else 1.0])
    R = Vt.T @ D @ U.T
    t = cb - R @ ca
    res = b - (a @ R.T + t)
    return R, t, float(np.sqrt(np.mean(np.sum(res * res, axis=1))))


def _kabsch_batch(
    reference: np.ndarray, points: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vectorised Kabsch for (n, k, 3) point sets against one (k, 3) reference."""
    ca = reference.mean(axis=0)
    cb = points.mean(axis=1)  # (n, 3)
    A = reference - ca
    B = points - cb[:, None, :]
    with np.errstate(over="ignore", invalid="ignore"):
        H = np.einsum("ki,nkj->nij", A, B)
    absurd = ~np.all(np.isfinite(H), axis=(1, 2))  # coordinates too large to square
    H[absurd] = np.eye(3)
    U, _, Vt = np.linalg.svd(H)
    V = np.transpose(Vt, (0, 2, 1))
    UT = np.transpose(U, (0, 2, 1))
    d = np.sign(np.linalg.det(V @ UT))
    d[d == 0] = 1.0
    D = np.zeros((points.shape[0], 3, 3))
    D[:, 0, 0] = 1.0
    D[:, 1, 1] = 1.0
    D[:, 2, 2] = d
    R = V @ D @ UT
    t = cb - np.einsum("nij,j->ni", R, ca)
    fitted = np.einsum("nij,kj->nki", R, reference) + t[:, None, :]
    res = points - fitted
    with np.errstate(over="ignore", invalid="ignore"):
        rms = np.sqrt(np.mean(np.sum(res * res, axis=2), axis=1))
    rms[absurd | ~np.isfinite(rms)] = np.inf
    return R, t, rms


def _check_not_collinear(reference: np.ndarray, what: str) -> None:
    c = reference - reference.mean(axis=0)
    s = np.linalg.svd(c, compute_uv=False)
    if s[0] == 0.0 or s[1] < 1e-3 * s[0]:
        raise MarkerError(
            f"{what}: the markers lie (almost) on one line, so the rod's rotation "
            "about that line is undefined; three non-collinear markers are needed"
        )


@dataclass(frozen=True)
class Poses:
    """Per-frame rigid pose of the marker cluster: ``x = R @ r + t`` for a reference point r.

    rotation (n, 3, 3), translation (n, 3) [m], rms (n,) Kabsch residual [m], ok (n,) True where a
    pose could be fitted (>= 3 valid markers), reference (m, 3) [m], time (n,) [s].
    """

    time: np.ndarray
    rotation: np.ndarray
    translation: np.ndarray
    rms: np.ndarray
    ok: np.ndarray
    reference: np.ndarray

    def apply(self, body_point: np.ndarray) -> np.ndarray:
        """Lab positions (n, 3) of a point fixed in the reference frame (NaN where no pose)."""
        x = np.einsum("nij,j->ni", self.rotation, np.asarray(body_point, dtype=np.float64))
        x = x + self.translation
        x[~self.ok] = np.nan
        return x

    def direction(self, body_vector: np.ndarray) -> np.ndarray:
        """Lab directions (n, 3) of a vector fixed in the reference frame (NaN where no pose)."""
        x = np.einsum("nij,j->ni", self.rotation, np.asarray(body_vector, dtype=np.float64))
        x[~self.ok] = np.nan
        return x


def fit_poses(tracks: MarkerTracks, reference: np.ndarray) -> Poses:
    """Fit the pose of ``reference`` (m, 3) [m] to every frame of ``tracks`` (Kabsch)."""
    check_instance(tracks, MarkerTracks, "tracks", "read them with read_markers()")
    ref = np.asarray(reference, dtype=np.float64)
    if ref.shape != (tracks.n_markers, 3):
        raise ValueError(f"reference must have shape ({tracks.n_markers}, 3), got {ref.shape}")
    _check_not_collinear(ref, "reference cluster")
    n = tracks.n_frames
    R = np.full((n, 3, 3), np.nan)
    t = np.full((n, 3), np.nan)
    rms = np.full(n, np.nan)
    ok = np.zeros(n, dtype=bool)
    valid = tracks.valid
    full = np.all(valid, axis=1)
    if full.any():
        Rf, tf, rf = _kabsch_batch(ref, tracks.positions[full])
        R[full], t[full], rms[full] = Rf, tf, rf
        ok[full] = np.isfinite(rf)  # coordinates too large for a fit give no pose
    for k in np.flatnonzero(~full & (valid.sum(axis=1) >= 3)):
        sel = valid[k]
        sub = ref[sel]
        c = sub - sub.mean(axis=0)
        s = np.linalg.svd(c, compute_uv=False)
        if s[1] < 1e-3 * s[0]:
            continue  # the visible markers are collinear: no pose this frame
        Rk, tk, rk = _kabsch_batch(sub, tracks.positions[k, sel][None])
        R[k], t[k], rms[k] = Rk[0], tk[0], rk[0]
        ok[k] = bool(np.isfinite(rk[0]))
    R[~ok], t[~ok] = np.nan, np.nan
    return Poses(tracks.time, R, t, rms, ok, ref)


def never_seen(tracks: MarkerTracks) -> str:
    """`` (never seen: ['M3'])``: the markers invalid in every frame (``""`` for none)."""
    gone = [lab for j, lab in enumerate(tracks.labels) if not tracks.valid[:, j].any()]
    return f" (never seen: {gone})" if gone else ""


#: A frame whose Kabsch residual exceeds this many times the median residual of the record (and
#: ``OUTLIER_FLOOR`` of the cluster's size) is left out of the reference cluster.
OUTLIER_FACTOR = 5.0
OUTLIER_FLOOR = 1e-3


def _plausible_frames(pts: np.ndarray) -> np.ndarray:
    """(n,) True for the frames whose inter-marker distances all lie within 10 times the
    cluster's size of their medians over the record (others hold garbage coordinates)."""
    with np.errstate(over="ignore", invalid="ignore"):
        d = np.linalg.norm(pts[:, :, None, :] - pts[:, None, :, :], axis=3)
        med = np.median(d, axis=0)
        off = np.max(np.abs(d - med), axis=(1, 2))
    return np.isfinite(off) & (off <= 10.0 * max(float(med.max()), 1e-12))


def reference_cluster(
    tracks: MarkerTracks, *, iterations: int = 3, max_frames: int = 400
) -> np.ndarray:
    """The marker cluster's shape (m, 3) [m], centred on its centroid, as the Procrustes mean of
    the frames in which every marker is seen (generalised Procrustes analysis, a few passes).

    Robust to a few wrong samples (a marker glitch, labels swapped for some frames, garbage
    coordinates): the first estimate is the frame whose inter-marker distances lie nearest
    their medians, and frames whose residual exceeds ``OUTLIER_FACTOR`` times the median one
    are left out of the mean."""
    full = np.flatnonzero(np.all(tracks.valid, axis=1))
    if full.size == 0:
        raise MarkerError(
            f"{tracks.source or 'marker tracks'}: no frame shows all "
            f"{tracks.n_markers} markers{never_seen(tracks)}, so the marker cluster cannot be "
            "measured; give the marker geometry"
        )
    if full.size > max_frames:
        full = full[np.linspace(0, full.size - 1, max_frames).astype(int)]
    pts = tracks.positions[full]
    sane = _plausible_frames(pts)
    pts = pts[sane] if sane.any() else pts
    d = np.linalg.norm(pts[:, :, None, :] - pts[:, None, :, :], axis=3)
    start = int(np.argmin(np.max(np.abs(d - np.median(d, axis=0)), axis=(1, 2))))
    ref = pts[start] - pts[start].mean(axis=0)
    _check_not_collinear(ref, tracks.source or "marker tracks")
    size = float(np.sqrt(np.mean(np.sum(ref * ref, axis=1))))
    for _ in range(max(1, iterations)):
        R, t, rms = _kabsch_batch(ref, pts)
        use = rms <= max(OUTLIER_FACTOR * float(np.median(rms)), OUTLIER_FLOOR * size)
        back = np.einsum("nji,nkj->nki", R[use], pts[use] - t[use, None, :])  # R^T (x - t)
        ref = back.mean(axis=0)
        ref = ref - ref.mean(axis=0)
    return ref


@dataclass(frozen=True)
class RigidityReport:
    """Inter-marker distance statistics: per pair (label_i, label_j) the median distance [m] and
    the drift [m] (range of its running median); ``tolerance`` [m]; ``worst`` pair."""

    pairs: dict[tuple[str, str], tuple[float, float]] = field(default_factory=dict)
    tolerance: float = 0.0
    worst: tuple[str, str] | None = None
    worst_drift: float = 0.0

    def to_dict(self) -> dict[str, Any]:
        return {
            "tolerance_m": self.tolerance,
            "worst_pair": list(self.worst) if self.worst else None,
            "worst_drift_m": self.worst_drift,
            "pairs": {
                f"{a}-{b}": {"median_m": m, "drift_m": d} for (a, b), (m, d) in self.pairs.items()
            },
        }


def check_rigidity(
    tracks: MarkerTracks, *, tolerance: float = 1.0e-3, window: int = 15, raise_error: bool = True
) -> RigidityReport:
    """Check that the markers move as one rigid body.

    For every marker pair the distance is followed over the frames where both are seen; its running
    median over ``window`` samples (robust to noise and to single wrong samples) must stay within
    ``tolerance`` [m] of itself over the whole record (drift = max - min of the running median).
    A loose marker (one that slips at the impact, or creeps) exceeds it; random noise of sigma s
    gives a drift of roughly 6 * 1.25 s * sqrt(2 / window), about 0.5 mm for s = 0.2 mm.
    Raises :class:`RigidityError` naming the pair and the drift unless ``raise_error`` is False.
    """
    check_instance(tracks, MarkerTracks, "tracks", "read them with read_markers()")
    if tolerance <= 0:
        raise ValueError(f"tolerance must be > 0 m, got {tolerance!r}")
    window = max(3, int(window))
    pos = tracks.positions
    valid = tracks.valid
    pairs: dict[tuple[str, str], tuple[float, float]] = {}
    worst: tuple[str, str] | None = None
    worst_drift = 0.0
    for i in range(tracks.n_markers):
        for j in range(i + 1, tracks.n_markers):
            both = valid[:, i] & valid[:, j]
            d = np.linalg.norm(pos[both, i] - pos[both, j], axis=1)
            if d.size == 0:
                continue
            med = float(np.median(d))
            if d.size >= window:
                run = np.median(np.lib.stride_tricks.sliding_window_view(d, window), axis=1)
                drift = float(run.max() - run.min())
            else:
                drift = float(d.max() - d.min())
            key = (tracks.labels[i], tracks.labels[j])
            pairs[key] = (med, drift)
            if drift > worst_drift:
                worst, worst_drift = key, drift
    report = RigidityReport(pairs, float(tolerance), worst, worst_drift)
    if raise_error and worst is not None and worst_drift > tolerance:
        raise RigidityError(
            f"{tracks.source or 'marker tracks'}: markers {worst[0]} and {worst[1]} are not "
            f"rigidly attached: their distance drifts by {worst_drift * 1e3:.2f} mm over the "
            f"record (tolerance {tolerance * 1e3:.2f} mm)"
        )
    return report


@dataclass(frozen=True)
class MarkerGeometry:
    """Where the markers sit on the rod (the body frame of the rod, SI).

    Body frame: origin at the rod's centre of mass C; first axis e1 = unit vector along the rod axis
    from C towards the centre of the tip sphere (which lies L/2 from C, paper Eq. 1); the other two
    axes complete a right-handed frame in any orientation. ``markers`` (m, 3) [m] are the marker
    centres in this frame, in the order of ``labels`` (None: the order of the tracks).
    """

    markers: np.ndarray
    labels: tuple[str, ...] | None = None
    units_note: str = field(default="", compare=False, repr=False)
    """The unit the geometry's lengths were read in (e.g. ``"m (no units key)"``), for
    messages; empty for one given in metres as an array."""

    def __post_init__(self) -> None:
        m = np.array(self.markers, dtype=np.float64)
        if m.ndim != 2 or m.shape[1] != 3 or m.shape[0] < 3:
            raise ValueError(f"markers must have shape (m >= 3, 3), got {m.shape}")
        if not np.all(np.isfinite(m)):
            raise ValueError("markers must be finite")
        _check_not_collinear(m, "marker geometry")
        m.setflags(write=False)
        object.__setattr__(self, "markers", m)
        if self.labels is not None:
            labels = tuple(str(s) for s in self.labels)
            if len(labels) != m.shape[0]:
                raise ValueError(f"{len(labels)} labels for {m.shape[0]} markers")
            object.__setattr__(self, "labels", labels)

    @classmethod
    def from_mapping(cls, data: Mapping[str, Any], *, units: str | None = None) -> MarkerGeometry:
        """From ``{"units": "mm", "M1": [x, y, z], ...}`` (the ``[markers]`` table of a TOML
        file); ``units`` overrides the table's (default m, said in the messages that compare
        the geometry with the markers). ValueError naming ``markers.<label>`` for an entry that
        is not three numbers."""
        check_instance(data, Mapping, "data", '{"units": "mm", "M1": [x, y, z], ...}')
        d = dict(data)
        table_unit = d.pop("units", None)
        unit = units or table_unit or "m"
        if units:
            note = f"{units} (units=)"
        elif table_unit:
            note = str(table_unit)
        else:
            note = "m (no units key)"
        fac = length_factor(str(unit), name="markers.units")
        labels, rows = [], []
        for k, v in d.items():
            labels.append(str(k))
            rows.append(_xyz(k, v) * fac)
        if len(rows) < 3:
            raise ValueError(f"the marker geometry needs at least 3 markers, got {len(rows)}")
        return cls(np.array(rows), tuple(labels), note)


def _xyz(label: Any, value: Any) -> np.ndarray:
    """``markers.<label>`` as three finite numbers; ValueError naming it otherwise."""
    wrong = ValueError(
        f"markers.{label} must be [x, y, z], three numbers (in the table's units), got {value!r}"
    )
    if isinstance(value, str | bytes) or not isinstance(value, list | tuple | np.ndarray):
        raise wrong
    if any(isinstance(x, bool) or not isinstance(x, int | float | np.number) for x in value):
        raise wrong
    arr = np.asarray(value, dtype=np.float64)
    if arr.shape != (3,) or not np.all(np.isfinite(arr)):
        raise wrong
    return arr
