"""Two rigid-body relations between the measured velocity changes: checks that a mirrored
marker geometry breaks.

A contact impulse P acting at the contact point O, at r_CO = (-a, -b) from the centre of mass C
(lever arms a = (L/2) cos(theta), b = (L/2) sin(theta) + R, paper Eq. 1), changes the velocity
of C by P / m and the spin by (r_CO x P)_z / I_C. Eliminating P:

    k^2 dw = b dv_Cx - a dv_Cy,        k^2 = I_C / m (the radius of gyration squared)

so the measured spin change dw must equal the one the measured change of the centre of mass's
velocity predicts, dw_pred = (b dv_Cx - a dv_Cy) / k^2. Gravity acts at C (no moment), and the
fits are evaluated at the impact instant, so the relation holds for a contact of any law, with
friction, slip or stick. A mirrored geometry puts C, the rod's axis and so a, b and dv_C on a
body point and a direction that are not the rod's: the relation then fails, by far more than
its noise at most angles (see docs/experiment.md).

The same impulse turns the rod about r_CO x P, perpendicular to the vertical plane of the rod's
axis (r_CO lies in it, and so does P for a tip that slides in that plane): the change of the spin
vector, fitted in 3D to the rotations before and after, is perpendicular to the rod's axis. A
mirrored geometry's axis is the real one reflected through the markers' plane, tilted out of the
plane of the turn. A tip that slides sideways makes the rod roll about its own axis (whose moment
of inertia is small) and breaks this relation too, so it alone only draws a warning.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.spatial.transform import Rotation

from impactlab.bodies import lever_arms
from impactlab.experiment.kinematics.result import ImpactKinematics
from impactlab.experiment.rigid import Poses
from impactlab.experiment.uncertainty import fixed, propagate

__all__ = [
    "AXIS_TOLERANCE",
    "IMPULSE_SIGMAS",
    "IMPULSE_TOLERANCE",
    "ImpulseCheck",
    "gyration_squared",
    "impulse_check",
]

#: The measured and predicted spin changes disagree when they differ by more than this many
#: standard uncertainties of the difference ...
IMPULSE_SIGMAS = 4.0
#: ... and by more than this fraction of the larger of them (the rod's inertia, the marker
#: mounts' share of it, a contact point that moves during a finite contact).
IMPULSE_TOLERANCE = 0.05
#: The spin change leaves the plane perpendicular to the rod's axis when the sine of its angle
#: to that plane exceeds this (3 deg) and ``IMPULSE_SIGMAS`` of its uncertainty.
AXIS_TOLERANCE = 0.05


@dataclass(frozen=True)
class ImpulseCheck:
    """The measured spin change ``spin_change`` and the one the impulse relation predicts from
    the centre of mass's velocity change, ``predicted`` [rad/s]; ``sigma``: the standard
    uncertainty of their difference [rad/s]."""

    spin_change: float
    predicted: float
    sigma: float
    axis_sine: float = 0.0
    """The sine of the angle between the spin change (3D) and the plane perpendicular to the
    rod's axis; ``axis_sigma`` its standard uncertainty."""
    axis_sigma: float = math.inf

    @property
    def difference(self) -> float:
        return self.spin_change - self.predicted

    @property
    def spin_agrees(self) -> bool:
        """Whether the two spin changes agree within ``IMPULSE_SIGMAS`` and
        ``IMPULSE_TOLERANCE``."""
        return not self.spin_differs(IMPULSE_SIGMAS, IMPULSE_TOLERANCE)

    def spin_differs(self, sigmas: float, tolerance: float) -> bool:
        """Whether the two spin changes differ by more than ``sigmas`` standard uncertainties
        of their difference and by more than the fraction ``tolerance`` of the larger."""
        scale = max(abs(self.spin_change), abs(self.predicted))
        return abs(self.difference) > max(sigmas * self.sigma, tolerance * scale)

    @property
    def sigmas(self) -> float:
        """The difference in standard uncertainties of it (inf for a zero uncertainty)."""
        return abs(self.difference) / self.sigma if self.sigma > 0 else math.inf

    @property
    def axis_agrees(self) -> bool:
        """Whether the spin change is perpendicular to the rod's axis within
        ``IMPULSE_SIGMAS`` and ``AXIS_TOLERANCE``."""
        return abs(self.axis_sine) <= max(IMPULSE_SIGMAS * self.axis_sigma, AXIS_TOLERANCE)

    @property
    def consistent(self) -> bool:
        return self.spin_agrees and self.axis_agrees

    @property
    def relative(self) -> float:
        """The difference as a fraction of the larger spin change."""
        scale = max(abs(self.spin_change), abs(self.predicted))
        return abs(self.difference) / scale if scale > 0 else 0.0

    @property
    def axis_degrees(self) -> float:
        """The angle between the spin change and the plane perpendicular to the rod [deg]."""
        return abs(math.degrees(math.asin(max(-1.0, min(1.0, self.axis_sine)))))

    def text(self) -> str:
        return (
            f"spin change {self.spin_change:.3g} rad/s against {self.predicted:.3g} rad/s from "
            f"the impulse (differing by {fixed(100.0 * self.relative)} %), turning about an axis "
            f"{fixed(self.axis_degrees)} deg off the perpendicular to the rod"
        )


