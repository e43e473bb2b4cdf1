"""From marker tracks to the impact kinematics: velocities before/after, e, mu, the rod angle.

Pipeline (details and the uncertainty model in docs/experiment.md):

1. rigidity check of the marker cluster, then its pose per frame (Kabsch, :mod:`.rigid`);
2. the centre of mass C and the rod axis from the marker geometry (given, or estimated: the axis
   from the cluster's principal direction, C as the body point that flies ballistically);
3. impact detection: the largest jump of the upward velocity of the cluster, from straight-line
   fits to ``window`` frames on either side of each frame (gravity removed);
4. free-flight segments before and after, ``guard`` frames away from the impact frame, at most
   ``max_fit_frames`` long, trimmed at their far end where the data stop being ballistic (the rod
   still held before the release, a second bounce after);
5. per segment one least-squares fit, common design matrix [1, tau]: the horizontal and out-of-
   plane coordinates of C linear in time, the vertical one quadratic with the known gravity, the
   rod angle linear; covariance of the coefficients = S (x) (A^T A)^-1 with S the residual
   covariance of the four coordinates (multivariate regression);
6. the impact instant: where the extrapolated tip heights of the two fits cross;
7. at that instant: v_C, omega and theta before and after, the tip velocities, e and mu; all with
   first-order uncertainties propagated from the two fits (numerical Jacobian), the impact instant
   included.

Frame of the results (the paper's, Fig. 1): y up (``up``), x horizontal in the vertical plane of
the rod axis at impact, positive from the tip towards C; z = x cross y. theta is the angle of the
vector tip -> C above the horizontal (the rod angle to the flat); omega = d theta / dt (the z spin).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq

from impactlab.experiment.errors import ImpactNotFoundError, MarkerError, TooFewFramesError
from impactlab.experiment.markers import MarkerTracks
from impactlab.experiment.rigid import (
    MarkerGeometry,
    Poses,
    RigidityReport,
    check_rigidity,
    fit_poses,
    reference_cluster,
)
from impactlab.experiment.uncertainty import Estimate, propagate

__all__ = [
    "G0",
    "ImpactKinematics",
    "SegmentFit",
    "measure_impact",
    "parse_up",
    "rod_dimensions",
]

#: Standard gravity [m/s^2].
G0 = 9.80665


def parse_up(up: Any) -> np.ndarray:
    """The lab's upward unit vector from "+z", "-y", "z" ... or a 3-vector."""
    if isinstance(up, str):
        s = up.strip().lower()
        sign = -1.0 if s.startswith("-") else 1.0
        s = s.lstrip("+-")
        if s not in ("x", "y", "z"):
            raise ValueError(f"up must be one of '+x', '-x', '+y', '-y', '+z', '-z' or a "
                             f"3-vector, got {up!r}")
        v = np.zeros(3)
        v["xyz".index(s)] = sign
        return v
    v = np.asarray(up, dtype=np.float64).reshape(-1)
    if v.shape != (3,) or not np.all(np.isfinite(v)) or np.linalg.norm(v) == 0:
        raise ValueError(f"up must be an axis name such as '+z' or a non-zero 3-vector, got {up!r}")
    return v / np.linalg.norm(v)


def rod_dimensions(rod: Any) -> tuple[float, float]:
    """(half length L/2 = distance C -> tip-sphere centre [m], tip radius R [m]) of a rod-like
    object (``impactlab.bodies.Rod``: ``half_length``/``L``; ``analytic.RodProperties``:
    ``length``)."""
    if hasattr(rod, "half_length"):
        h = float(rod.half_length)
    elif hasattr(rod, "L"):
        h = 0.5 * float(rod.L)
    elif hasattr(rod, "length"):
        h = 0.5 * float(rod.length)
    else:
        raise ValueError(f"rod must have a length (L, length or half_length), got {rod!r}")
    R = float(rod.tip_radius)
    if not (math.isfinite(h) and h > 0 and math.isfinite(R) and R > 0):
        raise ValueError(f"rod half length and tip radius must be > 0, got {h!r}, {R!r}")
    return h, R


@dataclass(frozen=True)
class SegmentFit:
    """One free-flight fit. ``frames``: indices into the tracks; ``tau`` [s] times relative to the
    reference instant; ``data`` (n, 4): X, Y, Z of C [m] and theta [rad] in the impact frame;
    ``coef`` (2, 4): offset and rate per coordinate (Y with gravity removed: Y + g tau^2/2);
    ``cov`` (8, 8) covariance of coef.T.ravel() (order X0, X1, Y0, Y1, Z0, Z1, th0, th1);
    ``rms`` (4,) residual RMS; ``trimmed``: frames dropped at the far end."""

    frames: np.ndarray
    tau: np.ndarray
    data: np.ndarray
    coef: np.ndarray
    cov: np.ndarray
    rms: np.ndarray
    trimmed: int = 0

    @property
    def n(self) -> int:
        return int(self.frames.size)


