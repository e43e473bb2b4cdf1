"""From the impact frame to the estimates: the two ballistic fits (trimmed; an estimated centre of
mass refitted on the trimmed segments), the derived quantities with their propagated covariance
and units, their checks and the plausibility warnings (lengths in m, angles in rad, time in s)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.experiment.errors import MarkerError, TooFewFramesError
from impactlab.experiment.kinematics.body import RodBody
from impactlab.experiment.kinematics.com import estimate_com
from impactlab.experiment.kinematics.derive import derive
from impactlab.experiment.kinematics.fits import SegmentFit, fit_segment, segment_data, trimmed_fit
from impactlab.experiment.rigid import Poses
from impactlab.experiment.uncertainty import Estimate, propagate

__all__ = [
    "DERIVED_UNITS",
    "FitFrame",
    "check_derived",
    "impact_fits",
    "plausibility",
    "propagated",
]

#: Units of the derived quantities (order ``DERIVED``).
DERIVED_UNITS = (
    "s", "rad", "rad", "m/s", "m/s", "rad/s", "m/s", "m/s", "rad/s", "m/s", "m/s", "m/s", "m/s",
    "1", "1", "m/s", "m/s", "m/s", "m/s",
)  # fmt: skip


def check_derived(y: np.ndarray, src: str) -> None:
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


@dataclass(frozen=True)
class FitFrame:
    """What the fits need: the poses, the impact frame (``axes``, ``origin``), ``t_ref`` [s],
    gravity ``g`` [m/s^2], the rod's ``half`` length and ``R_tip`` [m]."""

    poses: Poses
    axes: np.ndarray
    origin: np.ndarray
    t_ref: float
    g: float
    half: float
    R_tip: float


def impact_fits(
    fm: FitFrame,
    pre_fr: np.ndarray,
    post_fr: np.ndarray,
    body: RodBody,
    upv: np.ndarray,
    min_fit_frames: int,
    src: str,
    warnings: list[str],
) -> tuple[SegmentFit, SegmentFit, RodBody]:
    """The ballistic fits before and after the impact, trimmed at their far ends; an estimated
    centre of mass is re-estimated on the trimmed segments."""

    def fit(fr: np.ndarray, far_end: str, b: RodBody) -> SegmentFit:
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
        body = RodBody(com, body.axis, com_cov, body.source)
        pre, post = fit(pre.frames, "start", body), fit(post.frames, "end", body)
    return pre, post, body


def propagated(
    fm: FitFrame, pre: SegmentFit, post: SegmentFit, body: RodBody
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


def plausibility(
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
