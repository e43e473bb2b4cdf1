"""A calibration as the command line's JSON (docs/json-schema.md: every number with a fractional
part is a quantity object ``{"value", "unit"[, "sigma"]}``, in SI or the unit it names (a
Brinell hardness in kgf/mm^2, an autocorrelation time in steps); counts stay integers)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

from impactlab._json import jsonable, quantity
from impactlab._version import __version__
from impactlab.calibrate.api import Calibration
from impactlab.calibrate.correlated_likelihood import correlation_rows
from impactlab.calibrate.result import ModelPosterior
from impactlab.contact import get_law
from impactlab.sweep.inputs import INPUTS

__all__ = ["calibration_json"]

_ONE = "1"


def _model(post: ModelPosterior) -> dict[str, Any]:
    params = {}
    for p in post.params:
        s = post.summary[p.name]
        params[p.name] = {
            "prior": p.describe(),
            **{k: quantity(s[k], p.unit) for k in ("median", "mean", "sd", "q05", "q95")},
            **{k: quantity(s[k], _ONE) for k in ("rhat", "ess_bulk")},
            "tau": quantity(s["tau"], _ONE),  # in steps of the chain
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
        "draws": int(post.draws),
        "failed_draws": int(post.failed_draws),
        "law_extrapolated": _extrapolated(post.law_extrapolated),
        "acceptance": quantity(post.acceptance, _ONE),
        "steps": int(post.steps),
        "burn": int(post.burn),
        "converged": post.converged,
        "warnings": list(post.warnings),
    }


def _extrapolated(found: Mapping[str, Any]) -> dict[str, Any]:
    """``ModelPosterior.law_extrapolated`` with its share as a quantity ({} when not known)."""
    if not found:
        return {}
    return {**found, "share": quantity(float(found["share"]), _ONE)}


def _law_params(law: str, given: Mapping[str, Any]) -> dict[str, Any]:
    try:
        units = {q.name: q.unit for q in get_law(law).parameters if q.unit not in ("-", "", "1")}
    except (ValueError, AttributeError):
        units = {}
    return {
        k: quantity(v, units.get(k) or _ONE) if isinstance(v, float) else v
        for k, v in given.items()
    }


def _settings(settings: Mapping[str, Any]) -> dict[str, Any]:
    """The settings, their numbers as quantities: the engine's gravity and rtol, the values
    each model fixes (in the input's unit) and its law parameters (in the law's)."""
    out = dict(settings)
    eng = dict(out.get("engine", {}))
    if "gravity" in eng:
        eng["gravity"] = quantity(eng["gravity"], "m/s^2")
    if eng.get("rtol") is not None:
        eng["rtol"] = quantity(float(eng["rtol"]), _ONE)
    out["engine"] = eng
    defs = {}
    for name, d in out.get("model_definitions", {}).items():
        fixed = {k: quantity(v, INPUTS[k].unit) for k, v in d.get("fixed", {}).items()}
        defs[name] = {**d, "fixed": fixed, "law_params": _law_params(d["law"], d["law_params"])}
    out["model_definitions"] = defs
    return out


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
            "pareto_k_max": quantity(r["pareto_k_max"], _ONE),
            "converged": bool(r["converged"]),
            "law_extrapolated": quantity(r["law_extrapolated"], _ONE),
            "misfit_max": quantity(r.get("misfit_max", math.nan), _ONE),
            "distinguishable": r["distinguishable"],
            "note": r["note"],
        }
        for r in cal.ranking
    ]
    m = cal.measurements
    return jsonable(
        {
            "impactlab_version": __version__,
            "measurements": {
                "source": m.source,
                "drops": list(m.labels),
                "quantities": list(m.quantities),
                "values": m.n_values,
                "correlation": [
                    {**r, "coefficient": quantity(r["coefficient"], _ONE)}
                    for r in correlation_rows(m)
                ],
            },
            "settings": _settings(cal.settings),
            "criterion": "PSIS-LOO elpd over drops (higher is better)",
            "ranking": ranking,
            "models": {k: _model(v) for k, v in cal.posteriors.items()},
            "warnings": list(cal.warnings),
        }
    )
