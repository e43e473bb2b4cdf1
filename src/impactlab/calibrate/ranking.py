"""The ranking of candidate models: PSIS-LOO, the expected log predictive density of each
drop left out in turn (Vehtari, Gelman & Gabry 2017), estimated from the posterior's pointwise
log likelihoods by Pareto-smoothed importance sampling, and compared with ``arviz.compare``
(stacking weights). Why a cross-validated score rather than the evidence: it asks how well a
model predicts a drop it was not fitted to, it does not depend on the width of a uniform prior
that the evidence penalises, and it comes from the same chain. With few drops its standard
errors are large: ``dse`` says whether a difference means anything (about 2 dse or more); each
row says whether its model is distinguishable from the best and whether its chain converged.
With one drop PSIS-LOO does not rank (leaving the drop out leaves no data; dse is 0): no model
is distinguishable then, whatever the elpd_diff and the weights say."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from impactlab.calibrate._arviz import az, quiet
from impactlab.calibrate.result import ModelPosterior

__all__ = ["annotate", "distinguishable", "rank_models"]


def rank_models(posteriors: Mapping[str, ModelPosterior]) -> list[dict[str, Any]]:
    """Rows best first: model, rank, elpd_loo, se, elpd_diff (to the best), dse (its standard
    error), p_loo, weight (stacking), warning (Pareto k > 0.7 somewhere), pareto_k_max,
    converged (the model's chain: ``ModelPosterior.converged``), distinguishable and note
    (``annotate``)."""
    usable = {k: v for k, v in posteriors.items() if v.loo}
    if not usable:
        return []
    drops = int(next(iter(usable.values())).log_lik.shape[-1])
    if len(usable) == 1:
        ((name, p),) = usable.items()
        rows = [
            {
                "model": name,
                "rank": 0,
                "elpd_loo": p.loo["elpd"],
                "se": p.loo["se"],
                "elpd_diff": 0.0,
                "dse": 0.0,
                "p_loo": p.loo["p_loo"],
                "weight": 1.0,
                "warning": bool(p.loo["n_bad_k"]),
            }
        ]
        return annotate(rows, posteriors, drops=drops)
    with quiet():
        table = az.compare({k: v.idata() for k, v in usable.items()}, ic="loo")
    rows = []
    for name, r in table.iterrows():
        rows.append(
            {
                "model": str(name),
                "rank": int(r["rank"]),
                "elpd_loo": float(r["elpd_loo"]),
                "se": float(r["se"]),
                "elpd_diff": float(r["elpd_diff"]),
                "dse": float(r["dse"]),
                "p_loo": float(r["p_loo"]),
                "weight": float(r["weight"]),
                "warning": bool(r["warning"]),
            }
        )
    return annotate(rows, posteriors, drops=drops)


#: A difference of elpd smaller than this many of its standard errors does not tell two
#: models apart.
DSE_MULTIPLE = 2.0
NOT_DISTINGUISHABLE = "not distinguishable (elpd_diff < 2 dse)"
#: The note of every row of a ranking over one drop.
NOT_RANKED = "not distinguishable (one drop: PSIS-LOO does not rank)"
NOT_CONVERGED = "not converged"


def distinguishable(row: Mapping[str, Any], drops: int | None = None) -> bool:
    """Whether a ranked model's elpd differs from the best's by at least DSE_MULTIPLE of its
    standard error: never for a tie (elpd_diff 0), a standard error that is 0 or not a number
    (nothing to judge the difference by), or fewer than 2 ``drops`` (None: not known)."""
    diff, dse = float(row["elpd_diff"]), float(row["dse"])
    if drops is not None and drops < 2:
        return False
    return diff > 0.0 and dse > 0.0 and diff >= DSE_MULTIPLE * dse


def annotate(
    rows: list[dict[str, Any]],
    posteriors: Mapping[str, ModelPosterior],
    *,
    drops: int | None = None,
) -> list[dict[str, Any]]:
    """``rows`` (best first) with pareto_k_max, converged, distinguishable (from the best; the
    best's: from the runner-up; None for a single model, False for every row when there are
    fewer than 2 ``drops``, None: not known) and note (what makes the row's place unsure:
    ``NOT_DISTINGUISHABLE`` or, over one drop, ``NOT_RANKED``; ``NOT_CONVERGED``; joined by
    "; ")."""
    one = drops is not None and drops < 2
    for i, r in enumerate(rows):
        post = posteriors[r["model"]]
        r["pareto_k_max"] = float(post.loo.get("pareto_k_max", math.nan))
        r["converged"] = post.converged
        other = rows[1] if i == 0 and len(rows) > 1 else r
        r["distinguishable"] = None if len(rows) == 1 else distinguishable(other, drops)
        why = NOT_RANKED if one else NOT_DISTINGUISHABLE
        notes = [why] if r["distinguishable"] is False else []
        notes += [] if post.converged else [NOT_CONVERGED]
        r["note"] = "; ".join(notes)
    return rows
