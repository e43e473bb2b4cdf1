"""Measure the impact from marker tracks: :func:`measure_impact` (steps in the package docstring).

``measure_impact`` runs the steps in order; each step is one function here: the marker cluster
and its poses, the impact detection, the free-flight segments, the gravity check, the centre of
mass and axis, the impact frame, the ballistic fits and the propagated uncertainties.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.experiment.errors import MarkerError, TooFewFramesError
from impactlab.experiment.kinematics.com import estimate_com
from impactlab.experiment.kinematics.derive import DERIVED, derive
from impactlab.experiment.kinematics.detect import detect_impact, free_flight
from impactlab.experiment.kinematics.fits import SegmentFit, fit_segment, segment_data, trimmed_fit
from impactlab.experiment.kinematics.frame import G0, parse_up, rod_dimensions
from impactlab.experiment.kinematics.result import ImpactKinematics
from impactlab.experiment.markers import MarkerTracks
from impactlab.experiment.rigid import (
    MarkerGeometry,
    Poses,
    check_rigidity,
    fit_poses,
    reference_cluster,
)
from impactlab.experiment.uncertainty import Estimate, propagate

__all__ = ["measure_impact"]

#: Units of the derived quantities (order ``DERIVED``).
_UNITS = (
    "s",
    "rad",
    "rad",
    "m/s",
    "m/s",
    "rad/s",
    "m/s",
    "m/s",
    "rad/s",
    "m/s",
    "m/s",
    "m/s",
    "m/s",
    "",
    "",
    "m/s",
    "m/s",
    "m/s",
    "m/s",
)


def _check_options(
    tracks: MarkerTracks,
    guard: int,
    window: int,
    min_fit_frames: int,
    max_fit_frames: int,
    src: str,
) -> None:
    if guard < 1 or window < 2 or min_fit_frames < 4 or max_fit_frames < min_fit_frames:
        raise ValueError(
            f"need guard >= 1, window >= 2, min_fit_frames >= 4 and max_fit_frames >= "
            f"min_fit_frames; got {guard}, {window}, {min_fit_frames}, "
            f"{max_fit_frames}"
        )
    if tracks.n_markers < 3:
        raise MarkerError(
            f"{src}: {tracks.n_markers} markers; at least 3 are needed for the rod's pose"
        )


def _check_derived(y: np.ndarray, src: str) -> None:
    """The derived quantities must be finite, with the tip approaching the flat."""
    if not np.all(np.isfinite(y)):
        raise MarkerError(
            f"{src}: the fits give no finite impact velocities (tip velocity "
            "before the impact is zero?)"
        )
    if y[10] >= 0:
        raise MarkerError(
            f"{src}: the tip is not moving towards the flat before the impact "
            f"(v_tip,y = {y[10]:.3g} m/s); check up="
        )


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


def _gravity(
    poses: Poses,
    fr: np.ndarray,
    t_ref: float,
    upv: np.ndarray,
    g: float,
    src: str,
    warnings: list[str],
) -> float | None:
    """Free quadratic fit of the cluster origin before the impact (C when the geometry is given;
    the rod hardly turns before the impact in a drop test): the fitted gravity [m/s^2] (None
    when too uncertain); MarkerError when it points away from -up."""
    if fr.size < 8:
        return None
    tau = poses.time[fr] - t_ref
    c_lab = poses.translation[fr]
    A = np.column_stack([np.ones_like(tau), tau, 0.5 * tau * tau])
    coef, _res, *_ = np.linalg.lstsq(A, c_lab, rcond=None)
    E = c_lab - A @ coef
    s2 = np.sum(E * E, axis=0) / max(fr.size - 3, 1)
    var_a = np.linalg.inv(A.T @ A)[2, 2] * s2
    a = coef[2]
    sig_a = float(np.sqrt(np.sum(var_a)))
    if not sig_a < 0.2 * g:
        return None
    fitted_g = float(np.linalg.norm(a))
    cosang = float(-(a @ upv) / max(np.linalg.norm(a), 1e-30))
    if not (0.5 * g < fitted_g < 2.0 * g):
        warnings.append(
            f"the free fall before the impact accelerates at {fitted_g:.3g} "
            f"m/s^2, not g = {g:.4g}: check the length units"
        )
    elif cosang < math.cos(math.radians(25.0)):
        dirn = ", ".join(f"{v:+.2f}" for v in (-a / np.linalg.norm(a)))
        raise MarkerError(
            f"{src}: gravity in the data points down along ({dirn}) in camera "
            f"coordinates, {math.degrees(math.acos(max(-1, min(1, cosang)))):.0f} deg "
            f"away from -up; pass the right up= (e.g. up='+y')"
        )
    return fitted_g


@dataclass(frozen=True)
class _Body:
    """Centre of mass ``com`` and axis ``axis`` (towards the tip) in the reference cluster's
    frame; ``com_cov`` (3, 3) [m^2] when estimated (None when given); ``source``."""

    com: np.ndarray
    axis: np.ndarray
    com_cov: np.ndarray | None
    source: str


def _estimated_body(
    poses: Poses,
    reference: np.ndarray,
    pre_fr: np.ndarray,
    post_fr: np.ndarray,
    t_ref: float,
    upv: np.ndarray,
    g: float,
    max_com_sigma: float,
    src: str,
) -> _Body:
    """The axis from the cluster's principal direction, C as the ballistic body point."""
    _, _, vt = np.linalg.svd(reference - reference.mean(axis=0))
    axis_body = vt[0]
    k_last = pre_fr[-1]
    if (poses.rotation[k_last] @ axis_body) @ upv > 0:
        axis_body = -axis_body  # e1 points to the lower end (the tip) at impact
    com_body, com_cov = estimate_com(poses, [pre_fr, post_fr], t_ref, upv, g)
    sig_axis = (
        float(np.sqrt(max(axis_body @ com_cov @ axis_body, 0.0)))
        if np.all(np.isfinite(com_cov))
        else math.inf
    )
    if not sig_axis < max_com_sigma:
        raise MarkerError(
            f"{src}: cannot locate the rod's centre of mass from the flight precisely enough "
            f"(+-{sig_axis * 1e3:.2g} mm along the axis, limit {max_com_sigma * 1e3:.2g} mm: "
            "too little rotation or too few frames after the impact); give the marker "
            "geometry (the markers' positions relative to the rod axis)"
        )
    return _Body(
        com_body,
        axis_body,
        com_cov,
        f"estimated (centre of mass +- {sig_axis * 1e3:.2g} mm along the axis)",
    )


