"""What a finished calibration warns of: each model's convergence problems, a posterior against a
bound of its prior or of the range its contact or rate law is fitted for, an extrapolated law, a
share of failed parameter values, and why the best-ranked model may not be the one the data
single out."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab.calibrate.diagnostics import (
    EDGE_MASS,
    EDGE_SHARE,
    MISFIT_SIGMAS,
    edge_note,
    extrapolation_note,
    failed_note,
    shown,
)
from impactlab.calibrate.models import CandidateModel
from impactlab.calibrate.priors import Parameter
from impactlab.calibrate.ranking import (
    ELPD_DIFF_MIN,
    MISFIT,
    NOT_CONVERGED,
    NOT_DISTINGUISHABLE,
    SMALL_DIFFERENCE,
    UNRELIABLE_LOO,
)
from impactlab.calibrate.result import ModelPosterior
from impactlab.contact.rate import RATE_LAWS

__all__ = ["best_warnings", "chain_warnings", "fitted_range_note"]

#: A free flat property -> the field of ``contact.rate.FittedFor`` that bounds it (the range of
#: the material a built-in rate law's constants were fitted for).
_FITTED = {"flat_yield_strength": "yield_strength", "flat_E": "E"}


def chain_warnings(
    posteriors: Mapping[str, ModelPosterior],
    params: Sequence[Parameter],
    usage: Mapping[str, Sequence[bool]],
    cands: Sequence[CandidateModel],
) -> list[str]:
    """Each model's convergence problems (of the parameters it uses: ``summarise`` notes none
    for an unused one, whose chain is its prior's and says nothing of the model), each used
    parameter whose posterior lies against a bound of its prior or of the range its rate law
    is fitted for (:func:`fitted_range_note`), a contact law extrapolated in
    the predicted impacts and a share of failed parameter values above FAILED_SHARE_MAX (the
    last three added to the model's own warnings too), as ``"model: text"``."""
    out = []
    laws = {c.name: c.law for c in cands}
    rate_laws = {c.name: c.rate for c in cands}
    for name, post in posteriors.items():
        edges = [
            note
            for j, p in enumerate(params)
            if usage[name][j]
            and (
                (note := edge_note(p, post.samples[:, j])) is not None
                or (note := fitted_range_note(p, post.samples[:, j], rate_laws[name])) is not None
            )
        ]
        for note in (
            extrapolation_note(laws[name], post.law_extrapolated),
            failed_note(laws[name], post),
        ):
            edges += [] if note is None else [note]
        post.warnings.extend(edges)
        out += [f"{name}: {text}" for text in (*post.convergence, *edges)]
    return out


def best_warnings(ranking: Sequence[Mapping[str, Any]]) -> list[str]:
    """Why the best-ranked model may not be the one the data single out."""
    if not ranking:
        return []
    best = ranking[0]
    out = _not_distinguishable(best, ranking[1]) if len(ranking) > 1 else []
    if NOT_CONVERGED in best["note"]:
        out.append(
            f"the best-ranked model {best['model']!r} has not converged: its rank and "
            "posterior may change with more steps"
        )
    if MISFIT in best["note"]:
        out.append(
            f"the best-ranked model {best['model']!r} misses a measured value by "
            f"{best['misfit_max']:.1f} sigma at its best fit (its notes name it): it does not "
            "describe every measurement"
        )
    return out


def _not_distinguishable(best: Mapping[str, Any], other: Mapping[str, Any]) -> list[str]:
    """The warning (or none) that ``best`` is not distinguishable from the runner-up
    ``other``, with each reason its note names."""
    why = []
    if NOT_DISTINGUISHABLE in best["note"]:
        why.append(
            f"elpd_diff {other['elpd_diff']:.2f} < 2 dse ({2 * other['dse']:.2f})"
            if other["dse"] > 0
            else f"elpd_diff {other['elpd_diff']:.2f} has no standard error (dse 0) to judge it"
        )
    if SMALL_DIFFERENCE in best["note"]:
        why.append(
            f"elpd_diff {other['elpd_diff']:.2f} < {ELPD_DIFF_MIN:g}: too small for its dse to "
            "be trusted (Sivula et al. 2020, arXiv:2008.10296)"
        )
    if UNRELIABLE_LOO in best["note"]:
        ks = ", ".join(f"{r['model']!r} {r['pareto_k_max']:.2f}" for r in (best, other))
        why.append(
            f"PSIS-LOO is unreliable for a drop (Pareto k max {ks}; above 0.7 a drop's elpd "
            "may be off by as much as the difference)"
        )
    if not why:
        return []
    apart = (
        f"; yet {other['model']!r} misses a measured value by {other['misfit_max']:.1f} sigma "
        f"at its best fit and {best['model']!r} comes within {MISFIT_SIGMAS:g} (each model's "
        "notes name the values): the fit, not PSIS-LOO, tells them apart"
        if MISFIT in other["note"] and MISFIT not in best["note"]
        else "; the data do not single out one model"
    )
    return [
        f"the best-ranked model {best['model']!r} is not distinguishable from "
        f"{other['model']!r}: {'; '.join(why)}{apart}"
    ]


def fitted_range_note(p: Parameter, draws: np.ndarray, rate: str | None) -> str | None:
    """A line when the posterior draws of the flat property ``p`` pile against an end of the
    range that the built-in rate law ``rate`` is fitted for (``contact.rate.FittedFor``: beyond
    it every case is refused, a likelihood of zero) where that end lies inside the prior (more
    than EDGE_SHARE of the draws in the outer EDGE_MASS of the prior's mass inside the range),
    or None: the posterior is cut there by the law, not by the data."""
    law = RATE_LAWS.get(rate or "")
    field = _FITTED.get(p.name)
    if law is None or law.fitted_for is None or field is None:
        return None
    lo, hi = getattr(law.fitted_for, field)
    a, b = max(p.low, lo), min(p.high, hi)
    x = np.asarray(draws, dtype=np.float64)
    x = x[np.isfinite(x)]
    ca, cb = (float(v) for v in p.cdf(np.array([a, b])))
    if x.size == 0 or not cb > ca:
        return None
    u = (p.cdf(x) - ca) / (cb - ca)
    for side, share, end, inside in (
        ("upper", float(np.mean(u > 1.0 - EDGE_MASS)), hi, hi < p.high),
        ("lower", float(np.mean(u < EDGE_MASS)), lo, lo > p.low),
    ):
        if not (inside and share > EDGE_SHARE):
            continue
        return (
            f"{p.name}: the posterior lies against the {side} end of the range the rate law "
            f"{rate!r} is fitted for ({shown(p.name, p.unit, end)}; {law.fitted_for.name}: "
            f"{shown(p.name, p.unit, lo)} to {shown(p.name, p.unit, hi)}; {100 * share:.0f} % "
            f"of the draws in the outer {100 * EDGE_MASS:.0f} % of the prior's mass inside "
            "it): beyond it the model refuses every case, so the law cuts the posterior off, not "
            "the data (the law's constants hold for that material only: a flat outside it "
            "needs its own, or a model without the rate law)"
        )
    return None