@dataclass(frozen=True)
class ImpactKinematics:
    """The measured impact (SI units; frame and signs in the module docstring).

    Estimates (value, sigma): ``t_impact`` [s], ``theta_in``/``theta_out`` [rad], ``v_c_in``/
    ``v_c_out`` ((x, y) of the centre of mass [m/s]), ``omega_in``/``omega_out`` [rad/s],
    ``v_tip_in``/``v_tip_out`` ((x, y) of the contact point [m/s]), ``e`` (= -v_tip,y,out /
    v_tip,y,in), ``mu`` (= |dv_Cx / dv_Cy|, paper Eq. 28), ``dv_cx``, ``dv_cy`` [m/s],
    ``v_c_z_in``/``v_c_z_out`` (out-of-plane, should be ~0) [m/s]. ``correlation``: correlation
    matrix of the derived quantities (names in ``derived_names``). Diagnostics: ``pre``/``post``
    fits, ``rigidity``, ``fitted_gravity`` [m/s^2], ``tilt_out_of_plane`` [rad], ``warnings``.
    """

    t_impact: Estimate
    theta_in: Estimate
    theta_out: Estimate
    v_c_in: tuple[Estimate, Estimate]
    v_c_out: tuple[Estimate, Estimate]
    omega_in: Estimate
    omega_out: Estimate
    v_tip_in: tuple[Estimate, Estimate]
    v_tip_out: tuple[Estimate, Estimate]
    e: Estimate
    mu: Estimate
    dv_cx: Estimate
    dv_cy: Estimate
    v_c_z_in: Estimate
    v_c_z_out: Estimate
    derived_names: tuple[str, ...]
    derived_values: np.ndarray = field(repr=False)
    derived_cov: np.ndarray = field(repr=False)
    pre: SegmentFit = field(repr=False)
    post: SegmentFit = field(repr=False)
    impact_frame: int = -1
    t_ref: float = 0.0
    gravity: float = G0
    half_length: float = 0.0
    tip_radius: float = 0.0
    frame_axes: np.ndarray = field(default_factory=lambda: np.eye(3), repr=False)
    origin: np.ndarray = field(default_factory=lambda: np.zeros(3), repr=False)
    com_body: np.ndarray = field(default_factory=lambda: np.zeros(3), repr=False)
    axis_body: np.ndarray = field(default_factory=lambda: np.array([1.0, 0, 0]), repr=False)
    geometry_source: str = "given"
    rigidity: RigidityReport | None = field(default=None, repr=False)
    fitted_gravity: float | None = None
    tilt_out_of_plane: float = 0.0
    poses: Poses | None = field(default=None, repr=False)
    warnings: tuple[str, ...] = ()

    @property
    def v_i(self) -> Estimate:
        """Normal (vertical) tip velocity before the impact [m/s] (negative: downwards)."""
        return self.v_tip_in[1]

    @property
    def correlation(self) -> np.ndarray:
        s = np.sqrt(np.clip(np.diag(self.derived_cov), 0, None))
        with np.errstate(invalid="ignore", divide="ignore"):
            c = self.derived_cov / np.outer(s, s)
        return np.nan_to_num(c)

    def series(self) -> tuple[np.ndarray, np.ndarray]:
        """All frames with a pose: (time [s], (n, 4) X, Y, Z of C [m] and theta [rad]) in the
        impact frame (NaN where no pose)."""
        if self.poses is None:
            return np.zeros(0), np.zeros((0, 4))
        fr = np.flatnonzero(self.poses.ok)
        data = _segment_data(self.poses, fr, self.com_body, self.axis_body, self.frame_axes,
                             self.origin)
        return self.poses.time[fr], data

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready summary (SI units; angles also in degrees)."""

        def est(x: Estimate) -> dict[str, Any]:
            return x.to_dict()

        d: dict[str, Any] = {
            "t_impact": est(self.t_impact),
            "theta_in": est(self.theta_in),
            "theta_in_deg": est(self.theta_in.scaled(180.0 / math.pi, "deg")),
            "theta_out": est(self.theta_out),
            "v_c_in": [est(v) for v in self.v_c_in],
            "v_c_out": [est(v) for v in self.v_c_out],
            "omega_in": est(self.omega_in),
            "omega_out": est(self.omega_out),
            "v_tip_in": [est(v) for v in self.v_tip_in],
            "v_tip_out": [est(v) for v in self.v_tip_out],
            "v_i": est(self.v_i),
            "e": est(self.e),
            "mu": est(self.mu),
            "dv_cx": est(self.dv_cx),
            "dv_cy": est(self.dv_cy),
            "v_c_z_in": est(self.v_c_z_in),
            "v_c_z_out": est(self.v_c_z_out),
            "impact_frame": self.impact_frame,
            "frames_before": self.pre.n,
            "frames_after": self.post.n,
            "fit_rms_before": {"X_m": self.pre.rms[0], "Y_m": self.pre.rms[1],
                               "Z_m": self.pre.rms[2], "theta_rad": self.pre.rms[3]},
            "fit_rms_after": {"X_m": self.post.rms[0], "Y_m": self.post.rms[1],
                              "Z_m": self.post.rms[2], "theta_rad": self.post.rms[3]},
            "geometry": self.geometry_source,
            "fitted_gravity": self.fitted_gravity,
            "tilt_out_of_plane_deg": math.degrees(self.tilt_out_of_plane),
            "warnings": list(self.warnings),
        }
        if self.rigidity is not None:
            d["rigidity"] = self.rigidity.to_dict()
        return d


# ----------------------------------------------------------------------------------------------
# helpers
# ----------------------------------------------------------------------------------------------


def _line_slopes(t: np.ndarray, h: np.ndarray) -> float:
    tc = t - t.mean()
    return float(np.dot(tc, h - h.mean()) / np.dot(tc, tc))


def _velocity_jumps(t: np.ndarray, h: np.ndarray, window: int) -> np.ndarray:
    """Jump of the slope of h at each sample: slope of the ``window`` samples after minus that of
    the ``window`` samples before (the sample itself excluded); NaN where a side is short."""
    n = t.size
    out = np.full(n, np.nan)
    for i in range(window, n - window):
        sb = _line_slopes(t[i - window:i], h[i - window:i])
        sa = _line_slopes(t[i + 1:i + 1 + window], h[i + 1:i + 1 + window])
        out[i] = sa - sb
    return out


def _robust_sigma(x: np.ndarray) -> float:
    x = x[np.isfinite(x)]
    if x.size == 0:
        return 0.0
    return float(1.4826 * np.median(np.abs(x - np.median(x))))


def _fit_segment(tau: np.ndarray, data: np.ndarray, g: float) -> tuple[np.ndarray, np.ndarray,
                                                                       np.ndarray, np.ndarray]:
    """Multivariate least squares with design [1, tau]; Y gets + g tau^2 / 2 (known gravity).
    Returns (coef (2, 4), cov (8, 8), residuals (n, 4), rms (4,))."""
    D = data.copy()
    D[:, 1] = D[:, 1] + 0.5 * g * tau * tau
    A = np.column_stack([np.ones_like(tau), tau])
    AtA_inv = np.linalg.inv(A.T @ A)
    coef = AtA_inv @ A.T @ D
    E = D - A @ coef
    n = tau.size
    S = (E.T @ E) / max(n - 2, 1)
    cov = np.kron(S, AtA_inv)
    rms = np.sqrt(np.mean(E * E, axis=0))
    return coef, cov, E, rms


def _segment_data(
    poses: Poses, frames: np.ndarray, com_body: np.ndarray, axis_body: np.ndarray,
    axes: np.ndarray, origin: np.ndarray,
) -> np.ndarray:
    """(n, 4): X, Y, Z of C in the impact frame [m], theta [rad] (unwrapped)."""
    R = poses.rotation[frames]
    t = poses.translation[frames]
    c = np.einsum("nij,j->ni", R, com_body) + t - origin
    u = -np.einsum("nij,j->ni", R, axis_body)  # tip -> C
    xh, yh, zh = axes
    X, Y, Z = c @ xh, c @ yh, c @ zh
    th = np.unwrap(np.arctan2(u @ yh, u @ xh))
    return np.column_stack([X, Y, Z, th])


def _prediction_z(a: np.ndarray, d: np.ndarray, coef: np.ndarray, AtA_inv: np.ndarray,
                  S: np.ndarray) -> float:
    """Largest |residual| / prediction sigma over the coordinates of one new frame."""
    var = S * (1.0 + a @ AtA_inv @ a)
    return float(np.max(np.abs(d - a @ coef) / np.sqrt(var)))


def _trimmed_fit(
    poses: Poses, frames: np.ndarray, far_end: str, t_ref: float, com_body: np.ndarray,
    axis_body: np.ndarray, axes: np.ndarray, origin: np.ndarray, g: float, min_frames: int,
    threshold: float = 5.0, n_start: int = 10,
) -> SegmentFit:
    """Fit a free-flight segment grown outwards from the impact: start with the ``n_start``
    frames nearest to it, then add one frame at a time while it agrees with the prediction of the
    current fit (every coordinate within ``threshold`` prediction sigmas). A single disagreeing
    frame is dropped as an outlier; two in a row end the segment (the rod still held before its
    release, a second bounce, the rod leaving the camera's volume)."""
    order = frames[::-1] if far_end == "start" else frames
    tau_all = poses.time[order] - t_ref
    data_all = _segment_data(poses, order, com_body, axis_body, axes, origin)
    D = data_all.copy()
    D[:, 1] = D[:, 1] + 0.5 * g * tau_all * tau_all
    A_all = np.column_stack([np.ones_like(tau_all), tau_all])
    floor = np.array([1e-6, 1e-6, 1e-6, 1e-6]) ** 2
    n0 = min(max(min_frames, n_start), order.size)
    keep = list(range(n0))
    j = n0
    while j < order.size:
        A = A_all[keep]
        AtA_inv = np.linalg.inv(A.T @ A)
        coef = AtA_inv @ A.T @ D[keep]
        E = D[keep] - A @ coef
        S = np.maximum(np.sum(E * E, axis=0) / max(len(keep) - 2, 1), floor)

        if _prediction_z(A_all[j], D[j], coef, AtA_inv, S) <= threshold:
            keep.append(j)
            j += 1
            continue
        if j + 1 < order.size and \
                _prediction_z(A_all[j + 1], D[j + 1], coef, AtA_inv, S) <= threshold:
            j += 1  # a single outlier: skip it
            continue
        break
    sel = np.sort(order[keep])
    tau = poses.time[sel] - t_ref
    data = _segment_data(poses, sel, com_body, axis_body, axes, origin)
    coef, cov, _, rms = _fit_segment(tau, data, g)
    return SegmentFit(sel, tau, data, coef, cov, rms, int(order.size - len(keep)))


def _smoothed_rotations(poses: Poses, fr: np.ndarray, t_ref: float) -> np.ndarray:
    """Rotations of a free-flight segment smoothed by a constant-spin model: rotation vectors
    relative to the middle frame fitted linearly in time (torque-free planar flight)."""
    from scipy.spatial.transform import Rotation

    R = poses.rotation[fr]
    mid = fr.size // 2
    R0 = R[mid]
    rv = Rotation.from_matrix(np.einsum("nij,kj->nik", R, R0)).as_rotvec()  # R_k R0^T
    tau = poses.time[fr] - t_ref
    A = np.column_stack([np.ones_like(tau), tau])
    coef, *_ = np.linalg.lstsq(A, rv, rcond=None)
    return np.einsum("nij,jk->nik", Rotation.from_rotvec(A @ coef).as_matrix(), R0)


def _estimate_com(
    poses: Poses, segments: list[np.ndarray], t_ref: float, up: np.ndarray, g: float,
    ridge: float = 1e-3, min_turn: float = 0.05,
) -> tuple[np.ndarray, np.ndarray]:
    """The body point (reference frame) that moves ballistically in every segment.

    Unknowns: p (3) and per segment c0, c1 (3 each); rows: R_k p - c0 - c1 tau_k = -t_k - g tau^2/2
    up. Only segments in which the rod turns by at least ``min_turn`` [rad] are used (a still
    rod says nothing about p), with their rotations smoothed by a constant-spin fit (noisy R_k
    would bias p towards the cluster centroid: errors in variables). The component of p along the
    spin axis does not change the motion (planar flight); a weak ridge term pulls it to the
    cluster centroid. Returns (p, covariance of p)."""
    from scipy.spatial.transform import Rotation

    used = []
    for fr in segments:
        if fr.size < 4:
            continue
        turn = Rotation.from_matrix(poses.rotation[fr[-1]] @ poses.rotation[fr[0]].T).magnitude()
        if turn >= min_turn:
            used.append(fr)
    if not used:
        return np.zeros(3), np.diag(np.full(3, np.inf))
    nseg = len(used)
    ncol = 3 + 6 * nseg
    rows: list[np.ndarray] = []
    rhs: list[np.ndarray] = []
    for s, fr in enumerate(used):
        tau = poses.time[fr] - t_ref
        Rs = _smoothed_rotations(poses, fr, t_ref)
        for k, tk, Rk in zip(fr, tau, Rs, strict=True):
            blk = np.zeros((3, ncol))
            blk[:, :3] = Rk
            blk[:, 3 + 6 * s:6 + 6 * s] = -np.eye(3)
            blk[:, 6 + 6 * s:9 + 6 * s] = -tk * np.eye(3)
            rows.append(blk)
            rhs.append(-poses.translation[k] - 0.5 * g * tk * tk * up)
    A = np.vstack(rows)
    b = np.concatenate(rhs)
    reg = np.zeros((3, ncol))
    reg[:, :3] = ridge * np.eye(3)
    Ar = np.vstack([A, reg])
    br = np.concatenate([b, np.zeros(3)])
    x, *_ = np.linalg.lstsq(Ar, br, rcond=None)
    res = b - A @ x
    dof = max(A.shape[0] - ncol, 1)
    s2 = float(res @ res) / dof
    cov = s2 * np.linalg.pinv(Ar.T @ Ar)
    return x[:3], cov[:3, :3]


def _derive(x: np.ndarray, t_ref: float, tau_lo: float, tau_hi: float, g: float, half: float,
            R_tip: float, notes: list[str]) -> np.ndarray:
    """The derived quantities (order ``_DERIVED``) from the 16 fit coefficients (before, after)."""
    a_, b_ = x[:8], x[8:]

    def tip_h(c: np.ndarray, tau: float) -> float:
        Y = c[2] + c[3] * tau - 0.5 * g * tau * tau
        return float(Y - half * math.sin(c[6] + c[7] * tau))

    def f(tau: float) -> float:
        return tip_h(a_, tau) - tip_h(b_, tau)

    flo, fhi = f(tau_lo), f(tau_hi)
    if flo > 0 > fhi:
        tau_i = float(brentq(f, tau_lo, tau_hi, xtol=1e-12))
    else:
        # no crossing between the segments: the linearised crossing, clipped
        tau_i = tau_lo - flo * (tau_hi - tau_lo) / (fhi - flo) if fhi != flo else 0.0
        tau_i = min(max(tau_i, tau_lo), tau_hi)
        if not notes:
            notes.append("the extrapolated tip heights do not cross between the fits; the "
                         "impact instant is approximate")
    vals = []
    for c in (a_, b_):
        th = c[6] + c[7] * tau_i
        vx, vy, vz, om = c[1], c[3] - g * tau_i, c[5], c[7]
        ra = half * math.cos(th)
        rb = half * math.sin(th) + R_tip
        vals.append((th, vx, vy, om, vx + om * rb, vy - om * ra, vz))
    (thi, vxi, vyi, omi, txi, tyi, vzi), (tho, vxo, vyo, omo, txo, tyo, vzo) = vals
    dvx, dvy = vxo - vxi, vyo - vyi
    e = -tyo / tyi if tyi != 0 else math.nan
    mu = abs(dvx / dvy) if dvy != 0 else math.nan
    return np.array([t_ref + tau_i, thi, tho, vxi, vyi, omi, vxo, vyo, omo, txi, tyi, txo, tyo,
                     e, mu, dvx, dvy, vzi, vzo])


# ----------------------------------------------------------------------------------------------
# main entry
# ----------------------------------------------------------------------------------------------

_DERIVED = (
    "t_impact", "theta_in", "theta_out", "v_cx_in", "v_cy_in", "omega_in", "v_cx_out",
    "v_cy_out", "omega_out", "v_tip_x_in", "v_tip_y_in", "v_tip_x_out", "v_tip_y_out", "e", "mu",
    "dv_cx", "dv_cy", "v_cz_in", "v_cz_out",
)


def measure_impact(
    tracks: MarkerTracks,
    rod: Any,
    *,
    geometry: MarkerGeometry | None = None,
    up: Any = "+z",
    g: float = G0,
    guard: int = 2,
    window: int = 5,
    max_fit_frames: int = 40,
    min_fit_frames: int = 6,
    rigidity_tolerance: float = 1.0e-3,
    rigidity_window: int = 15,
    max_com_sigma: float = 5.0e-3,
) -> ImpactKinematics:
    """Measure the impact from marker tracks (steps and frame in the module docstring).

    Parameters
    ----------
    tracks : the markers (SI), e.g. from :func:`impactlab.experiment.read_markers`.
    rod : rod-like (``impactlab.bodies.Rod``): its length (L/2 from C to the tip-sphere centre)
        and ``tip_radius`` place the contact point.
    geometry : the markers' positions in the rod's body frame (:class:`MarkerGeometry`); None
        estimates the axis (principal direction of the cluster: markers mounted along the rod) and
        C (the ballistic body point; needs the rod to turn after the impact).
    up : the lab's upward direction ("+z" default, or a 3-vector), normal to the flat.
    g : gravity [m/s^2]. guard : frames on each side of the impact frame left out of the fits.
    window : frames per side for the impact detector. max_fit_frames, min_fit_frames : length
        limits of each free-flight fit. rigidity_tolerance [m], rigidity_window : see
        :func:`check_rigidity`. max_com_sigma [m] : largest acceptable uncertainty of an estimated
        centre of mass along the rod axis.

    Raises :class:`MarkerError` subclasses naming the problem (loose markers, no impact, too few
    free-flight frames, geometry that does not fit).
    """
    src = tracks.source or "marker tracks"
    half, R_tip = rod_dimensions(rod)
    upv = parse_up(up)
    warnings: list[str] = []
    if guard < 1 or window < 2 or min_fit_frames < 4 or max_fit_frames < min_fit_frames:
        raise ValueError(f"need guard >= 1, window >= 2, min_fit_frames >= 4 and max_fit_frames >= "
                         f"min_fit_frames; got {guard}, {window}, {min_fit_frames}, "
                         f"{max_fit_frames}")
    if tracks.n_markers < 3:
        raise MarkerError(f"{src}: {tracks.n_markers} markers; at least 3 are needed for the "
                          "rod's pose")

    # 1. geometry and poses
    if geometry is not None:
        if geometry.labels is not None:
            missing = [lab for lab in geometry.labels if lab not in tracks.labels]
            if missing:
                raise MarkerError(f"{src}: the marker geometry names markers {missing} that the "
                                  f"file does not have (it has {list(tracks.labels)})")
            tracks = tracks.select(list(geometry.labels))
        elif geometry.markers.shape[0] != tracks.n_markers:
            raise MarkerError(f"{src}: the marker geometry has {geometry.markers.shape[0]} "
                              f"markers {list(geometry.labels or [])} but the file has "
                              f"{tracks.n_markers} {list(tracks.labels)}")
        reference = np.asarray(geometry.markers, dtype=np.float64)
    else:
        reference = reference_cluster(tracks)
    rigidity = check_rigidity(tracks, tolerance=rigidity_tolerance, window=rigidity_window)
    if geometry is not None:
        # the given geometry must match the measured cluster shape
        meas = reference_cluster(tracks)
        d_meas = np.linalg.norm(meas[:, None] - meas[None], axis=2)
        d_geo = np.linalg.norm(reference[:, None] - reference[None], axis=2)
        mis = float(np.max(np.abs(d_meas - d_geo)))
        if mis > max(2.0 * rigidity_tolerance, 2e-3):
            raise MarkerError(f"{src}: the given marker geometry does not match the markers: "
                              f"inter-marker distances differ by up to {mis * 1e3:.2f} mm "
                              "(wrong labels, order or units?)")
    poses = fit_poses(tracks, reference)
    ok = np.flatnonzero(poses.ok)
    if ok.size < 2 * min_fit_frames + 1:
        raise TooFewFramesError(f"{src}: only {ok.size} frames with a usable pose (3 or more "
                                f"markers seen); need at least {2 * min_fit_frames + 1}")

    # 2. impact detection: jumps of the velocity of the cluster origin and of the rate of turn
    # of the cluster's principal axis, each in units of its robust noise, combined
    t_ok = poses.time[ok]
    _, _, vt_ref = np.linalg.svd(reference - reference.mean(axis=0))
    spread = float(np.ptp((reference - reference.mean(axis=0)) @ vt_ref[0]))
    chans = np.column_stack([
        poses.translation[ok] + 0.5 * g * ((t_ok - t_ok[0]) ** 2)[:, None] * upv,
        np.einsum("nij,j->ni", poses.rotation[ok], vt_ref[0]) * spread,
    ])
    jumps = np.column_stack([_velocity_jumps(t_ok, chans[:, c], window) for c in range(6)])
    if not np.any(np.isfinite(jumps[:, 0])):
        raise TooFewFramesError(f"{src}: too few frames ({ok.size}) to find the impact")
    sig_c = np.array([max(_robust_sigma(jumps[:, c]), 1e-9) for c in range(6)])
    stat = np.sqrt(np.sum((jumps / sig_c) ** 2, axis=1))
    i_star = int(np.nanargmax(stat))
    jmax = float(stat[i_star])
    if not jmax > 12.0:
        raise ImpactNotFoundError(
            f"{src}: no impact found: the largest jump of the rod's velocity is {jmax:.3g} "
            "noise sigmas (need > 12); is there an impact in the record?")
    k_star = int(ok[i_star])
    t_ref = float(poses.time[k_star])
    # other impacts (a second bounce) bound the segments
    idx = np.arange(stat.size)
    others = np.flatnonzero((stat > max(12.0, 0.3 * jmax)) & (np.abs(idx - i_star) > 2 * window))
    lo_i = int(others[others < i_star].max()) + window if np.any(others < i_star) else 0
    hi_i = int(others[others > i_star].min()) - window if np.any(others > i_star) else ok.size - 1

    # 3. segments
    pre_all = ok[(ok <= k_star - guard) & (ok >= ok[min(lo_i, ok.size - 1)])]
    post_all = ok[(ok >= k_star + guard) & (ok <= ok[max(hi_i, 0)])]
    pre_fr = pre_all[-max_fit_frames:]
    post_fr = post_all[:max_fit_frames]
    for name, fr in (("before", pre_fr), ("after", post_fr)):
        if fr.size < min_fit_frames:
            raise TooFewFramesError(
                f"{src}: only {fr.size} free-flight frames with a pose {name} the impact at "
                f"t = {t_ref:.4f} s (frame {k_star}); need at least {min_fit_frames}")

    # gravity direction check: free quadratic fit of the cluster origin before the impact (C when
    # the geometry is given; the rod hardly turns before the impact in a drop test)
    fitted_g = None
    fr = pre_fr
    if fr.size >= 8:
        tau = poses.time[fr] - t_ref
        c_lab = poses.translation[fr]
        A = np.column_stack([np.ones_like(tau), tau, 0.5 * tau * tau])
        coef, res, *_ = np.linalg.lstsq(A, c_lab, rcond=None)
        E = c_lab - A @ coef
        s2 = np.sum(E * E, axis=0) / max(fr.size - 3, 1)
        var_a = np.linalg.inv(A.T @ A)[2, 2] * s2
        a = coef[2]
        sig_a = float(np.sqrt(np.sum(var_a)))
        if sig_a < 0.2 * g:
            fitted_g = float(np.linalg.norm(a))
            cosang = float(-(a @ upv) / max(np.linalg.norm(a), 1e-30))
            if not (0.5 * g < fitted_g < 2.0 * g):
                warnings.append(f"the free fall before the impact accelerates at {fitted_g:.3g} "
                                f"m/s^2, not g = {g:.4g}: check the length units")
            elif cosang < math.cos(math.radians(25.0)):
                dirn = ", ".join(f"{v:+.2f}" for v in (-a / np.linalg.norm(a)))
                raise MarkerError(
                    f"{src}: gravity in the data points down along ({dirn}) in camera "
                    f"coordinates, {math.degrees(math.acos(max(-1, min(1, cosang)))):.0f} deg "
                    f"away from -up; pass the right up= (e.g. up='+y')")

    # 4. centre of mass and axis in the reference frame
    com_cov: np.ndarray | None = None
    if geometry is not None:
        com_body = np.zeros(3)
        axis_body = np.array([1.0, 0.0, 0.0])
        geometry_source = "given"
    else:
        _, _, vt = np.linalg.svd(reference - reference.mean(axis=0))
        axis_body = vt[0]
        k_last = pre_fr[-1]
        if (poses.rotation[k_last] @ axis_body) @ upv > 0:
            axis_body = -axis_body  # e1 points to the lower end (the tip) at impact
        com_body, com_cov = _estimate_com(poses, [pre_fr, post_fr], t_ref, upv, g)
        sig_axis = float(np.sqrt(max(axis_body @ com_cov @ axis_body, 0.0))) \
            if np.all(np.isfinite(com_cov)) else math.inf
        if not sig_axis < max_com_sigma:
            raise MarkerError(
                f"{src}: cannot locate the rod's centre of mass from the flight precisely enough "
                f"(+-{sig_axis * 1e3:.2g} mm along the axis, limit {max_com_sigma * 1e3:.2g} mm: "
                "too little rotation or too few frames after the impact); give the marker "
                "geometry (the markers' positions relative to the rod axis)")
        geometry_source = f"estimated (centre of mass +- {sig_axis * 1e3:.2g} mm along the axis)"

    # 5. the impact frame of reference
    k_last = pre_fr[-1]
    Rk = poses.rotation[k_last]
    e1_lab = Rk @ axis_body
    if e1_lab @ upv >= 0:
        raise MarkerError(f"{src}: the rod's tip (+e1 end of the marker geometry) is not below "
                          "its centre of mass before the impact; check the geometry's axis "
                          "direction (e1 points from the centre of mass to the tip) and up=")
    u = -e1_lab
    uh = u - (u @ upv) * upv
    if np.linalg.norm(uh) < 1e-3:
        raise MarkerError(f"{src}: the rod is vertical at the impact; the impact plane (x axis) "
                          "is undefined")
    xh = uh / np.linalg.norm(uh)
    zh = np.cross(xh, upv)
    axes = np.vstack([xh, upv, zh])
    origin = Rk @ com_body + poses.translation[k_last]

    pre = _trimmed_fit(poses, pre_fr, "start", t_ref, com_body, axis_body, axes, origin, g,
                       min_fit_frames)
    post = _trimmed_fit(poses, post_fr, "end", t_ref, com_body, axis_body, axes, origin, g,
                        min_fit_frames)
    for name, seg in (("before", pre), ("after", post)):
        if seg.n < min_fit_frames:
            raise TooFewFramesError(
                f"{src}: only {seg.n} ballistic free-flight frames {name} the impact at "
                f"t = {t_ref:.4f} s; need at least {min_fit_frames}")
        if seg.trimmed:
            warnings.append(f"{seg.trimmed} non-ballistic frames dropped at the far end of the "
                            f"fit {name} the impact")
    if geometry is None and (pre.trimmed or post.trimmed):
        com_body, com_cov = _estimate_com(poses, [pre.frames, post.frames], t_ref, upv, g)
        pre = _trimmed_fit(poses, pre.frames, "start", t_ref, com_body, axis_body, axes, origin,
                           g, min_fit_frames)
        post = _trimmed_fit(poses, post.frames, "end", t_ref, com_body, axis_body, axes, origin,
                            g, min_fit_frames)

    # 6./7. derived quantities with uncertainties
    tau_lo = float(poses.time[pre.frames[-1]] - t_ref)
    tau_hi = float(poses.time[post.frames[0]] - t_ref)
    crossing_note: list[str] = []

    def derive(x: np.ndarray) -> np.ndarray:
        return _derive(x, t_ref, tau_lo, tau_hi, g, half, R_tip, crossing_note)

    x0 = np.concatenate([pre.coef.T.ravel(), post.coef.T.ravel()])
    cov0 = np.zeros((16, 16))
    cov0[:8, :8] = pre.cov
    cov0[8:, 8:] = post.cov
    y, cov_y = propagate(derive, x0, cov0)
    if com_cov is not None:
        # an estimated centre of mass: add its uncertainty (the fits redone with C moved)
        sig_p = np.sqrt(np.clip(np.diag(com_cov), 0.0, None))
        Jp = np.zeros((y.size, 3))
        for j in range(3):
            h = max(sig_p[j], 1e-6)
            ys = []
            for sgn in (1.0, -1.0):
                cb = com_body.copy()
                cb[j] += sgn * h
                xs = []
                for seg in (pre, post):
                    tau = poses.time[seg.frames] - t_ref
                    data = _segment_data(poses, seg.frames, cb, axis_body, axes, origin)
                    xs.append(_fit_segment(tau, data, g)[0].T.ravel())
                ys.append(derive(np.concatenate(xs)))
            Jp[:, j] = (ys[0] - ys[1]) / (2.0 * h)
        cov_y = cov_y + Jp @ com_cov @ Jp.T
    warnings += crossing_note
    if not np.all(np.isfinite(y)):
        raise MarkerError(f"{src}: the fits give no finite impact velocities (tip velocity "
                          "before the impact is zero?)")
    if y[10] >= 0:
        raise MarkerError(f"{src}: the tip is not moving towards the flat before the impact "
                          f"(v_tip,y = {y[10]:.3g} m/s); check up=")
    sig = np.sqrt(np.clip(np.diag(cov_y), 0.0, None))
    E_ = {n: Estimate(v, s, u_) for n, v, s, u_ in zip(
        _DERIVED, y, sig,
        ("s", "rad", "rad", "m/s", "m/s", "rad/s", "m/s", "m/s", "rad/s", "m/s", "m/s", "m/s",
         "m/s", "", "", "m/s", "m/s", "m/s", "m/s"), strict=True)}
    if not 0.0 < E_["theta_in"].value < 0.5 * math.pi:
        warnings.append(f"rod angle at impact {math.degrees(E_['theta_in'].value):.1f} deg is "
                        "outside (0, 90) deg")
    # out-of-plane tilt of the rod axis before the impact
    u_pre = -np.einsum("nij,j->ni", poses.rotation[pre.frames], axis_body)
    tilt = float(np.median(np.arcsin(np.clip(u_pre @ zh, -1, 1))))
    if abs(tilt) > math.radians(5):
        warnings.append(f"the rod axis leaves the vertical impact plane by "
                        f"{math.degrees(tilt):.1f} deg before the impact")
    vz_max = max(abs(E_["v_cz_in"].value), abs(E_["v_cz_out"].value))
    if vz_max > 0.1 * abs(E_["v_tip_y_in"].value):
        warnings.append(f"out-of-plane centre-of-mass velocity up to {vz_max:.3g} m/s: the "
                        "motion is not planar, the planar analysis is approximate")
    return ImpactKinematics(
        t_impact=E_["t_impact"], theta_in=E_["theta_in"], theta_out=E_["theta_out"],
        v_c_in=(E_["v_cx_in"], E_["v_cy_in"]), v_c_out=(E_["v_cx_out"], E_["v_cy_out"]),
        omega_in=E_["omega_in"], omega_out=E_["omega_out"],
        v_tip_in=(E_["v_tip_x_in"], E_["v_tip_y_in"]),
        v_tip_out=(E_["v_tip_x_out"], E_["v_tip_y_out"]),
        e=E_["e"], mu=E_["mu"], dv_cx=E_["dv_cx"], dv_cy=E_["dv_cy"],
        v_c_z_in=E_["v_cz_in"], v_c_z_out=E_["v_cz_out"],
        derived_names=_DERIVED, derived_values=y, derived_cov=cov_y,
        pre=pre, post=post, impact_frame=k_star, t_ref=t_ref, gravity=g,
        half_length=half, tip_radius=R_tip, frame_axes=axes, origin=origin, com_body=com_body,
        axis_body=axis_body, geometry_source=geometry_source, rigidity=rigidity,
        fitted_gravity=fitted_g, tilt_out_of_plane=tilt, poses=poses,
        warnings=tuple(warnings),
    )