def _impact_frame(
    poses: Poses, k_last: int, body: _Body, upv: np.ndarray, src: str
) -> tuple[np.ndarray, np.ndarray]:
    """(axes (3, 3): rows x, y = up, z of the impact frame; origin: C at the last frame before
    the impact [m]); x is the horizontal direction from the tip towards C."""
    Rk = poses.rotation[k_last]
    e1_lab = Rk @ body.axis
    if e1_lab @ upv >= 0:
        raise MarkerError(
            f"{src}: the rod's tip (+e1 end of the marker geometry) is not below "
            "its centre of mass before the impact; check the geometry's axis "
            "direction (e1 points from the centre of mass to the tip) and up="
        )
    u = -e1_lab
    uh = u - (u @ upv) * upv
    if np.linalg.norm(uh) < 1e-3:
        raise MarkerError(
            f"{src}: the rod is vertical at the impact; the impact plane (x axis) is undefined"
        )
    xh = uh / np.linalg.norm(uh)
    zh = np.cross(xh, upv)
    return np.vstack([xh, upv, zh]), Rk @ body.com + poses.translation[k_last]


@dataclass(frozen=True)
class _Frame:
    """What the fits need: the poses, the impact frame (``axes``, ``origin``), ``t_ref`` [s],
    gravity ``g`` [m/s^2], the rod's ``half`` length and ``R_tip`` [m]."""

    poses: Poses
    axes: np.ndarray
    origin: np.ndarray
    t_ref: float
    g: float
    half: float
    R_tip: float


