"""The rod in the marker data: gravity's direction, its centre of mass and axis, the impact
frame (steps of :func:`~impactlab.experiment.kinematics.measure_impact`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.kinematics.com import estimate_com
from impactlab.experiment.rigid import Poses

__all__ = ["RodBody", "estimated_body", "fitted_gravity", "impact_frame"]


def fitted_gravity(
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
    if not (0.5 * g < fitted_g < 2.0 * g):
        raise MarkerError(
            f"{src}: the free fall before the impact accelerates at {fitted_g:.3g} m/s^2, "
            f"{fitted_g / g:.3g} times g = {g:.4g} m/s^2: the time base or the length unit is "
            "wrong (check the frame rate, a C3D's POINT:RATE or the time column's unit, and "
            "the marker units); e and mu cannot be measured from it"
        )
    down = a / fitted_g
    tilt = math.degrees(math.acos(max(-1.0, min(1.0, float(-(down @ upv))))))
    dirn = ", ".join(f"{v:+.2f}" for v in down)
    if tilt > 25.0:
        raise MarkerError(
            f"{src}: gravity in the data points along ({dirn}) in camera coordinates, "
            f"{tilt:.0f} deg away from the downward direction -up that up= gives; pass "
            f"{suggested_up(-down)}"
        )
    # the fitted direction's own uncertainty [deg]: tilts within it are noise
    if tilt > max(TILT_WARN_DEG, 3.0 * math.degrees(sig_a / fitted_g)):
        warnings.append(
            f"gravity in the data points along ({dirn}), {tilt:.1f} deg away from -up: e, mu "
            "and the angle are measured in a frame tilted by as much (10 deg biases mu by "
            f"several percent); pass {suggested_up(-down, exact=True)}"
        )
    return fitted_g


#: A tilt of the camera's vertical from the fitted gravity [deg] beyond which a warning says so.
TILT_WARN_DEG = 2.0


def suggested_up(measured_up: np.ndarray, exact: bool = False) -> str:
    """The ``up=`` argument for the measured upward unit vector: the camera axis it lies along
    (within ``TILT_WARN_DEG``, the tilt that draws a warning), e.g. ``up='+z'``, else (and
    with ``exact``) the vector itself, with the command line's form."""
    k = int(np.argmax(np.abs(measured_up)))
    if not exact and abs(measured_up[k]) >= math.cos(math.radians(TILT_WARN_DEG)):
        axis = f"{'+' if measured_up[k] > 0 else '-'}{'xyz'[k]}"
        return f"up='{axis}' (impactlab analyze --up {axis})"
    text = ", ".join(f"{v:.3f}" for v in measured_up)
    return f"up=({text}) (impactlab analyze --up '{text}')"


@dataclass(frozen=True)
class RodBody:
    """Centre of mass ``com`` and axis ``axis`` (towards the tip) in the reference cluster's
    frame; ``com_cov`` (3, 3) [m^2] when estimated (None when given); ``source``."""

    com: np.ndarray
    axis: np.ndarray
    com_cov: np.ndarray | None
    source: str


def estimated_body(
    poses: Poses,
    reference: np.ndarray,
    pre_fr: np.ndarray,
    post_fr: np.ndarray,
    t_ref: float,
    upv: np.ndarray,
    g: float,
    max_com_sigma: float,
    src: str,
) -> RodBody:
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
    return RodBody(
        com_body,
        axis_body,
        com_cov,
        f"estimated (centre of mass +- {sig_axis * 1e3:.2g} mm along the axis)",
    )


def impact_frame(
    poses: Poses, k_last: int, body: RodBody, upv: np.ndarray, src: str
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
