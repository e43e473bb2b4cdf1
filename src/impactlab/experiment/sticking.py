"""Does the measured impact slide? The inversion of Eq. 12 needs gross sliding (mu < mu_c).

The inversion itself compares the point values only (``impactlab.analytic.invert``): a measured
mu a hair below mu_c (a sticking impact measures mu ~ mu_c, its friction not fully mobilised)
would pass and give a duration and force of no meaning. Here the measurement's uncertainty
decides: the impact is taken as sticking when mu lies within ``STICK_SIGMAS`` of mu_c, or when
the tip leaves the flat without a tangential velocity (zero within ``STICK_SIGMAS``).
"""

from __future__ import annotations

import math

from impactlab import analytic
from impactlab.bodies import Rod
from impactlab.experiment.kinematics import ImpactKinematics

__all__ = ["STICK_SIGMAS", "sticking_message"]

#: mu within this many sigmas of mu_c, or a tangential exit velocity of the tip within this many
#: sigmas of zero: the impact sticks.
STICK_SIGMAS = 3.0


def _critical(angle: float, sigma: float, rod: Rod) -> tuple[float, float]:
    """(mu_c, its sigma from the angle's) at ``angle`` [rad]."""
    mu_c = float(analytic.critical_friction(angle, rod))
    h = min(max(sigma, 1e-6), 0.25 * min(angle, 0.5 * math.pi - angle))
    if h <= 0:
        return mu_c, 0.0
    slope = float(
        analytic.critical_friction(angle + h, rod) - analytic.critical_friction(angle - h, rod)
    ) / (2.0 * h)
    return mu_c, abs(slope) * sigma


def sticking_message(k: ImpactKinematics, rod: Rod) -> str | None:
    """The reason the impact counts as sticking (module docstring), or None when it slides (or
    when mu_c cannot be evaluated: an angle outside (0, 90) deg, left to the inversion)."""
    angle = k.angle_in
    if not 0.0 < angle.value < 0.5 * math.pi:
        return None
    try:
        mu_c, sig_c = _critical(angle.value, angle.sigma, rod)
    except ValueError:
        return None
    sig = math.hypot(k.mu.sigma, sig_c)
    margin = (mu_c - k.mu.value) / sig if sig > 0 else math.inf
    v_x = k.v_tip_out[0]
    still = abs(v_x.value) / v_x.sigma if v_x.sigma > 0 else math.inf
    if margin >= STICK_SIGMAS and still >= STICK_SIGMAS:
        return None
    why = []
    if margin < STICK_SIGMAS:
        where = "reaches" if k.mu.value >= mu_c else f"lies within {STICK_SIGMAS:g} sigma of"
        why.append(
            f"mu = {k.mu:.4g} {where} mu_c = {mu_c:.4g} (at the measured angle "
            f"{math.degrees(angle.value):.4g} deg)"
        )
    if still < STICK_SIGMAS:
        why.append(
            f"the tip leaves the flat with a tangential velocity of {v_x:.3g}, zero within "
            f"{STICK_SIGMAS:g} sigma"
        )
    return (
        "sticking regime: "
        + " and ".join(why)
        + ": the tip stops sliding on the flat (a sticking impact measures mu near mu_c, "
        "its friction not fully used), so the dent's length does not fix the duration; "
        "Eq. 12 gives no T or F here (the measured e, mu and dent are kept)"
    )
