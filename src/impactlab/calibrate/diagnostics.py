"""What a calibration checks in its own chains: convergence (R-hat, the autocorrelation time,
and whether they can be assessed at all), a posterior piled against a bound of its prior, a
contact law used beyond its verified range, a model that fails on much of its prior, and the
texts of a measured value shown in its display unit."""

from __future__ import annotations

import math
from collections.abc import Collection, Mapping
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number
from impactlab.calibrate.priors import Parameter, possible_range
from impactlab.contact import get_law
from impactlab.contact.tabulated import NU_TOLERANCE, RATIO_TOLERANCE, Tabulated

__all__ = [
    "EDGE_MASS",
    "EDGE_SHARE",
    "FAILED_SHARE_MAX",
    "MISFIT_SIGMAS",
    "RHAT_MAX",
    "TAU_MULTIPLE",
    "convergence_notes",
    "edge_note",
    "extrapolation_note",
    "failed_note",
    "misfit_text",
    "misfits",
    "shown",
    "steps_needed",
]

#: R-hat (rank-normalised split R-hat, the walkers as chains) above this: the walkers have not
#: mixed. Vehtari et al. (2021) ask < 1.01 of independent chains; an ensemble's walkers are not
#: independent, and over a kept chain of 50 autocorrelation times (below) R-hat over walkers
#: still lies a little above 1, so the looser 1.05 (Gelman et al.'s 1.1 is looser still).
RHAT_MAX = 1.05
#: The kept chain (after burn-in) must be this many autocorrelation times long: emcee's
#: ``integrated_time`` trusts its estimate of tau (and so the effective sample size) only then
#: (its ``tol``, 50; Foreman-Mackey et al., emcee's docs "Autocorrelation analysis").
TAU_MULTIPLE = 50
#: The outer share of a prior's mass at each bound, and the share of posterior draws in it
#: above which the posterior lies against that bound (2.5 times the prior's own share: a
#: posterior equal to its prior puts 2 % there, one cut off by the bound far more).
EDGE_MASS = 0.02
EDGE_SHARE = 0.05


def steps_needed(tau: float, burn: int) -> int:
    """The steps (burn-in included) that keep TAU_MULTIPLE autocorrelation times ``tau`` after a
    burn-in of ``burn`` steps, rounded up to two significant digits (1780 -> 1800)."""
    total = burn + math.ceil(TAU_MULTIPLE * tau)
    step = 10 ** max(math.floor(math.log10(total)) - 1, 0)
    return int(math.ceil(total / step) * step)


def convergence_notes(
    summary: Mapping[str, Mapping[str, float]],
    kept: int,
    burn: int,
    draws: int,
    skip: Collection[str] = (),
) -> list[str]:
    """One line per parameter whose chain has not converged (R-hat > RHAT_MAX; a chain of
    ``kept`` steps after a burn-in of ``burn`` shorter than TAU_MULTIPLE autocorrelation times,
    with the steps that would do) or cannot be assessed (too few draws per walker: R-hat, ESS
    or the autocorrelation time is not a number; an ESS is NaN too where ArviZ's estimate
    exceeded the ``draws``, all walkers' kept steps). The parameters in ``skip`` (those the
    model does not use: their chain samples the prior and says nothing of the model) get none."""
    notes = []
    for n, s in summary.items():
        if n in skip:
            continue
        if not math.isfinite(s["rhat"]):
            notes.append(
                f"{n}: R-hat and ESS not assessable (too few draws per walker after burn-in; "
                "ArviZ needs at least 4): convergence unknown, run more steps"
            )
        else:
            if not math.isfinite(s["ess_bulk"]):
                notes.append(
                    f"{n}: ESS not assessable (the estimate exceeds the {draws} draws after "
                    "burn-in: too short a chain to estimate it): run more steps"
                )
            if s["rhat"] > RHAT_MAX:
                notes.append(f"{n}: R-hat {s['rhat']:.3f} > {RHAT_MAX} (run more steps)")
        tau = s["tau"]
        if not (math.isfinite(tau) and tau > 0):
            notes.append(
                f"{n}: autocorrelation time not assessable (chain too short): run more steps"
            )
        elif tau * TAU_MULTIPLE > kept:
            notes.append(
                f"{n}: the chain is {kept} steps after burn-in, "
                f"{format_number(kept / tau, 2)} autocorrelation times (tau = "
                f"{format_number(tau, 2)} steps); {TAU_MULTIPLE} are needed: run about "
                f"{steps_needed(tau, burn)} steps with burn {burn}"
            )
    return notes


def shown(name: str, unit: str, x: float, digits: int = 4) -> str:
    """``x`` (in ``unit``) in the display unit of ``name`` with that unit: ``"49.52 um"``."""
    d = display_unit(name, unit)
    u = "" if d.unit in ("", "1", "-") else f" {d.unit}"
    return f"{format_number(x * d.scale, digits)}{u}"


