"""Where the inversion's T holds, and how well: the incoming tangential velocity of the tip
(Eq. 12 needs the tip sliding towards -x throughout), the conditioning of T on mu and the angle
(alpha -> 0 near mu_c and near 90 deg, where T ~ 1/|alpha| diverges), an implausibly long T, and
results that over- or underflow (a rod's or an input's extreme values). ValueError for what gives
no T, ImplausibleInputWarning for a T to read with care."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from impactlab._validation import warn_implausible
from impactlab.analytic._measurements import PLAUSIBLE_DURATION
from impactlab.analytic.closed_forms import duration_from_dent
from impactlab.analytic.result import Measured

__all__ = [
    "ANGLE_STEP_DEG",
    "CONDITION_LIMIT",
    "REVERSAL_SIGMAS",
    "check_coefficients",
    "check_conditioning",
    "check_direction",
    "check_duration",
    "check_finite_result",
    "check_mc_duration",
]

#: A relative sensitivity |d ln T / d ln mu| or |d ln T / d ln angle| above this draws an
#: ImplausibleInputWarning: a 1 % error in mu (or the angle) moves T by more than 10 %. The
#: paper's three drops give at most 2.8 (the angle at 70 deg).
CONDITION_LIMIT = 10.0
#: A positive vt_in more than this many sigmas above 0 draws the warning of a reversing slip
#: with T's bounds (within it, the Monte Carlo's samples with vt_in > 0 are weighed instead:
#: ``monte_carlo.REVERSAL_LEAN``).
REVERSAL_SIGMAS = 3.0
#: The angle error [deg] whose effect on T the warning of an ill-conditioned T quotes (an
#: angle's error is absolute: 1 % of 89.9 deg would pass 90 deg); within twice it of 90 deg
#: the warning says that it reaches towards 90 deg instead.
ANGLE_STEP_DEG = 0.1


def check_direction(
    meas: Mapping[str, Measured], abs_alpha: float, gravity: bool, g: float
) -> None:
    """Checks of the incoming tangential velocity ``vt_in`` [m/s] (where given) at the nominal
    inputs, with ``abs_alpha`` = |alpha|: ValueError where vt_in >= |alpha| |v_i| (the tip would
    not slide towards -x at all, Eq. 12 gives no T); ImplausibleInputWarning where vt_in > 0
    beyond ``REVERSAL_SIGMAS``: the tip first slides towards +x and reverses, and T lies between
    the values for vt_in = 0 and for vt_in (docs/analytic.md, Sec. 5)."""
    if "vt_in" not in meas:
        return
    vt = meas["vt_in"]
    vi, dp, ls = (meas[k].value for k in ("v_i", "delta_p", "sliding_length"))
    if vt.value >= abs_alpha * vi:
        raise ValueError(
            f"vt_in = {vt.value:.4g} m/s is at least |alpha| |v_i| = {abs_alpha * vi:.4g} m/s: "
            "the tip moves towards +x (towards the centre of mass) so fast that it need not "
            "slide towards -x at all during the contact, and Eq. 12 gives no duration; check "
            "the sign of vt_in (along +x, towards the centre of mass)"
        )
    if vt.value <= 0.0 or vt.value <= REVERSAL_SIGMAS * vt.sigma:
        return
    lo = float(duration_from_dent(dp, ls, vi, abs_alpha, gravity, g))
    hi = float(duration_from_dent(dp, ls, vi - vt.value / abs_alpha, abs_alpha, gravity, g))
    warn_implausible(
        f"vt_in = {vt.value:.4g} +- {vt.sigma:.2g} m/s > 0: the tip first slides towards +x "
        "(towards the centre of mass) and its sliding reverses during the contact, which "
        f"Eq. 12 (one sliding direction) does not describe; T lies between {lo:.4g} s (the "
        f"value for vt_in = 0) and {hi:.4g} s, the value given (an upper bound)"
    )


def check_conditioning(
    meas: Mapping[str, Measured],
    sens_T: Mapping[str, float],
    T: float,
    alpha: float,
    mu_c: float,
) -> bool:
    """ImplausibleInputWarning, and True, where T [s] is ill-conditioned: |d ln T / d ln mu| or
    |d ln T / d ln angle| (from the sensitivities ``sens_T``) above ``CONDITION_LIMIT``. The
    text quotes what a 1 % error in mu, or an error of ``ANGLE_STEP_DEG`` in the angle, does
    to T, names alpha, mu_c and how close mu lies to it, and the angle's distance from 90 deg
    where that is under 10 deg."""
    mu, th = meas["mu"].value, meas["angle"].value
    rel = {
        "mu": abs(sens_T["mu"] * mu / T),
        "the angle": abs(sens_T["angle"] * th / T),
    }
    rel = {k: v if math.isfinite(v) else math.inf for k, v in rel.items()}  # a step past mu_c
    worst = max(rel, key=lambda k: rel[k])
    if rel[worst] <= CONDITION_LIMIT:
        return False
    deg = math.degrees(th)
    near = f"{100.0 * (mu_c - mu) / mu_c:.3g} % below" if mu_c > 0 else "at"
    where = f"mu = {mu:.4g} lies {near} mu_c = {mu_c:.4g} at angle = {deg:.4g} deg"
    if deg > 80.0:
        where += f" (the rod {90.0 - deg:.3g} deg from vertical, where alpha and mu_c -> 0)"
    if worst == "mu":
        moves = f"a 1 % error in mu moves T by about {rel['mu']:.3g} %"
    elif 90.0 - deg > 2.0 * ANGLE_STEP_DEG:  # an absolute step, well short of 90 deg
        moves = (
            f"an error of {ANGLE_STEP_DEG:g} deg in the angle moves T by about "
            f"{rel[worst] * ANGLE_STEP_DEG / deg * 100.0:.3g} %"
        )
    else:  # a first-order change means nothing where the step reaches 90 deg
        moves = (
            f"an error of {ANGLE_STEP_DEG:g} deg in the angle is over half its distance to "
            f"90 deg ({90.0 - deg:.2g} deg), where T diverges"
        )
    warn_implausible(
        f"T is ill-conditioned here: {moves} (|d ln T/d ln mu| = {rel['mu']:.3g}, "
        f"|d ln T/d ln angle| = {rel['the angle']:.3g}, above {CONDITION_LIMIT:g}): "
        "T ~ 1/|alpha|, and "
        f"alpha = {alpha:.3g} changes fast towards 0 at mu_c; {where}. T is only as good as mu "
        "and the angle are known"
    )
    return True


def check_duration(T: float, conditioned: bool) -> None:
    """ImplausibleInputWarning for a nominal T [s] above ``PLAUSIBLE_DURATION``: a units hint,
    or, where the ill-conditioning explains it (``conditioned``), that reason instead."""
    if T <= PLAUSIBLE_DURATION:
        return
    why = (
        "alpha is near 0, where T ~ 1/|alpha| diverges (the warning on the conditioning)"
        if conditioned
        else "check the units of the inputs (SI)"
    )
    warn_implausible(
        f"the inverted duration T = {T:.4g} s exceeds {PLAUSIBLE_DURATION:g} s, far longer "
        f"than a rigid-body impact; {why}"
    )


def check_mc_duration(
    T: float, mc: Mapping[str, Any], meas: Mapping[str, Measured], sens_T: Mapping[str, float]
) -> None:
    """ImplausibleInputWarning where the nominal T [s] is plausible but the Monte Carlo's median
    ``T_median_mc`` or the upper end of ``T_interval_mc`` lies above ``PLAUSIBLE_DURATION``: the
    sigmas spread T to durations no rigid-body impact has (the nominal's rule, ``check_duration``,
    applied to the distribution); the text names the input whose sigma moves T most (first
    order, ``sens_T``)."""
    median, upper = mc["T_median_mc"], mc["T_interval_mc"][1]
    if T > PLAUSIBLE_DURATION or max(median, upper) <= PLAUSIBLE_DURATION:
        return
    share = {k: abs(sens_T.get(k, 0.0)) * m.sigma for k, m in meas.items()}
    top = max(share, key=lambda k: share[k])
    what = (
        f"the Monte Carlo's median T_median_mc = {median:.4g} s"
        if median > PLAUSIBLE_DURATION
        else f"the upper end of the Monte Carlo's 95 % interval of T, {upper:.4g} s,"
    )
    warn_implausible(
        f"{what} exceeds {PLAUSIBLE_DURATION:g} s (the nominal T = {T:.4g} s), far longer "
        "than a rigid-body impact: the sigmas given spread T beyond any impact (the largest "
        f"share from the sigma of {top} = {meas[top].sigma:.4g}); check the sigmas and their "
        "units (SI)"
    )


def _rod_text(rod: Mapping[str, float]) -> str:
    """The rod's values as an error names them (SI)."""
    units = {"mass": "kg", "length": "m", "tip_radius": "m", "inertia": "kg m^2"}
    return ", ".join(f"rod.{k} = {rod[k]!r} {u}" for k, u in units.items() if k in rod)