def gyration_squared(rod: Any) -> float | None:
    """k^2 = I_C / m [m^2] of a rod-like object with ``inertia`` and ``mass``; None without
    them (the check is then not made)."""
    try:
        k2 = float(rod.inertia) / float(rod.mass)
    except (AttributeError, TypeError, ValueError, ZeroDivisionError):
        return None
    return k2 if math.isfinite(k2) and k2 > 0 else None


def impulse_check(k: ImpactKinematics, k2: float) -> ImpulseCheck:
    """The impulse relation (module docstring) for the measured impact ``k``, with
    ``k2`` = I_C / m [m^2]; the uncertainty from the derived quantities' covariance."""
    names = list(k.derived_names)
    i_th, i_w0, i_w1 = names.index("angle_in"), names.index("spin_in"), names.index("spin_out")
    i_dx, i_dy = names.index("dv_cx"), names.index("dv_cy")
    half, R = k.half_length, k.tip_radius

    def f(y: np.ndarray) -> np.ndarray:
        a, b = lever_arms(half, R, y[i_th])
        dw = y[i_w1] - y[i_w0]
        pred = (b * y[i_dx] - a * y[i_dy]) / k2
        return np.array([dw, pred, dw - pred])

    out, cov = propagate(f, np.asarray(k.derived_values), np.asarray(k.derived_cov))
    sine, sine_sigma = _axis_sine(k)
    return ImpulseCheck(
        float(out[0]), float(out[1]), float(np.sqrt(max(cov[2, 2], 0.0))), sine, sine_sigma
    )


def _spin_vector(poses: Poses, frames: np.ndarray, axis: np.ndarray) -> tuple[np.ndarray, float]:
    """(the spin vector in the lab [rad/s] fitted to the rotations of ``frames`` (constant
    spin), the variance of its component along the unit vector ``axis``, widened as a Student
    t's for few frames; inf with fewer than 5). The rotation from the first frame is summed from
    one frame to the next, so that a turn beyond pi does not wrap."""
    R = poses.rotation[frames]
    t = poses.time[frames] - poses.time[frames[0]]
    steps = Rotation.from_matrix(R[1:] @ np.transpose(R[:-1], (0, 2, 1))).as_rotvec()
    rv = np.vstack([np.zeros(3), np.cumsum(steps, axis=0)])
    A = np.column_stack([np.ones_like(t), t])
    coef, *_ = np.linalg.lstsq(A, rv, rcond=None)
    dof = t.size - 2
    if dof < 3:
        return coef[1], math.inf
    along = (rv - A @ coef) @ axis  # the residuals along the axis (roll noise is correlated)
    s2 = float(along @ along) / dof * (dof / (dof - 2.0))
    return coef[1], float(np.linalg.inv(A.T @ A)[1, 1]) * s2


def _axis_sine(k: ImpactKinematics) -> tuple[float, float]:
    """The sine of the angle between the spin change (3D, lab) and the plane perpendicular to
    the rod's axis at the impact, and its standard uncertainty (inf without the poses)."""
    if k.poses is None:
        return 0.0, math.inf
    axis = k.poses.rotation[k.post.frames[0]] @ k.axis_body
    axis = axis / np.linalg.norm(axis)
    w0, v0 = _spin_vector(k.poses, k.pre.frames, axis)
    w1, v1 = _spin_vector(k.poses, k.post.frames, axis)
    size = float(np.linalg.norm(w1 - w0))
    if not size > 0:
        return 0.0, math.inf
    return float(axis @ (w1 - w0)) / size, math.sqrt(v0 + v1) / size
