"""Synthetic experiments with a known truth: marker tracks (C3D/CSV) and dent scans.

No public raw files of the paper's experiment exist, so the tests (and the worked example of
docs/experiment.md) make realistic ones here:

* :func:`rigid_impulse_impact`: the outgoing state of a rod after an instantaneous impact at its
  tip with a normal restitution ``e`` of the tip velocity and Coulomb friction ``mu`` (impulse
  ratio P_x = mu P in gross sliding, paper Eq. 7; sticking when the tip's tangential velocity would
  reverse). Rigid-body impulse relations as in docs/analytic.md. :func:`engine_impact` does the
  same with the impact engine (``impactlab.dynamics.simulate``) when it is installed.
* :func:`marker_tracks`: three (or more) markers on the rod at 500 fps, ballistic flight with
  gravity before and after, optional hold-and-release phase, Gaussian noise, occlusions.
* :func:`groove_surface`: an analytic dent: the envelope of the tip sphere (paraboloid
  approximation, valid for depths << R) swept along a straight path while its penetration rises
  linearly to ``depth`` and falls to ``end_depth`` (a gentle entry ramp, a sharper end, as the
  paper's Figs. 6-7 describe), plus a pile-up rim outside the dent. Its metrics have closed forms
  (:class:`GrooveTruth`).
* writers: C3D (ezc3d, residual -1 for occluded samples), the CSV layout, and height maps as X3P,
  Gwyddion GWY and NetCDF (SurfaceTopography's writers), ISO 25178-71 SDF (ASCII and binary,
  written here from the standard's layout), NPY and CSV.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from scipy.optimize import brentq

from impactlab.experiment.kinematics import G0, rod_dimensions
from impactlab.experiment.markers import MarkerTracks, length_factor

__all__ = [
    "ALIGNED_MARKERS",
    "DEFAULT_MARKERS",
    "GrooveTruth",
    "ImpactTruth",
    "ScanTruth",
    "engine_impact",
    "groove_surface",
    "marker_tracks",
    "rigid_impulse_impact",
    "synthetic_scan",
    "write_c3d",
    "write_scan",
]

#: Marker positions in the rod body frame [m] (origin C, e1 towards the tip): spread along the
#: upper half of the rod on short stubs, non-collinear.
DEFAULT_MARKERS = np.array([
    [-0.030, 0.018, 0.000],
    [-0.090, 0.000, 0.022],
    [-0.130, -0.020, 0.004],
])

#: A layout for the estimated-geometry mode: the two outer markers on one side of the rod, the
#: middle one on the other, so the cluster's principal axis is parallel to the rod axis.
ALIGNED_MARKERS = np.array([
    [-0.020, 0.012, 0.000],
    [-0.075, -0.006, 0.0104],
    [-0.130, 0.012, 0.000],
])


@dataclass(frozen=True)
class ImpactTruth:
    """The true impact (planar frame of the paper: x towards C, y up; omega = d theta/dt).

    angle [rad]; v_in, v_out (x, y) of C [m/s]; omega_in, omega_out [rad/s]; v_tip_in, v_tip_out
    [m/s]; e (tip normal restitution), mu (= |dv_Cx/dv_Cy|); regime ("sliding"/"sticking");
    duration [s] (0 for the impulse model); source ("impulse" or "engine"); for the engine also
    delta_p, sliding_length [m] and ``contact`` (k, 4): t [s], x, y of C [m] (origin: first
    contact point) and the rotation phi [rad] through the contact."""

    angle: float
    v_in: tuple[float, float]
    omega_in: float
    v_out: tuple[float, float]
    omega_out: float
    v_tip_in: tuple[float, float]
    v_tip_out: tuple[float, float]
    e: float
    mu: float
    regime: str
    duration: float = 0.0
    source: str = "impulse"
    delta_p: float = math.nan
    sliding_length: float = math.nan
    contact: np.ndarray | None = None


def _rod_mass_inertia(rod: Any) -> tuple[float, float]:
    m = float(rod.mass)
    inertia = getattr(rod, "inertia", None)
    if inertia is None:
        L = 2.0 * rod_dimensions(rod)[0]
        inertia = m * L * L / 12.0
    return m, float(inertia)


def _tip_velocity(v: tuple[float, float], om: float, a: float, b: float) -> tuple[float, float]:
    return (v[0] + om * b, v[1] - om * a)


def rigid_impulse_impact(
    rod: Any, angle: float, v_in: tuple[float, float] = (0.0, -1.41), *, e: float = 0.5,
    mu: float = 0.2, omega_in: float = 0.0,
) -> ImpactTruth:
    """Instantaneous rigid-body impact at the tip (Newton restitution ``e`` of the tip's normal
    velocity, Coulomb friction ``mu`` in gross sliding, sticking if the tip's tangential velocity
    would reverse). ``angle`` [rad] in (0, pi/2), velocities [m/s] (x towards C, y up)."""
    half, R = rod_dimensions(rod)
    m, inertia = _rod_mass_inertia(rod)
    a = half * math.cos(angle)
    b = half * math.sin(angle) + R
    vt0 = _tip_velocity(v_in, omega_in, a, b)
    if vt0[1] >= 0:
        raise ValueError(f"the tip must approach the flat (v_tip,y < 0), got {vt0[1]!r} m/s")
    # tip velocity change per impulse: dv_Ox = cxx Px - cxy Py, dv_Oy = cyy Py - cxy Px
    cxx = 1.0 / m + b * b / inertia
    cyy = 1.0 / m + a * a / inertia
    cxy = a * b / inertia
    target_dvy = (1.0 + e) * (-vt0[1])
    # sliding: friction opposes the slip direction the normal impulse drives (the tip moves -x
    # for vt0x = 0), so Px = s mu Py with s = +1 for slip towards -x
    s = 1.0 if (vt0[0] < 0 or (vt0[0] == 0 and cxy > 0)) else -1.0
    Py = target_dvy / (cyy - s * mu * cxy)
    Px = s * mu * Py
    vtx_end = vt0[0] + cxx * Px - cxy * Py
    regime = "sliding"
    if s * vtx_end > 0:  # the slip would reverse: the tip sticks; solve for Px with vtx_end = 0
        M = np.array([[cxx, -cxy], [-cxy, cyy]])
        Px, Py = np.linalg.solve(M, np.array([-vt0[0], target_dvy]))
        regime = "sticking"
    v_out = (v_in[0] + Px / m, v_in[1] + Py / m)
    om_out = omega_in + (b * Px - a * Py) / inertia
    vt1 = _tip_velocity(v_out, om_out, a, b)
    mu_eff = abs(Px / Py)
    return ImpactTruth(angle, (float(v_in[0]), float(v_in[1])), float(omega_in),
                       (float(v_out[0]), float(v_out[1])), float(om_out),
                       (float(vt0[0]), float(vt0[1])), (float(vt1[0]), float(vt1[1])),
                       float(-vt1[1] / vt0[1]), float(mu_eff), regime)


def engine_impact(rod: Any, flat: Any, angle: float, v_in: tuple[float, float], *, mu: float,
                  **kwargs: Any) -> ImpactTruth:
    """The impact from the engine (``impactlab.dynamics.simulate``, finite contact duration);
    ImportError when the engine is not installed. Extra keyword arguments go to ``simulate``.
    ``mu`` of the truth is the contact's impulse ratio (the gravity impulse excluded), e the
    engine's normal restitution of the contact point."""
    from impactlab.dynamics import simulate  # type: ignore[attr-defined,unused-ignore]

    res = simulate(rod, flat, mu=mu, angle=angle, velocity=(float(v_in[0]), float(v_in[1])),
                   history=True, **kwargs)
    vo = (float(res.velocity_out[0]), float(res.velocity_out[1]))
    h = res.history
    contact = np.column_stack([h.t, h.x, h.y, h.phi]) if h is not None else None
    return ImpactTruth(
        angle, (float(v_in[0]), float(v_in[1])), float(kwargs.get("spin", 0.0)), vo,
        float(res.spin_out), (float(res.vt_in), float(res.vn_in)),
        (float(res.vt_out), float(res.vn_out)), float(res.e),
        abs(float(res.tangential_impulse) / float(res.normal_impulse)), str(res.regime),
        float(res.duration), "engine", float(res.delta_p), float(res.sliding_length), contact)


