"""The inversion's Monte Carlo: T and F of samples of the measured inputs (normal draws), their
means, spreads, medians and 95 % intervals, and the warnings when the samples reach the
sticking regime or are discarded; the point distribution of inputs without any sigma."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._validation import warn_implausible
from impactlab.analytic.result import MC_INTERVAL, Measured

__all__ = ["MC_REJECTED_WARNING", "SPREAD_ROUNDING", "monte_carlo", "point_distribution"]

#: A Monte Carlo that discards more than this share of its samples (sticking regime or out of
#: range) draws an ImplausibleInputWarning: its mean and spread then describe a truncated
#: distribution, not the measurement's. Any sample in the sticking regime draws another (the
#: heavy tail of T, ``monte_carlo``).
MC_REJECTED_WARNING = 0.05
#: A Monte Carlo standard deviation below this fraction of its mean is rounding (T when only
#: dv_cy is uncertain, which T does not depend on) and is reported as 0.
SPREAD_ROUNDING = 1e-12


def monte_carlo(
    meas: Mapping[str, Measured], n: int, seed: int | None, core: Any
) -> dict[str, Any]:
    """Means, standard deviations, medians, 95 % intervals (``MC_INTERVAL`` percentiles), the
    rejected fraction and the number of samples kept of ``n`` samples of the inputs ``meas``
    (at least one with a sigma), T and F from ``core``; ImplausibleInputWarning
    when more than ``MC_REJECTED_WARNING`` of them are discarded, and when any falls in the
    sticking regime (the spread of T is then unreliable: :func:`_warn_heavy_tail`)."""
    rng = np.random.default_rng(seed)
    samples = {
        k: (v.value + v.sigma * rng.standard_normal(n)) if v.sigma > 0 else np.full(n, v.value)
        for k, v in meas.items()
    }
    Ts, Fs, ok, stuck = (np.broadcast_to(v, (n,)) for v in core(samples))
    rejected = 1.0 - float(np.mean(ok))
    Tv, Fv = Ts[ok], Fs[ok]
    if Tv.size < 2:
        raise ValueError(
            "almost all Monte Carlo samples fall in the sticking regime or out of "
            "range: the uncertainties are too large for this inversion"
        )
    if rejected > MC_REJECTED_WARNING:
        warn_implausible(
            f"{rejected:.1%} of the {n} Monte Carlo samples fell in the sticking regime or out "
            f"of range and were discarded (more than {MC_REJECTED_WARNING:.0%}): T_mc and F_mc "
            f"rest on the {Tv.size} kept, a truncated distribution; the uncertainties given are "
            "too large for this inversion, check the sigmas"
        )
    n_stuck = int(np.count_nonzero(stuck))
    if n_stuck:
        _warn_heavy_tail(n_stuck, n)
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
        "and T_mc depend on the seed and the spread is unreliable; read T_median_mc and "
        f"T_interval_mc ({lo:g}-{hi:g} percentiles) instead, or narrow the sigmas of mu and "
        "the angle"
    )