def _fits(
    fm: _Frame,
    pre_fr: np.ndarray,
    post_fr: np.ndarray,
    body: _Body,
    upv: np.ndarray,
    min_fit_frames: int,
    src: str,
    warnings: list[str],
) -> tuple[SegmentFit, SegmentFit, _Body]:
    """The ballistic fits before and after the impact, trimmed at their far ends; an estimated
    centre of mass is re-estimated on the trimmed segments."""

    def fit(fr: np.ndarray, far_end: str, b: _Body) -> SegmentFit:
        return trimmed_fit(
            fm.poses, fr, far_end, fm.t_ref, b.com, b.axis, fm.axes, fm.origin, fm.g, min_fit_frames
        )

    pre, post = fit(pre_fr, "start", body), fit(post_fr, "end", body)
    for name, seg in (("before", pre), ("after", post)):
        if seg.n < min_fit_frames:
            raise TooFewFramesError(
                f"{src}: only {seg.n} ballistic free-flight frames {name} the impact at "
                f"t = {fm.t_ref:.4f} s; need at least {min_fit_frames}"
            )
        if seg.trimmed:
            warnings.append(
                f"{seg.trimmed} non-ballistic frames dropped at the far end of the "
                f"fit {name} the impact"
            )
    if body.com_cov is not None and (pre.trimmed or post.trimmed):
        com, com_cov = estimate_com(fm.poses, [pre.frames, post.frames], fm.t_ref, upv, fm.g)
        body = _Body(com, body.axis, com_cov, body.source)
        pre, post = fit(pre.frames, "start", body), fit(post.frames, "end", body)
    return pre, post, body


def _propagated(
    fm: _Frame, pre: SegmentFit, post: SegmentFit, body: _Body
) -> tuple[np.ndarray, np.ndarray, list[str]]:
    """The derived quantities (order ``DERIVED``), their covariance (the fits' and, for an
    estimated centre of mass, its own, by refitting with C moved) and the crossing notes."""
    tau_lo = float(fm.poses.time[pre.frames[-1]] - fm.t_ref)
    tau_hi = float(fm.poses.time[post.frames[0]] - fm.t_ref)
    notes: list[str] = []

    def derived(x: np.ndarray) -> np.ndarray:
        return derive(x, fm.t_ref, tau_lo, tau_hi, fm.g, fm.half, fm.R_tip, notes)

    x0 = np.concatenate([pre.coef.T.ravel(), post.coef.T.ravel()])
    cov0 = np.zeros((16, 16))
    cov0[:8, :8] = pre.cov
    cov0[8:, 8:] = post.cov
    y, cov_y = propagate(derived, x0, cov0)
    if body.com_cov is not None:
        sig_p = np.sqrt(np.clip(np.diag(body.com_cov), 0.0, None))
        Jp = np.zeros((y.size, 3))
        for j in range(3):
            h = max(sig_p[j], 1e-6)
            ys = []
            for sgn in (1.0, -1.0):
                cb = body.com.copy()
                cb[j] += sgn * h
                xs = []
                for seg in (pre, post):
                    tau = fm.poses.time[seg.frames] - fm.t_ref
                    data = segment_data(fm.poses, seg.frames, cb, body.axis, fm.axes, fm.origin)
                    xs.append(fit_segment(tau, data, fm.g)[0].T.ravel())
                ys.append(derived(np.concatenate(xs)))
            Jp[:, j] = (ys[0] - ys[1]) / (2.0 * h)
        cov_y = cov_y + Jp @ body.com_cov @ Jp.T
    return y, cov_y, notes


def _plausibility(
    E_: dict[str, Estimate],
    poses: Poses,
    pre: SegmentFit,
    axis_body: np.ndarray,
    zh: np.ndarray,
    warnings: list[str],
) -> float:
    """Warnings for an angle outside (0, 90) deg, an out-of-plane rod or motion; returns the
    rod axis's median out-of-plane tilt before the impact [rad]."""
    if not 0.0 < E_["angle_in"].value < 0.5 * math.pi:
        warnings.append(
            f"rod angle at impact {math.degrees(E_['angle_in'].value):.1f} deg is "
            "outside (0, 90) deg"
        )
    u_pre = -np.einsum("nij,j->ni", poses.rotation[pre.frames], axis_body)
    tilt = float(np.median(np.arcsin(np.clip(u_pre @ zh, -1, 1))))
    if abs(tilt) > math.radians(5):
        warnings.append(
            f"the rod axis leaves the vertical impact plane by "
            f"{math.degrees(tilt):.1f} deg before the impact"
        )
    vz_max = max(abs(E_["v_cz_in"].value), abs(E_["v_cz_out"].value))
    if vz_max > 0.1 * abs(E_["v_tip_y_in"].value):
        warnings.append(
            f"out-of-plane centre-of-mass velocity up to {vz_max:.3g} m/s: the "
            "motion is not planar, the planar analysis is approximate"
        )
    return tilt