def _rot_z(phi: np.ndarray) -> np.ndarray:
    c, s = np.cos(phi), np.sin(phi)
    R = np.zeros(phi.shape + (3, 3))
    R[..., 0, 0] = c
    R[..., 0, 1] = -s
    R[..., 1, 0] = s
    R[..., 1, 1] = c
    R[..., 2, 2] = 1.0
    return R


def marker_tracks(
    rod: Any,
    truth: ImpactTruth,
    *,
    markers: np.ndarray | None = None,
    labels: tuple[str, ...] | None = None,
    rate: float = 500.0,
    before: float = 0.10,
    after: float = 0.10,
    noise: float = 0.15e-3,
    occlusion: float = 0.02,
    occlusion_burst: int = 4,
    heading: float = 0.6,
    origin: tuple[float, float, float] = (0.21, -0.35, 0.012),
    up: str = "+z",
    release: bool = False,
    g: float = G0,
    seed: int = 0,
    impact_phase: float | None = None,
    second_impact: bool = False,
) -> tuple[MarkerTracks, dict[str, Any]]:
    """Marker positions [m] in a lab frame for the impact ``truth`` (free flight with gravity
    before and after; the impact at time ``before`` + a random sub-frame phase).

    ``heading`` [rad]: direction of the impact plane's x axis in the horizontal plane; ``origin``:
    the contact point in the lab [m]; ``up``: "+z" (Vicon style) or "+y"; ``noise``: Gaussian sigma
    per coordinate [m]; ``occlusion``: fraction of marker samples lost at random, plus one burst of
    ``occlusion_burst`` frames for one marker; ``release``: the rod hangs still until it is let go
    (needs v_x = omega = 0 before the impact). The record ends when the rod, turning after the
    impact, touches the flat again (its lowest point, capsule of radius R), unless
    ``second_impact``: then it bounces crudely and flies on. Returns (tracks, info) with the true
    impact time, the body-frame markers and the lab axes."""
    rng = np.random.default_rng(seed)
    half, R_tip = rod_dimensions(rod)
    mk = DEFAULT_MARKERS if markers is None else np.asarray(markers, dtype=np.float64)
    labels = labels or tuple(f"M{i + 1}" for i in range(mk.shape[0]))
    dt = 1.0 / rate
    phase = rng.uniform(0.2, 0.8) if impact_phase is None else impact_phase
    n_before = int(round(before * rate))
    n_after = int(round(after * rate))
    t = np.arange(n_before + n_after + 1) * dt
    t_imp = (n_before + phase) * dt  # between two frames
    tau = t - t_imp
    th0 = truth.angle
    c0 = np.array([half * math.cos(th0), half * math.sin(th0) + R_tip, 0.0])
    pos = np.zeros((t.size, 3))
    th = np.zeros(t.size)
    pre = tau < 0
    T = truth.duration if truth.contact is not None else 0.0
    end = np.array([c0[0], c0[1], th0])
    if T > 0:
        assert truth.contact is not None
        ct = truth.contact
        end = np.array([ct[-1, 1], ct[-1, 2], th0 + ct[-1, 3]])
        during = (tau >= 0) & (tau < T)
        pos[during, 0] = np.interp(tau[during], ct[:, 0], ct[:, 1])
        pos[during, 1] = np.interp(tau[during], ct[:, 0], ct[:, 2])
        th[during] = th0 + np.interp(tau[during], ct[:, 0], ct[:, 3])
    flying_after = tau >= T
    for sel, v, om, start, t0 in ((pre, truth.v_in, truth.omega_in, (c0[0], c0[1], th0), 0.0),
                                  (flying_after, truth.v_out, truth.omega_out, tuple(end), T)):
        ts = tau[sel] - t0
        pos[sel, 0] = start[0] + v[0] * ts
        pos[sel, 1] = start[1] + v[1] * ts - 0.5 * g * ts * ts
        pos[sel, 2] = 0.0
        th[sel] = start[2] + om * ts
    info: dict[str, Any] = {"t_impact": float(t_imp), "markers_body": mk, "labels": labels}
    # after the impact the rod may turn down onto the flat: the lowest point of the capsule (end
    # spheres of radius R at C -+ (L/2) u, u = tip -> C) reaches the flat at t2
    post = ~pre
    u_post = np.column_stack([np.cos(th[post]), np.sin(th[post])])
    low = np.minimum(pos[post, 1] - half * u_post[:, 1], pos[post, 1] + half * u_post[:, 1]) - R_tip
    hit = np.flatnonzero((low < 0) & (tau[post] > 2.0 * dt))
    t2 = float(t[post][hit[0]]) if hit.size else math.inf
    info["t_second_contact"] = t2
    if math.isfinite(t2):
        if second_impact:
            # a crude second impact: the rod bounces off with its vertical velocity reversed
            # (x 0.3) and its spin halved; the free flight continues from there
            sel = t >= t2
            ts2 = t2 - t_imp - T
            y2 = end[1] + truth.v_out[1] * ts2 - 0.5 * g * ts2 * ts2
            vy2 = -0.3 * (truth.v_out[1] - g * ts2)
            th2 = end[2] + truth.omega_out * ts2
            x2 = end[0] + truth.v_out[0] * ts2
            tt = t[sel] - t2
            pos[sel, 0] = x2 + truth.v_out[0] * tt
            pos[sel, 1] = y2 + vy2 * tt - 0.5 * g * tt * tt
            th[sel] = th2 + 0.5 * truth.omega_out * tt
        else:
            keep = t < t2
            t, tau, pos, th, pre = t[keep], tau[keep], pos[keep], th[keep], pre[keep]
    if release:
        if abs(truth.v_in[0]) > 0 or abs(truth.omega_in) > 0:
            raise ValueError("release=True needs v_x = omega = 0 before the impact")
        t_rel = t_imp + truth.v_in[1] / g  # v_y(t_rel) = 0
        held = t < t_rel
        ts_rel = t_rel - t_imp
        pos[held, 0] = c0[0]
        pos[held, 1] = c0[1] + truth.v_in[1] * ts_rel - 0.5 * g * ts_rel * ts_rel
        th[held] = th0
        info["t_release"] = float(t_rel)
    # body -> planar: rotation by theta + pi about z (e1 = -(cos th, sin th, 0))
    Rp = _rot_z(th + math.pi)
    planar = np.einsum("nij,mj->nmi", Rp, mk) + pos[:, None, :]
    # planar (x, y up, z) -> lab
    xh = np.array([math.cos(heading), math.sin(heading), 0.0])
    yh = np.array([0.0, 0.0, 1.0])
    if up == "+y":
        xh = np.array([math.cos(heading), 0.0, math.sin(heading)])
        yh = np.array([0.0, 1.0, 0.0])
    elif up != "+z":
        raise ValueError(f"up must be '+z' or '+y', got {up!r}")
    zh = np.cross(xh, yh)
    M = np.column_stack([xh, yh, zh])
    lab = planar @ M.T + np.asarray(origin, dtype=np.float64)
    lab = lab + noise * rng.standard_normal(lab.shape)
    n, m = lab.shape[:2]
    lost = rng.random((n, m)) < occlusion
    if occlusion_burst > 0 and n > 3 * occlusion_burst:
        j = int(rng.integers(m))
        k0 = int(rng.integers(n // 5, n // 3))
        lost[k0:k0 + occlusion_burst, j] = True
    lab[lost] = np.nan
    info.update({"axes": np.vstack([xh, yh, zh]), "occluded": lost, "truth": truth,
                 "com_lab": pos @ M.T + np.asarray(origin), "theta": th})
    return MarkerTracks(t, lab, tuple(labels), "synthetic", {"units": "m"}), info


def write_c3d(tracks: MarkerTracks, path: str | Path, *, units: str = "mm") -> Path:
    """Write ``tracks`` as a C3D file with ezc3d: float points in ``units``, residual -1 (invalid)
    for occluded samples, POINT:RATE from the tracks' frame rate."""
    import ezc3d

    fac = length_factor(units)
    c = ezc3d.c3d()
    c["parameters"]["POINT"]["RATE"]["value"] = [float(round(tracks.rate, 6))]
    c["parameters"]["POINT"]["LABELS"]["value"] = tuple(tracks.labels)
    c.add_parameter("POINT", "UNITS", units)
    n, m = tracks.n_frames, tracks.n_markers
    pts = np.ones((4, m, n))
    xyz = np.transpose(tracks.positions / fac, (2, 1, 0))  # (3, m, n)
    valid = tracks.valid.T  # (m, n)
    pts[:3] = np.where(np.isfinite(xyz), xyz, 0.0)
    c["data"]["points"] = pts
    res = np.where(valid, 0.5, -1.0)[None, :, :]
    c["data"]["meta_points"]["residuals"] = res
    p = Path(path)
    c.write(str(p))
    return p


# ----------------------------------------------------------------------------------------------
# dents
# ----------------------------------------------------------------------------------------------


@dataclass(frozen=True)
class GrooveTruth:
    """Exact metrics of :func:`groove_surface` (paraboloid envelope), SI: ``depth`` (delta_p),
    ``length`` (extent of the region z < 0 along the sliding direction), ``width`` (across, at the
    deepest point), ``sliding_length`` (= length - width, the paper's L_s), ``deepest`` (x along
    the groove from the path start [m]), ``x_start``, ``x_end`` (ends of the dent along the groove
    [m]), ``pileup`` (rim height [m])."""

    depth: float
    length: float
    width: float
    sliding_length: float
    deepest: float
    x_start: float
    x_end: float
    pileup: float


def _groove_D(x: np.ndarray, knots_s: np.ndarray, knots_p: np.ndarray, R: float) -> np.ndarray:
    """Centre-line penetration D(x) = max_s [p(s) - (x - s)^2 / (2 R)] for piecewise-linear p."""
    x = np.asarray(x, dtype=np.float64)
    best = np.full(x.shape, -np.inf)
    for i in range(knots_s.size - 1):
        s0, s1 = knots_s[i], knots_s[i + 1]
        p0, p1 = knots_p[i], knots_p[i + 1]
        k = (p1 - p0) / (s1 - s0)
        s = np.clip(x + k * R, s0, s1)
        val = p0 + k * (s - s0) - (x - s) ** 2 / (2.0 * R)
        best = np.maximum(best, val)
    return best


def _groove_truth(knots_s: np.ndarray, knots_p: np.ndarray, R: float, pileup: float
                  ) -> GrooveTruth:
    i_m = int(np.argmax(knots_p))
    s_m, p_m = float(knots_s[i_m]), float(knots_p[i_m])

    def D(x: float) -> float:
        return float(_groove_D(np.array([x]), knots_s, knots_p, R)[0])

    span = math.sqrt(2.0 * R * p_m) + 1e-3
    x0 = brentq(D, knots_s[0] - span, s_m, xtol=1e-13)
    x1 = brentq(D, s_m, knots_s[-1] + span, xtol=1e-13)
    width = 2.0 * math.sqrt(2.0 * R * p_m)
    return GrooveTruth(p_m, x1 - x0, width, x1 - x0 - width, s_m, x0, x1, pileup)


def groove_surface(
    X: np.ndarray, Y: np.ndarray, *, depth: float, path: float, tip_radius: float,
    peak_at: float = 0.7, end_depth: float = 0.35, start: tuple[float, float] = (0.0, 0.0),
    direction: float = 0.0, pileup: float = 0.0,
) -> tuple[np.ndarray, GrooveTruth]:
    """Height [m] of an analytic sliding dent on the grid (X, Y) [m] (flat surface at 0).

    The tip sphere (radius ``tip_radius``, paraboloid approximation) slides a distance ``path``
    from ``start`` in the direction ``direction`` [rad, from the +X axis]; its penetration rises
    linearly to ``depth`` at ``peak_at`` * path and falls linearly to ``end_depth`` * depth at the
    end. The permanent surface is the envelope -max(0, D(x) - y^2 / (2R)) with D as in
    :func:`_groove_D` (x along, y across the path). ``pileup`` [m]: height of a rim just outside
    the dent (zero at the dent's edge, so the deformed area is unchanged). Returns (height, truth).
    """
    if not (0.0 < peak_at < 1.0) or not (0.0 <= end_depth <= 1.0):
        raise ValueError("peak_at must lie in (0, 1) and end_depth in [0, 1]")
    cphi, sphi = math.cos(direction), math.sin(direction)
    dx = X - start[0]
    dy = Y - start[1]
    xl = dx * cphi + dy * sphi
    yl = -dx * sphi + dy * cphi
    knots_s = np.array([0.0, peak_at * path, path])
    knots_p = np.array([0.0, depth, end_depth * depth])
    D = _groove_D(xl, knots_s, knots_p, tip_radius)
    q = D - yl * yl / (2.0 * tip_radius)
    z = -np.maximum(q, 0.0)
    if pileup > 0:
        q0 = 0.08 * depth
        r = np.clip(-q, 0.0, None) / q0
        z = z + np.where(q < 0, pileup * r * np.exp(1.0 - r), 0.0)
    return z, _groove_truth(knots_s, knots_p, tip_radius, pileup)


@dataclass(frozen=True)
class ScanTruth:
    """A synthetic scan's truth: the groove metrics, its placement (start [m], direction [rad]),
    noise sigma [m], the tilt plane coefficients (a, b, c) and the dropout mask."""

    groove: GrooveTruth
    start: tuple[float, float]
    direction: float
    noise: float
    plane: tuple[float, float, float]
    dropouts: np.ndarray


def synthetic_scan(
    *, depth: float = 22e-6, sliding_length: float = 1400e-6, tip_radius: float = 8.8e-3,
    pixel: float = 8e-6, margin: float = 0.8e-3, direction: float = 0.35, peak_at: float = 0.7,
    end_depth: float = 0.35, pileup: float = 1.5e-6, noise: float = 0.1e-6,
    tilt: tuple[float, float] = (1.5e-3, -0.8e-3), offset: float = 3e-6, dropouts: float = 0.01,
    seed: int = 0,
) -> tuple[np.ndarray, float, float, ScanTruth]:
    """A levelled-then-tilted, noisy height map (ny, nx) [m] with a groove whose paper metrics are
    ``depth`` (delta_p) and ``sliding_length`` (L_s = length - width), NaN dropouts (random pixels
    plus one cluster inside the dent); returns (heights, dx, dy, truth)."""
    rng = np.random.default_rng(seed)

    def ls_of(path: float) -> float:
        knots_s = np.array([0.0, peak_at * path, path])
        knots_p = np.array([0.0, depth, end_depth * depth])
        return _groove_truth(knots_s, knots_p, tip_radius, 0.0).sliding_length - sliding_length

    hi = sliding_length * 3 + 3e-3
    path = brentq(ls_of, 1e-7, hi, xtol=1e-12) if ls_of(1e-7) < 0 < ls_of(hi) else sliding_length
    width = 2.0 * math.sqrt(2.0 * tip_radius * depth)
    # bounding box of the dent in the scan: lay the groove out then add the margin
    probe = _groove_truth(np.array([0.0, peak_at * path, path]),
                          np.array([0.0, depth, end_depth * depth]), tip_radius, pileup)
    L = probe.length
    cphi, sphi = math.cos(direction), math.sin(direction)
    ext_x = abs(L * cphi) + abs(width * sphi)
    ext_y = abs(L * sphi) + abs(width * cphi)
    nx = int(math.ceil((ext_x + 2 * margin) / pixel))
    ny = int(math.ceil((ext_y + 2 * margin) / pixel))
    x = (np.arange(nx) + 0.5) * pixel
    y = (np.arange(ny) + 0.5) * pixel
    X, Y = np.meshgrid(x, y)
    mid = ((probe.x_start + probe.x_end) / 2.0)
    cx, cy = nx * pixel / 2.0, ny * pixel / 2.0
    start = (cx - mid * cphi + rng.uniform(-0.5, 0.5) * pixel,
             cy - mid * sphi + rng.uniform(-0.5, 0.5) * pixel)
    z, truth = groove_surface(X, Y, depth=depth, path=path, tip_radius=tip_radius,
                              peak_at=peak_at, end_depth=end_depth, start=start,
                              direction=direction, pileup=pileup)
    plane = (offset, tilt[0], tilt[1])
    z = z + plane[0] + plane[1] * X + plane[2] * Y + noise * rng.standard_normal(z.shape)
    drop = rng.random(z.shape) < dropouts
    if dropouts > 0:
        # a small cluster of lost pixels on the dent's flank (steep walls lose light)
        xc = start[0] + (truth.deepest * 0.5) * cphi - 0.3 * width * sphi
        yc = start[1] + (truth.deepest * 0.5) * sphi + 0.3 * width * cphi
        drop |= (X - xc) ** 2 + (Y - yc) ** 2 < (3.0 * pixel) ** 2
    z[drop] = np.nan
    return z, pixel, pixel, ScanTruth(truth, start, direction, noise, plane, drop)


# ----------------------------------------------------------------------------------------------
# scan writers
# ----------------------------------------------------------------------------------------------


def _write_sdf_ascii(z: np.ndarray, dx: float, dy: float, path: Path) -> None:
    ny, nx = z.shape
    lines = [
        "aISO-1.0",
        "ManufacID   = impactlab",
        "CreateDate  = 010120250000",
        "ModDate     = 010120250000",
        f"NumPoints   = {nx}",
        f"NumProfiles = {ny}",
        f"Xscale      = {dx:.10e}",
        f"Yscale      = {dy:.10e}",
        "Zscale      = 1.0e-6",
        "Zresolution = -1",
        "Compression = 0",
        "DataType    = 7",
        "CheckType   = 0",
        "*",
    ]
    zu = z * 1e6
    for row in zu:
        lines.append(" ".join("BAD" if not np.isfinite(v) else f"{v:.6f}" for v in row))
    lines.append("*")
    path.write_text("\n".join(lines) + "\n", encoding="ascii")


def _write_sdf_binary(z: np.ndarray, dx: float, dy: float, path: Path) -> None:
    ny, nx = z.shape
    head = struct.pack("<8s10s12s12sHHddddBBB", b"bISO-1.0", b"impactlab", b"010120250000",
                       b"010120250000", nx, ny, dx, dy, 1.0e-6, -1.0, 0, 7, 0)
    data = (z * 1e6).astype("<f8").tobytes()  # NaN marks invalid points for floating types
    path.write_bytes(head + data)


def write_scan(z: np.ndarray, dx: float, dy: float, path: str | Path, *, fmt: str | None = None
               ) -> Path:
    """Write a height map (ny, nx) [m], pixel sizes dx, dy [m] (NaN = no data).

    ``fmt`` (default from the extension): "x3p", "gwy", "nc" (SurfaceTopography's writers),
    "sdf" (ISO 25178-71 ASCII), "sdf-binary", "npy" (metres), "csv" (micrometres, with
    '# pixel_size' and '# height_unit' comment lines)."""
    p = Path(path)
    fmt = (fmt or p.suffix.lstrip(".")).lower()
    z = np.asarray(z, dtype=np.float64)
    if fmt in ("x3p", "gwy", "nc"):
        from SurfaceTopography import Topography

        ny, nx = z.shape
        topo = Topography(np.ma.masked_invalid(z.T), (nx * dx, ny * dy), unit="m")
        {"x3p": topo.to_x3p, "gwy": topo.to_gwy, "nc": topo.to_netcdf}[fmt](str(p))
    elif fmt == "sdf":
        _write_sdf_ascii(z, dx, dy, p)
    elif fmt == "sdf-binary":
        _write_sdf_binary(z, dx, dy, p)
    elif fmt == "npy":
        np.save(p, z)
    elif fmt == "csv":
        with p.open("w", encoding="utf-8") as fh:
            fh.write(f"# pixel_size: {dx * 1e6:.6g} um\n# height_unit: um\n")
            if dy != dx:
                fh.write(f"# pixel_size_y: {dy * 1e6:.6g} um\n")
            for row in z * 1e6:
                fh.write(",".join("" if not np.isfinite(v) else f"{v:.5f}" for v in row) + "\n")
    else:
        raise ValueError(f"unknown scan format {fmt!r}; use x3p, gwy, nc, sdf, sdf-binary, npy or "
                         "csv")
    return p
