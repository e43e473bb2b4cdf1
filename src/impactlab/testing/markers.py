"""Synthetic marker tracks of a drop with a known impact, and a C3D writer.

:func:`marker_tracks` films three (or more) markers on the rod at 500 fps: free flight with
gravity before and after the impact (through the contact along the engine's history when the
truth has one), an optional hold-and-release phase, Gaussian noise and occlusions.
:func:`write_c3d` writes them as a real C3D file (ezc3d, residual -1 for occluded samples).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import ezc3d
import numpy as np

from impactlab.bodies import lever_arms
from impactlab.experiment.kinematics import G0, rod_dimensions
from impactlab.experiment.markers import MarkerTracks, length_factor
from impactlab.testing.impacts import ImpactTruth

__all__ = ["ALIGNED_MARKERS", "DEFAULT_MARKERS", "marker_tracks", "write_c3d"]

#: Marker positions in the rod body frame [m] (origin C, e1 towards the tip): spread along the
#: upper half of the rod on short stubs, non-collinear.
DEFAULT_MARKERS = np.array(
    [
        [-0.030, 0.018, 0.000],
        [-0.090, 0.000, 0.022],
        [-0.130, -0.020, 0.004],
    ]
)

#: A layout for the estimated-geometry mode: the two outer markers on one side of the rod, the
#: middle one on the other, so the cluster's principal axis is parallel to the rod axis.
ALIGNED_MARKERS = np.array(
    [
        [-0.020, 0.012, 0.000],
        [-0.075, -0.006, 0.0104],
        [-0.130, 0.012, 0.000],
    ]
)


@dataclass
class _Motion:
    """The rod's planar motion per frame: time t [s], tau = t - t_impact [s], pos (n, 3) of C [m],
    th (n,) rod angle [rad]; ``end`` (x, y, angle) at separation; ``T`` contact duration [s]."""

    t: np.ndarray
    tau: np.ndarray
    pos: np.ndarray
    th: np.ndarray
    end: np.ndarray
    T: float


def _rot_z(phi: np.ndarray) -> np.ndarray:
    c, s = np.cos(phi), np.sin(phi)
    R = np.zeros((*phi.shape, 3, 3))
    R[..., 0, 0] = c
    R[..., 0, 1] = -s
    R[..., 1, 0] = s
    R[..., 1, 1] = c
    R[..., 2, 2] = 1.0
    return R


def _planar_motion(
    truth: ImpactTruth, t: np.ndarray, t_imp: float, c0: np.ndarray, g: float
) -> _Motion:
    """Free flight before and after the impact, the engine's history through the contact."""
    tau = t - t_imp
    th0 = truth.angle
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
    for sel, v, om, start, t0 in (
        (pre, truth.v_in, truth.spin_in, (c0[0], c0[1], th0), 0.0),
        (flying_after, truth.v_out, truth.spin_out, tuple(end), T),
    ):
        ts = tau[sel] - t0
        pos[sel, 0] = start[0] + v[0] * ts
        pos[sel, 1] = start[1] + v[1] * ts - 0.5 * g * ts * ts
        pos[sel, 2] = 0.0
        th[sel] = start[2] + om * ts
    return _Motion(t, tau, pos, th, end, T)


def _second_contact(mo: _Motion, half: float, R_tip: float, dt: float) -> float:
    """Time [s] when the rod, turning after the impact, touches the flat again (the lowest point
    of the capsule: end spheres of radius R at C -+ (L/2) u, u = tip -> C); inf if never."""
    post = mo.tau >= 0
    u_post = np.column_stack([np.cos(mo.th[post]), np.sin(mo.th[post])])
    low = (
        np.minimum(mo.pos[post, 1] - half * u_post[:, 1], mo.pos[post, 1] + half * u_post[:, 1])
        - R_tip
    )
    hit = np.flatnonzero((low < 0) & (mo.tau[post] > 2.0 * dt))
    return float(mo.t[post][hit[0]]) if hit.size else math.inf


def _bounce(mo: _Motion, truth: ImpactTruth, t2: float, t_imp: float, g: float) -> None:
    """A crude second impact at ``t2``: the rod bounces off with its vertical velocity reversed
    (x 0.3) and its spin halved; the free flight continues from there."""
    end = mo.end
    sel = mo.t >= t2
    ts2 = t2 - t_imp - mo.T
    y2 = end[1] + truth.v_out[1] * ts2 - 0.5 * g * ts2 * ts2
    vy2 = -0.3 * (truth.v_out[1] - g * ts2)
    th2 = end[2] + truth.spin_out * ts2
    x2 = end[0] + truth.v_out[0] * ts2
    tt = mo.t[sel] - t2
    mo.pos[sel, 0] = x2 + truth.v_out[0] * tt
    mo.pos[sel, 1] = y2 + vy2 * tt - 0.5 * g * tt * tt
    mo.th[sel] = th2 + 0.5 * truth.spin_out * tt