def _poses(
    tracks: MarkerTracks,
    geometry: MarkerGeometry | None,
    rigidity_tolerance: float,
    rigidity_window: int,
    min_fit_frames: int,
    src: str,
) -> tuple[Any, ...]:
    """(reference cluster, rigidity report, poses, frames with a pose)."""
    tracks, reference = _cluster(tracks, geometry, src)
    rigidity = check_rigidity(tracks, tolerance=rigidity_tolerance, window=rigidity_window)
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
    """Measure the impact from marker tracks (steps and frame in the package docstring).

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
    _check_options(tracks, guard, window, min_fit_frames, max_fit_frames, src)
    reference, rigidity, poses, ok = _poses(
        tracks, geometry, rigidity_tolerance, rigidity_window, min_fit_frames, src
    )
    imp = detect_impact(poses, ok, reference, upv, g, window, src)
    t_ref = imp.t_ref
    pre_fr, post_fr = free_flight(poses, ok, imp, guard, max_fit_frames, min_fit_frames, src)
    fitted_g = _gravity(poses, pre_fr, t_ref, upv, g, src, warnings)
    if geometry is not None:
        body = _Body(np.zeros(3), np.array([1.0, 0.0, 0.0]), None, "given")
    else:
        body = _estimated_body(poses, reference, pre_fr, post_fr, t_ref, upv, g, max_com_sigma, src)
    axes, origin = _impact_frame(poses, int(pre_fr[-1]), body, upv, src)
    fm = _Frame(poses, axes, origin, t_ref, g, half, R_tip)
    pre, post, body = _fits(fm, pre_fr, post_fr, body, upv, min_fit_frames, src, warnings)
    y, cov_y, notes = _propagated(fm, pre, post, body)
    warnings += notes
    _check_derived(y, src)
    sig = np.sqrt(np.clip(np.diag(cov_y), 0.0, None))
    E_ = {n: Estimate(v, s, u_) for n, v, s, u_ in zip(DERIVED, y, sig, _UNITS, strict=True)}
    tilt = _plausibility(E_, poses, pre, body.axis, axes[2], warnings)
    return ImpactKinematics(
        t_impact=E_["t_impact"],
        angle_in=E_["angle_in"],
        angle_out=E_["angle_out"],
        v_c_in=(E_["v_cx_in"], E_["v_cy_in"]),
        v_c_out=(E_["v_cx_out"], E_["v_cy_out"]),
        spin_in=E_["spin_in"],
        spin_out=E_["spin_out"],
        v_tip_in=(E_["v_tip_x_in"], E_["v_tip_y_in"]),
        v_tip_out=(E_["v_tip_x_out"], E_["v_tip_y_out"]),
        e=E_["e"],
        mu=E_["mu"],
        dv_cx=E_["dv_cx"],
        dv_cy=E_["dv_cy"],
        v_c_z_in=E_["v_cz_in"],
        v_c_z_out=E_["v_cz_out"],
        derived_names=DERIVED,
        derived_values=y,
        derived_cov=cov_y,
        pre=pre,
        post=post,
        impact_frame=imp.k_star,
        t_ref=t_ref,
        gravity=g,
        half_length=half,
        tip_radius=R_tip,
        frame_axes=axes,
        origin=origin,
        com_body=body.com,
        axis_body=body.axis,
        geometry_source=body.source,
        rigidity=rigidity,
        fitted_gravity=fitted_g,
        tilt_out_of_plane=tilt,
        poses=poses,
        warnings=tuple(warnings),
    )