def edge_note(p: Parameter, draws: np.ndarray) -> str | None:
    """A line when the posterior draws of ``p`` pile against a finite bound of its prior
    (more than EDGE_SHARE of them in the outer EDGE_MASS of the prior's mass there), or None.
    The bound is the prior's choice (widen it) or the parameter's possible range (the data
    favour the limit)."""
    x = np.asarray(draws, dtype=np.float64)
    x = x[np.isfinite(x)]
    if x.size == 0:
        return None
    u = p.cdf(x)
    lo, hi = possible_range(p.name)
    for side, share, bound, limit in (
        ("upper", float(np.mean(u > 1.0 - EDGE_MASS)), p.high, hi),
        ("lower", float(np.mean(u < EDGE_MASS)), p.low, lo),
    ):
        if not (math.isfinite(bound) and share > EDGE_SHARE):
            continue
        at = shown(p.name, p.unit, bound)
        why = (
            f"the {'largest' if side == 'upper' else 'smallest'} possible value: the data favour "
            "the limit"
            if bound == limit
            else "the prior cuts it off: widen the prior if "
            f"{'larger' if side == 'upper' else 'smaller'} values are possible"
        )
        return (
            f"{p.name}: the posterior lies against the {side} bound of its prior ({at}; "
            f"{100 * share:.0f} % of the draws in the prior's outer {100 * EDGE_MASS:.0f} %): "
            f"{why}"
        )
    return None


def misfit_text(r: Mapping[str, Any]) -> str:
    """A posterior predictive row's best fit against the measured value, in display units."""
    q, u = r["quantity"], r["unit"]
    return (
        f"{r['drop']} {q}: best fit {shown(q, u, r['best'])} is {r['z_best']:+.1f} sigma from "
        f"the measured {shown(q, u, r['observed'])}"
    )


#: A best fit farther than this many standard uncertainties from a measured value is a misfit.
MISFIT_SIGMAS = 5.0


def misfits(posteriors: Mapping[str, Any]) -> list[str]:
    """One line per measured value that no model's best fit comes within MISFIT_SIGMAS of
    (``posteriors``: model name -> ModelPosterior), in display units."""
    worst: dict[tuple[str, str], tuple[float, str, Mapping[str, Any]]] = {}
    for name, p in posteriors.items():
        for r in p.ppc:
            key, z = (r["drop"], r["quantity"]), abs(r["z_best"])
            z = z if math.isfinite(z) else math.inf
            if key not in worst or z < worst[key][0]:
                worst[key] = (z, name, r)
    lines = []
    for (d, q), (z, name, r) in worst.items():
        if z <= MISFIT_SIGMAS:
            continue
        show = display_unit(q, r["unit"])  # dent-scale lengths in um, as the tables
        unit = "" if show.unit in ("1", "", "-") else f" {show.unit}"
        value, sigma, best = (format_number(r[k] * show.scale, n)
                              for k, n in (("observed", 4), ("sigma", 2), ("best", 4)))  # fmt: skip
        lines.append(
            f"no model reproduces {d} {q} = {value} +- {sigma}{unit}: the closest best fit "
            f"({name}: {best}{unit}) is {z:.1f} sigma away"
        )
    return lines


#: A model whose failed parameter values (a likelihood of zero: a case it refused or whose
#: result is not ``ok``) exceed this share of those it ran gets a warning: its prior reaches
#: where it does not run, and its posterior is cut to where it does.
FAILED_SHARE_MAX = 0.05


def extrapolation_note(law: str, found: Mapping[str, Any]) -> str | None:
    """A line when some of the predicted impacts (``found``: ``ModelPosterior.law_extrapolated``,
    {share, impacts, basis}) used the contact ``law`` beyond its verified range, or None."""
    share = float(found.get("share", math.nan))
    if not (math.isfinite(share) and share > 0.0):
        return None
    return (
        f"the contact law {law!r} is extrapolated in {format_number(100 * share, 2)} % of the "
        f"{found['impacts']} predicted impacts at {found['basis']} (flag LAW_EXTRAPOLATED: used "
        "beyond its verified range, impactlab.contact.ranges): the posterior rests on the law "
        "where it is not validated (advisory: those cases still count)"
    )


def failed_note(law: str, post: Any) -> str | None:
    """A line when more than FAILED_SHARE_MAX of the parameter values a model ran (``post``: a
    ModelPosterior, its ``draws``, ``failed_draws`` and ``failures``) gave a likelihood of zero,
    or None; for the tabulated ``law``, the E*/S_y of its curves, the windows it runs in."""
    draws, failed = int(post.draws), int(post.failed_draws)
    if not draws or failed <= FAILED_SHARE_MAX * draws:
        return None
    reason = max(post.failures.items(), key=lambda kv: kv[1])[0] if post.failures else "failed"
    return (
        f"{format_number(100 * failed / draws, 2)} % of the {draws} parameter values run ("
        f"more than {100 * FAILED_SHARE_MAX:g} %) gave a likelihood of zero (most often: "
        f"{reason}): the prior reaches where the model does not run or gives no prediction, "
        "so the posterior is cut to where it runs, and a 90 % interval may span values where "
        f"it does not{_windows(law)}"
    )


def _windows(law: str) -> str:
    """Where a tabulated law runs: within its tolerances of one of its curves' E*/S_y and nu,
    the same body yielding."""
    try:
        found = get_law(law)
    except ValueError:
        return ""
    if not isinstance(found, Tabulated):
        return ""
    ratios = ", ".join(format_number(c.e_star_over_sy, 4) for c in found.candidates())
    return (
        f" (law {law!r} runs only where the pair's E*/S_y lies within "
        f"{100 * RATIO_TOLERANCE:g} % of one of its curves', E*/S_y = {ratios or 'none'}, and nu "
        f"within {NU_TOLERANCE:g}, the same body yielding: its posterior lies in those windows)"
    )