def check_coefficients(K_x: float, K_y: float, alpha: float, rod: Mapping[str, float]) -> None:
    """ValueError where the rod's impulse coefficients K_x, K_y [1/kg] or alpha are not finite,
    or K_y = 0 (1/(m k^2) over- or underflows for a rod's extreme mass or inertia), naming the
    rod's values; and, naming mu, where K_y < 0: mu a b > k^2 + a^2, a mu far above the
    critical mu_c, where the tip sticks."""
    finite = all(math.isfinite(v) for v in (K_x, K_y, alpha))
    if finite and K_y > 0.0:
        return
    if finite and K_y < 0.0:
        raise ValueError(
            f"mu lies far above the critical mu_c, where the tip sticks (K_y = {K_y:.4g} 1/kg "
            "< 0: mu a b > k^2 + a^2); the inversion of Eq. 12 needs gross sliding, mu < mu_c "
            "(impactlab.analytic.critical_friction); check mu, a friction coefficient (0.1-0.6 "
            "for metals)"
        )
    raise ValueError(
        f"the rod's impulse coefficients are not finite (K_x = {K_x!r}, K_y = {K_y!r} 1/kg, "
        f"alpha = {alpha!r}) for {_rod_text(rod)}: 1/(m k^2) over- or underflows, far outside "
        "any rod; check the rod's values and their units (SI)"
    )


def check_finite_result(
    values: Mapping[str, Any], meas: Mapping[str, Measured], rod: Mapping[str, float]
) -> None:
    """ValueError where a number among ``values`` (output name -> a number, or a tuple of
    numbers; counts and shares are skipped) is not finite, or a duration or force is 0 (it
    underflowed): the inputs (``meas``, SI) lie outside the range of a rigid-body impact. The
    error names the output and every input."""
    for name, v in values.items():
        if name in ("mc_rejected", "mc_used"):
            continue
        numbers = v if isinstance(v, tuple) else (v,)
        bad = next((float(x) for x in numbers if not math.isfinite(x)), None)
        if bad is None and not name.startswith("sigma") and any(x == 0.0 for x in numbers):
            bad = 0.0
        if bad is None:
            continue
        given = ", ".join(
            f"{k} = {m.value!r}" + (f" +- {m.sigma!r}" if m.sigma else "") for k, m in meas.items()
        )
        raise ValueError(
            f"the inversion gives {name} = {bad!r} (it over- or underflows) for {given} (SI) "
            f"and {_rod_text(rod)}: these inputs lie outside the range of a rigid-body impact; "
            "check their values and units (SI)"
        )