def _hold(mo: _Motion, truth: ImpactTruth, c0: np.ndarray, t_imp: float, g: float) -> float:
    """The rod hangs still until it is let go; returns the release time [s]."""
    if abs(truth.v_in[0]) > 0 or abs(truth.spin_in) > 0:
        raise ValueError("release=True needs v_x = spin = 0 before the impact")
    t_rel = t_imp + truth.v_in[1] / g  # v_y(t_rel) = 0
    held = mo.t < t_rel
    ts_rel = t_rel - t_imp
    mo.pos[held, 0] = c0[0]
    mo.pos[held, 1] = c0[1] + truth.v_in[1] * ts_rel - 0.5 * g * ts_rel * ts_rel
    mo.th[held] = truth.angle
    return float(t_rel)


def _lab_axes(heading: float, up: str) -> np.ndarray:
    """(3, 3) matrix whose columns are the planar x, y (up), z axes in the lab."""
    xh = np.array([math.cos(heading), math.sin(heading), 0.0])
    yh = np.array([0.0, 0.0, 1.0])
    if up == "+y":
        xh = np.array([math.cos(heading), 0.0, math.sin(heading)])
        yh = np.array([0.0, 1.0, 0.0])
    elif up != "+z":
        raise ValueError(f"up must be '+z' or '+y', got {up!r}")
    zh = np.cross(xh, yh)
    return np.column_stack([xh, yh, zh])


def _observe(
    lab: np.ndarray, rng: np.random.Generator, noise: float, occlusion: float, burst: int
) -> tuple[np.ndarray, np.ndarray]:
    """Add the camera noise and the occlusions (random samples plus one burst of ``burst`` frames
    for one marker); returns (positions with NaN where lost, lost mask)."""
    lab = lab + noise * rng.standard_normal(lab.shape)
    n, m = lab.shape[:2]
    lost = rng.random((n, m)) < occlusion
    if burst > 0 and n > 3 * burst:
        j = int(rng.integers(m))
        k0 = int(rng.integers(n // 5, n // 3))
        lost[k0 : k0 + burst, j] = True
    lab[lost] = np.nan
    return lab, lost


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
    (needs v_x = spin = 0 before the impact). The record ends when the rod, turning after the
    impact, touches the flat again (its lowest point, capsule of radius R), unless
    ``second_impact``: then it bounces crudely and flies on. Returns (tracks, info); info holds
    "t_impact" [s], "t_second_contact" [s] (inf if none), "t_release" [s] (with ``release``),
    "markers_body", "labels", "axes" (rows: the impact plane's x, y, z in the lab), "occluded",
    "truth", "com_lab" (C in the lab [m]) and "angle" (the rod angle per frame [rad])."""
    rng = np.random.default_rng(seed)
    half, R_tip = rod_dimensions(rod)
    mk = DEFAULT_MARKERS if markers is None else np.asarray(markers, dtype=np.float64)
    labels = labels or tuple(f"M{i + 1}" for i in range(mk.shape[0]))
    dt = 1.0 / rate
    phase = rng.uniform(0.2, 0.8) if impact_phase is None else impact_phase
    n_before = round(before * rate)
    n_after = round(after * rate)
    t = np.arange(n_before + n_after + 1) * dt
    t_imp = (n_before + phase) * dt  # between two frames
    a, b = lever_arms(half, R_tip, truth.angle)
    c0 = np.array([a, b, 0.0])
    mo = _planar_motion(truth, t, t_imp, c0, g)
    info: dict[str, Any] = {"t_impact": float(t_imp), "markers_body": mk, "labels": labels}
    t2 = _second_contact(mo, half, R_tip, dt)
    info["t_second_contact"] = t2
    if math.isfinite(t2):
        if second_impact:
            _bounce(mo, truth, t2, t_imp, g)
        else:
            keep = mo.t < t2
            mo = _Motion(mo.t[keep], mo.tau[keep], mo.pos[keep], mo.th[keep], mo.end, mo.T)
    if release:
        info["t_release"] = _hold(mo, truth, c0, t_imp, g)
    # body -> planar: rotation by theta + pi about z (e1 = -(cos th, sin th, 0)); planar -> lab
    Rp = _rot_z(mo.th + math.pi)
    planar = np.einsum("nij,mj->nmi", Rp, mk) + mo.pos[:, None, :]
    M = _lab_axes(heading, up)
    lab = planar @ M.T + np.asarray(origin, dtype=np.float64)
    lab, lost = _observe(lab, rng, noise, occlusion, occlusion_burst)
    info.update(
        {
            "axes": M.T.copy(),
            "occluded": lost,
            "truth": truth,
            "com_lab": mo.pos @ M.T + np.asarray(origin),
            "angle": mo.th,
        }
    )
    return MarkerTracks(mo.t, lab, tuple(labels), "synthetic", {"units": "m"}), info


def write_c3d(tracks: MarkerTracks, path: str | Path, *, units: str = "mm") -> Path:
    """Write ``tracks`` as a C3D file with ezc3d: float points in ``units``, residual -1 (invalid)
    for occluded samples, POINT:RATE from the tracks' frame rate."""
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
