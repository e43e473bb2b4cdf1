"""The inversion's Monte Carlo: T and F of samples of the measured inputs (normal draws), their
means, spreads, medians and 95 % intervals, and the warnings when the samples reach the
sticking regime or the pole of Eq. 12 in vt_in, are discarded, or reverse their sliding
(vt_in > 0); the point distribution of inputs without any sigma."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import warn_implausible
from impactlab.analytic._conditioning import REVERSAL_SIGMAS
from impactlab.analytic._correlation import Correlation, correlate
from impactlab.analytic.result import MC_INTERVAL, Measured

__all__ = [
    "MC_REJECTED_WARNING",
    "REVERSAL_LEAN",
    "SPREAD_ROUNDING",
    "monte_carlo",
    "point_distribution",
]

#: A Monte Carlo that discards more than this share of its samples (sticking regime or out of
#: range) draws an ImplausibleInputWarning naming each cause with its share: its mean and
#: spread then describe a truncated distribution, not the measurement's (for e drawn outside
#: [0, 1] alone: e's distribution truncated to its physical range). Any sample in the
#: sticking regime draws another (the heavy tail of T, ``monte_carlo``).
MC_REJECTED_WARNING = 0.05
#: A Monte Carlo standard deviation below this fraction of its mean is rounding (T when only
#: dv_cy is uncertain, which T does not depend on) and is reported as 0.
SPREAD_ROUNDING = 1e-12
#: Where more than ``MC_REJECTED_WARNING`` of the kept samples have vt_in > 0 (their T from
#: Eq. 12 only an upper bound), an ImplausibleInputWarning gives T's median and interval with
#: vt_in > 0 taken as 0 (the lower bound) when one of the three moves by more than this share
#: of the interval's width (about one standard deviation of a normal T).
REVERSAL_LEAN = 0.25


def monte_carlo(
    meas: Mapping[str, Measured],
    n: int,
    seed: int | None,
    core: Any,
    abs_alpha: float = math.nan,
    gravity: bool = False,
    corr: Correlation | None = None,
) -> dict[str, Any]:
    """Means, standard deviations, medians, 95 % intervals (``MC_INTERVAL`` percentiles), the
    rejected fraction and the number of samples kept of ``n`` samples of the inputs ``meas``
    (at least one with a sigma), T and F from ``core``; ImplausibleInputWarning
    when more than ``MC_REJECTED_WARNING`` of them are discarded (each cause with its share:
    :func:`_causes`; which samples are discarded is ``core``'s rule), when any falls in the
    sticking regime or reaches vt_in >= |alpha| |v_i| (``abs_alpha`` = |alpha| at the nominal
    inputs; the spread of T is then unreliable: :func:`_warn_heavy_tail`, :func:`_warn_pole`),
    and where samples with vt_in > 0 move T's median or interval (:func:`_check_reversal`).
    The inputs are drawn independently, or correlated as ``corr`` says (the same standard
    normals, mixed: :func:`correlate`)."""
    rng = np.random.default_rng(seed)
    z = {k: rng.standard_normal(n) for k, v in meas.items() if v.sigma > 0}
    if corr:
        correlate(z, meas, corr)
    samples = {
        k: (v.value + v.sigma * z[k]) if v.sigma > 0 else np.full(n, v.value)
        for k, v in meas.items()
    }
    Ts, Fs, ok, stuck, past = (np.broadcast_to(v, (n,)) for v in core(samples))
    rejected = 1.0 - float(np.mean(ok))
    Tv, Fv = Ts[ok], Fs[ok]
    if Tv.size < 2:
        raise ValueError(
            "almost all Monte Carlo samples fall in the sticking regime or out of "
            "range: the uncertainties are too large for this inversion"
        )
    if rejected > MC_REJECTED_WARNING:
        _warn_rejected(rejected, n, int(Tv.size), _causes(meas, samples, ok, stuck, past))
    n_stuck = int(np.count_nonzero(stuck))
    if n_stuck:
        _warn_heavy_tail(n_stuck, n)
    n_past = int(np.count_nonzero(past))
    if n_past:
        _warn_pole(n_past, n, meas, abs_alpha, gravity)
    vt = meas.get("vt_in")
    if vt is not None and vt.sigma > 0.0 and not vt.value > REVERSAL_SIGMAS * vt.sigma:
        _check_reversal(meas, samples, Tv, ok, core)
    lo, hi = MC_INTERVAL
    return {
        "T_mc": float(np.mean(Tv)),
        "F_mc": float(np.mean(Fv)),
        "sigma_T_mc": _spread(Tv),
        "sigma_F_mc": _spread(Fv),
        "T_median_mc": float(np.median(Tv)),
        "F_median_mc": float(np.median(Fv)),
        "T_interval_mc": (float(np.percentile(Tv, lo)), float(np.percentile(Tv, hi))),
        "F_interval_mc": (float(np.percentile(Fv, lo)), float(np.percentile(Fv, hi))),
        "mc_rejected": rejected,
        "mc_used": int(Tv.size),
    }


def point_distribution(T: float, F: float) -> dict[str, Any]:
    """The Monte Carlo outputs of inputs without any sigma: nothing is drawn (``mc_used`` 0),
    the distribution is the point (``T`` [s], ``F`` [N]): mean, median and interval ends."""
    return {
        "T_mc": T,
        "F_mc": F,
        "sigma_T_mc": 0.0,
        "sigma_F_mc": 0.0,
        "T_median_mc": T,
        "F_median_mc": F,
        "T_interval_mc": (T, T),
        "F_interval_mc": (F, F),
        "mc_rejected": 0.0,
        "mc_used": 0,
    }


def _spread(x: Any) -> float:
    """The sample standard deviation of ``x``, 0 where it is rounding (``SPREAD_ROUNDING``)."""
    sigma = float(np.std(x, ddof=1))
    return 0.0 if sigma <= SPREAD_ROUNDING * abs(float(np.mean(x))) else sigma


def _causes(
    meas: Mapping[str, Measured], samples: Mapping[str, Any], ok: Any, stuck: Any, past: Any
) -> list[tuple[int, str]]:
    """``(count, why)`` for the discarded samples (not ``ok``), each counted under the first
    of its causes: the sticking regime, the pole of Eq. 12 in vt_in, an input drawn outside
    its range (e outside [0, 1] where F comes from e, dv_cy <= 0, a magnitude <= 0, ...), and
    what remains (no finite T or F). The rule that discards them is ``_core``'s; this only
    names it."""
    left = ~np.asarray(ok)
    found: list[tuple[int, str]] = []

    def take(mask: Any, why: str) -> None:
        nonlocal left
        hit = left & np.broadcast_to(mask, left.shape)
        if hit.any():
            found.append((int(np.count_nonzero(hit)), why))
            left = left & ~hit

    take(stuck, "fell in the sticking regime (alpha >= 0)")
    take(past, "reached the pole of Eq. 12 (vt_in >= |alpha| |v_i|)")
    e = meas.get("e")
    if e is not None and e.sigma > 0.0 and "dv_cy" not in samples:  # F from e
        take(samples["e"] > 1.0, f"drew e > 1 ({_at_limit('e', e, 1.0)})")
        take(samples["e"] < 0.0, f"drew e < 0 ({_at_limit('e', e, 0.0)})")
    if "dv_cy" in samples:
        take(samples["dv_cy"] <= 0.0, "drew dv_cy <= 0 (the rod not pushed up)")
    take(samples["mu"] < 0.0, "drew mu < 0")
    take(samples["v_i"] <= 0.0, "drew |v_i| <= 0")
    take(samples["delta_p"] < 0.0, "drew |delta_p| < 0")
    take(samples["sliding_length"] <= 0.0, "drew |sliding_length| <= 0")
    angle = samples["angle"]
    take((angle < 0.0) | (angle > 0.5 * math.pi), "drew an angle outside [0, 90] deg")
    take(True, "gave no finite, positive T or F")
    return found


def _at_limit(name: str, x: Measured, limit: float) -> str:
    """``"e = 1 +- 0.01 lies at the physical limit e <= 1"`` or ``"... 2 sigma inside ..."``."""
    side = "<=" if limit >= x.value else ">="
    k = abs(limit - x.value) / x.sigma
    where = "at" if k < 0.05 else f"{k:.2g} sigma inside"
    given = f"{name} = {x.value:.4g} +- {x.sigma:.2g}"
    return f"{given} lies {where} the physical limit {name} {side} {limit:g}"


def _warn_rejected(rejected: float, n: int, kept: int, causes: list[tuple[int, str]]) -> None:
    """ImplausibleInputWarning: more than ``MC_REJECTED_WARNING`` of the ``n`` samples were
    discarded, with the share of each cause (:func:`_causes`). Where all of them drew e outside
    [0, 1] the kept samples are e's distribution truncated to its physical range (what F_mc
    then describes); otherwise the sigmas given are too wide for this inversion."""
    shares = "; ".join(f"{c / n:.1%} {why}" for c, why in causes)
    only_e = all(why.startswith(("drew e > 1", "drew e < 0")) for _, why in causes)
    advice = (
        f"T_mc and F_mc rest on the {kept} kept: e's distribution truncated to [0, 1], its "
        "physical range (the first-order sigma of F does not truncate it); the sigmas are not "
        "too wide, e lies near its limit"
        if only_e
        else f"T_mc and F_mc rest on the {kept} kept, a truncated distribution; the "
        "uncertainties given are too large for this inversion, check the sigmas"
    )
    warn_implausible(
        f"{rejected:.1%} of the {n} Monte Carlo samples were discarded (more than "
        f"{MC_REJECTED_WARNING:.0%}): {shares}. {advice}"
    )


def _warn_heavy_tail(n_stuck: int, n: int) -> None:
    """ImplausibleInputWarning: ``n_stuck`` of ``n`` samples reached alpha >= 0. T ~ 1/|alpha|
    and alpha passes 0 linearly at mu_c, so where the inputs' distribution reaches it the
    density of T falls as 1/T^2: its variance (and its mean) diverge, and the sample's
    standard deviation is set by its few largest draws, not by the measurement."""
    lo, hi = MC_INTERVAL
    warn_implausible(
        f"{n_stuck} of the {n} Monte Carlo samples ({n_stuck / n:.2%}) reached alpha >= 0 (the "
        "sticking regime) and were discarded: where the inputs' distribution reaches it, "
        "alpha -> 0 and T ~ 1/|alpha| has a heavy tail without a finite variance, so sigma_T_mc "
        "and T_mc depend on the seed and the spread is unreliable, and the first-order "
        "sigma_T (a linearisation) does not describe T's skewed spread either; read "
        f"T_median_mc and T_interval_mc ({lo:g}-{hi:g} percentiles) instead, or narrow the "
        "sigmas of mu and the angle"
    )


def _warn_pole(
    n_past: int, n: int, meas: Mapping[str, Measured], abs_alpha: float, gravity: bool
) -> None:
    """ImplausibleInputWarning: ``n_past`` of ``n`` samples reached vt_in >= |alpha| |v_i|, the
    pole of Eq. 12, T = (|delta_p| + |L_s|/|alpha|) / (|v_i| - vt_in/|alpha|): vt_in passes it
    linearly, so (without gravity) the density of T falls as 1/T^2 as at alpha -> 0."""
    vt = meas["vt_in"]
    lo, hi = MC_INTERVAL
    given = f"{vt.value:.4g} +- {vt.sigma:.2g} m/s" if vt.sigma > 0 else f"{vt.value:.4g} m/s"
    grows = (
        "grows steeply (to sqrt(2 (|delta_p| + |L_s|/|alpha|)/g) at it, with gravity)"
        if gravity
        else "grows without limit: a heavy tail without a finite variance"
    )
    warn_implausible(
        f"{n_past} of the {n} Monte Carlo samples ({n_past / n:.2%}) reached vt_in >= |alpha| "
        f"|v_i|, the pole of Eq. 12 ({abs_alpha * meas['v_i'].value:.4g} m/s at the nominal "
        f"inputs; vt_in = {given} was given): there the tip need not slide towards -x and "
        "Eq. 12 gives no T, so they were discarded, and towards the pole Eq. 12's T "
        f"(for vt_in > 0 only an upper bound) {grows}, so sigma_T_mc and T_mc (and F's) depend "
        f"on the seed and the spread is unreliable; read T_median_mc and T_interval_mc "
        f"({lo:g}-{hi:g} percentiles) instead, and narrow the sigma of vt_in (or of mu, the "
        "angle and v_i) or check its sign (along +x, towards the centre of mass)"
    )


def _check_reversal(
    meas: Mapping[str, Measured], samples: Mapping[str, Any], Tv: Any, ok: Any, core: Any
) -> None:
    """ImplausibleInputWarning where more than ``MC_REJECTED_WARNING`` of the kept samples
    (``ok``, their T ``Tv``) have vt_in > 0, whose T from Eq. 12 is only an upper bound (the
    sliding reverses; docs/analytic.md, Sec. 5), and taking their vt_in as 0 (the lower bound)
    moves T's median or an end of its interval by more than ``REVERSAL_LEAN`` of the
    interval's width: the warning gives both."""
    n_pos = int(np.count_nonzero(ok & (samples["vt_in"] > 0.0)))
    if n_pos <= MC_REJECTED_WARNING * Tv.size:
        return
    low = dict(samples)
    low["vt_in"] = np.minimum(samples["vt_in"], 0.0)
    T_low = np.broadcast_to(core(low)[0], ok.shape)[ok]
    q = (50.0, *MC_INTERVAL)
    upper, lower = np.percentile(Tv, q), np.percentile(T_low, q)
    if not np.max(np.abs(upper - lower)) > REVERSAL_LEAN * (upper[2] - upper[1]):
        return
    vt = meas["vt_in"]
    nominal = f" (the duration given, at vt_in = {vt.value:.4g} m/s, is an upper bound too)"
    nominal = nominal if vt.value > 0.0 else ""
    warn_implausible(
        f"{n_pos / Tv.size:.1%} of the Monte Carlo samples have vt_in > 0 (vt_in = "
        f"{vt.value:.4g} +- {vt.sigma:.2g} m/s): there the tip first slides towards +x and its "
        "sliding reverses, which Eq. 12 does not describe, and their T is only an upper bound "
        f"(docs/analytic.md, Sec. 5); T_median_mc = {upper[0]:.4g} s and T_interval_mc "
        f"({upper[1]:.4g}, {upper[2]:.4g}) s take the upper bounds, with vt_in > 0 taken as 0 "
        f"(the lower bound) they are {lower[0]:.4g} s and ({lower[1]:.4g}, {lower[2]:.4g}) s, "
        f"and T (and F) lie between{nominal}; measure vt_in more precisely, or check its sign "
        "(along +x, towards the centre of mass)"
    )
