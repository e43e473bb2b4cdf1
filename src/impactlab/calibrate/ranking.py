"""The ranking of candidate models: PSIS-LOO, the expected log predictive density of each
drop left out in turn (Vehtari, Gelman & Gabry 2017), estimated from the posterior's pointwise
log likelihoods by Pareto-smoothed importance sampling, and compared with ``arviz.compare``
(stacking weights). Why a cross-validated score rather than the evidence: it asks how well a
model predicts a drop it was not fitted to, it does not depend on the width of a uniform prior
that the evidence penalises, and it comes from the same chain. With few drops its standard
errors are large: ``dse`` says whether a difference means anything (about 2 dse or more)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from impactlab.calibrate._arviz import az, quiet
from impactlab.calibrate.result import ModelPosterior

__all__ = ["rank_models"]


def rank_models(posteriors: Mapping[str, ModelPosterior]) -> list[dict[str, Any]]:
    """Rows best first: model, rank, elpd_loo, se, elpd_diff (to the best), dse (its standard
    error), p_loo, weight (stacking), warning (Pareto k > 0.7 somewhere)."""
    usable = {k: v for k, v in posteriors.items() if v.loo}
    if not usable:
        return []
    if len(usable) == 1:
        ((name, p),) = usable.items()
        return [
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
    return rows
