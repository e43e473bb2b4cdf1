"""The rod in the marker data: its centre of mass and axis, the impact frame (steps of
:func:`~impactlab.experiment.kinematics.measure_impact`; gravity's check is ``.gravity``)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.experiment.errors import MarkerError
from impactlab.experiment.kinematics.com import estimate_com
from impactlab.experiment.rigid import Poses

__all__ = ["RodBody", "estimated_body", "impact_frame"]


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
