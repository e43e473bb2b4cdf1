"""A calibration as the command line's JSON (docs/json-schema.md: every number with a fractional
part is a quantity object ``{"value", "unit"[, "sigma"]}`` in SI; counts stay integers)."""

from __future__ import annotations

from typing import Any

from impactlab._json import jsonable, quantity
from impactlab.calibrate.api import Calibration
from impactlab.calibrate.result import ModelPosterior

__all__ = ["calibration_json"]

_ONE = "1"


def _model(post: ModelPosterior) -> dict[str, Any]:
    params = {}
    for p in post.params:
        s = post.summary[p.name]
        params[p.name] = {
            "prior": p.describe(),
            **{k: quantity(s[k], p.unit) for k in ("median", "mean", "sd", "q05", "q95")},
            **{k: quantity(s[k], _ONE) for k in ("rhat", "ess_bulk", "tau")},
            "best": quantity(post.best[p.name], p.unit),
        }
    loo: dict[str, Any] = {k: quantity(v, _ONE) for k, v in post.loo.items() if k != "n_bad_k"}
    if "n_bad_k" in post.loo:
        loo["n_bad_k"] = int(post.loo["n_bad_k"])
    ppc = []
    for r in post.ppc:
        u = r["unit"]
        row: dict[str, Any] = {"drop": r["drop"], "quantity": r["quantity"]}
        row["observed"] = quantity(r["observed"], u, r["sigma"])
        for k in ("best", "median", "q05", "q95", "pred_q05", "pred_q95"):
            row[k] = quantity(r[k], u)
        row["z_best"] = quantity(r["z_best"], _ONE)
        ppc.append(row)
    return {
        "parameters": params,
        "log_posterior_best": quantity(post.best_log_prob, _ONE),
        "loo": loo,
        "ppc": ppc,
        "failures": {k: int(v) for k, v in post.failures.items()},
        "evaluations": int(post.evaluations),
        "acceptance": quantity(post.acceptance, _ONE),
        "steps": int(post.steps),
        "burn": int(post.burn),
        "warnings": list(post.warnings),
    }


def calibration_json(cal: Calibration) -> dict[str, Any]:
    """The JSON object of ``impactlab calibrate --json``."""
    ranking = [
        {
            "model": r["model"],
            "rank": int(r["rank"]) + 1,  # 1 = best, as the table and calibration.json
            **{
                k: quantity(r[k], _ONE)
                for k in ("elpd_loo", "se", "elpd_diff", "dse", "p_loo", "weight")
            },
            "pareto_k_warning": bool(r["warning"]),
        }
        for r in cal.ranking
    ]
    m = cal.measurements
    return jsonable(
        {
            "measurements": {
                "source": m.source,
                "drops": list(m.labels),
                "quantities": list(m.quantities),
                "values": m.n_values,
            },
            "settings": {k: v for k, v in cal.settings.items()},
            "criterion": "PSIS-LOO elpd over drops (higher is better)",
            "ranking": ranking,
            "models": {k: _model(v) for k, v in cal.posteriors.items()},
            "warnings": list(cal.warnings),
        }
    )
