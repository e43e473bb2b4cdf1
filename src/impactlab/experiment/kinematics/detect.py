"""Impact detection in marker tracks and the free-flight segments around it.

The impact is the largest jump of the cluster's velocity and rate of turn (straight-line fits to
``window`` frames on either side of each frame, gravity removed), in units of their robust noise;
other large jumps (a second bounce) bound the free flight.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from impactlab.experiment.errors import ImpactNotFoundError, TooFewFramesError
from impactlab.experiment.kinematics.fits import robust_sigma, velocity_jumps
from impactlab.experiment.rigid import Poses

__all__ = ["Impact", "detect_impact", "free_flight"]


@dataclass(frozen=True)
class Impact:
    """The detected impact: frame ``k_star``, time ``t_ref`` [s], and the indices (into the
    frames with a pose) ``lo_i``, ``hi_i`` bounding the free flight (other impacts)."""

    k_star: int
    t_ref: float
    lo_i: int
    hi_i: int


def detect_impact(
    poses: Poses,
    ok: np.ndarray,
    reference: np.ndarray,
    upv: np.ndarray,
    g: float,
    window: int,
    src: str,
) -> Impact:
    """Jumps of the velocity of the cluster origin and of the rate of turn of the cluster's
    principal axis, each in units of its robust noise, combined; the largest is the impact."""
    t_ok = poses.time[ok]
    _, _, vt_ref = np.linalg.svd(reference - reference.mean(axis=0))
    spread = float(np.ptp((reference - reference.mean(axis=0)) @ vt_ref[0]))
    chans = np.column_stack(
        [
            poses.translation[ok] + 0.5 * g * ((t_ok - t_ok[0]) ** 2)[:, None] * upv,
            np.einsum("nij,j->ni", poses.rotation[ok], vt_ref[0]) * spread,
        ]
    )
    jumps = np.column_stack([velocity_jumps(t_ok, chans[:, c], window) for c in range(6)])
    if not np.any(np.isfinite(jumps[:, 0])):
        raise TooFewFramesError(f"{src}: too few frames ({ok.size}) to find the impact")
    sig_c = np.array([max(robust_sigma(jumps[:, c]), 1e-9) for c in range(6)])
    stat = np.sqrt(np.sum((jumps / sig_c) ** 2, axis=1))
    i_star = int(np.nanargmax(stat))
    jmax = float(stat[i_star])
    if not jmax > 12.0:
        raise ImpactNotFoundError(
            f"{src}: no impact found: the largest jump of the rod's velocity is {jmax:.3g} "
            "noise sigmas (need > 12); is there an impact in the record?"
        )
    k_star = int(ok[i_star])
    # other impacts (a second bounce) bound the segments
    idx = np.arange(stat.size)
    others = np.flatnonzero((stat > max(12.0, 0.3 * jmax)) & (np.abs(idx - i_star) > 2 * window))
    lo_i = int(others[others < i_star].max()) + window if np.any(others < i_star) else 0
    hi_i = int(others[others > i_star].min()) - window if np.any(others > i_star) else ok.size - 1
    return Impact(k_star, float(poses.time[k_star]), lo_i, hi_i)


def free_flight(
    poses: Poses,
    ok: np.ndarray,
    imp: Impact,
    guard: int,
    max_fit_frames: int,
    min_fit_frames: int,
    src: str,
) -> tuple[np.ndarray, np.ndarray]:
    """The frames of the free flight before and after the impact (at most ``max_fit_frames``)."""
    k_star = imp.k_star
    pre_all = ok[(ok <= k_star - guard) & (ok >= ok[min(imp.lo_i, ok.size - 1)])]
    post_all = ok[(ok >= k_star + guard) & (ok <= ok[max(imp.hi_i, 0)])]
    pre_fr = pre_all[-max_fit_frames:]
    post_fr = post_all[:max_fit_frames]
    for name, fr in (("before", pre_fr), ("after", post_fr)):
        if fr.size < min_fit_frames:
            raise TooFewFramesError(
                f"{src}: only {fr.size} free-flight frames with a pose {name} the impact at "
                f"t = {imp.t_ref:.4f} s (frame {k_star}); need at least {min_fit_frames}"
            )
    return pre_fr, post_fr
