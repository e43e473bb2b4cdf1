"""The ranking of candidate models: PSIS-LOO, the expected log predictive density of each
drop left out in turn (Vehtari, Gelman & Gabry 2017), estimated from the posterior's pointwise
log likelihoods by Pareto-smoothed importance sampling (``result.summarise``), and compared
here as ``arviz.compare`` does (elpd_diff and its standard error dse from the pointwise
differences), with stacking weights (Yao, Vehtari, Simpson & Gelman 2018,
doi:10.1214/17-BA1091) computed in log space: ``arviz.compare`` exponentiates each drop's elpd
as it is, so that a drop every model predicts poorly (elpd below about -745) underflows to 0,
its log to -inf, and the optimiser stops at its start (equal weights). Why a cross-validated
score rather than the evidence: it asks how well a model predicts a drop it was not fitted to,
it does not depend on the width of a uniform prior that the evidence penalises, and it comes
from the same chain. With few drops its standard errors are large: a difference means
something when it is at least 2 dse and 4 nats (below 4, dse itself is unreliable: Sivula,
Magnusson, Matamoros & Vehtari, arXiv:2008.10296, 2020), and only where both models' PSIS-LOO
holds (every Pareto k <= 0.7); each row says whether its model is distinguishable from the
best and whether its chain converged. With one drop PSIS-LOO does not rank (leaving the drop
out leaves no data; dse is 0): no model is distinguishable then, whatever the elpd_diff and
the weights say."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
from scipy.optimize import minimize
from scipy.special import logsumexp

from impactlab.calibrate.diagnostics import MISFIT_SIGMAS, edge_note
from impactlab.calibrate.result import ModelPosterior

__all__ = ["annotate", "distinguishable", "misfit_max", "rank_models", "stacking_weights"]


def stacking_weights(elpd: np.ndarray) -> np.ndarray:
    """Stacking weights (Yao et al. 2018, doi:10.1214/17-BA1091) of K models from their
    pointwise elpd (N drops x K models): the w on the simplex that maximise
    sum_i log sum_k w_k exp(elpd_ik), computed as a log-sum-exp (no underflow however
    negative the elpd), by SLSQP from equal weights. A non-finite elpd counts as -inf (that
    model gives the drop no density); a drop with no finite elpd carries no information and is
    left out; with none left, or one model, the weights are equal."""
    e = np.asarray(elpd, dtype=np.float64)
    if e.ndim != 2:
        raise ValueError(f"elpd must be an (N drops, K models) array, got shape {e.shape}")
    k = e.shape[1]
    e = np.where(np.isfinite(e), e, -np.inf)
    e = e[np.isfinite(e).any(axis=1)]
    if k < 2 or e.shape[0] == 0:
        return np.full(k, 1.0 / max(k, 1))
    e = e - e.max(axis=1, keepdims=True)  # each drop's best model at 0: a constant per drop

    def terms(w: np.ndarray) -> np.ndarray:
        with np.errstate(divide="ignore"):
            return np.asarray(logsumexp(e + np.log(np.clip(w, 0.0, None)), axis=1))

    def loss(w: np.ndarray) -> float:
        return -float(np.sum(terms(w)))

    def grad(w: np.ndarray) -> np.ndarray:
        with np.errstate(invalid="ignore", over="ignore"):
            g = -np.exp(e - terms(w)[:, None]).sum(axis=0)
        return np.nan_to_num(g, nan=0.0, neginf=-1e300)

    res = minimize(
        loss, np.full(k, 1.0 / k), jac=grad, method="SLSQP", bounds=[(0.0, 1.0)] * k,
        constraints=[{"type": "eq", "fun": lambda w: np.sum(w) - 1.0, "jac": lambda w: np.ones(k)}],
        options={"ftol": 1e-12, "maxiter": 500},
    )  # fmt: skip
    w = np.clip(np.asarray(res.x, dtype=np.float64), 0.0, None)
    return w / w.sum() if w.sum() > 0 else np.full(k, 1.0 / k)


def rank_models(posteriors: Mapping[str, ModelPosterior]) -> list[dict[str, Any]]:
    """Rows best first: model, rank, elpd_loo, se, elpd_diff (to the best), dse (its standard
    error: sqrt(N var) of the pointwise differences, as ``arviz.compare``), p_loo, weight
    (stacking: ``stacking_weights``), warning (Pareto k > 0.7 somewhere), pareto_k_max,
    converged (the model's chain: ``ModelPosterior.converged``), law_extrapolated (the share of
    its predicted impacts that used its law beyond the verified range:
    ``ModelPosterior.law_extrapolated``), misfit_max (the largest |z| of its best fit),
    distinguishable and note (``annotate``)."""
    usable = {k: v for k, v in posteriors.items() if v.loo}
    if not usable:
        return []
    drops = int(next(iter(usable.values())).log_lik.shape[-1])
    order = sorted(usable, key=lambda k: _sort_key(usable[k].loo["elpd"]))
    best = usable[order[0]]
    pointwise = np.column_stack([_pointwise(usable[k], drops) for k in order])
    weights = stacking_weights(pointwise) if len(order) > 1 else np.ones(1)
    rows = []
    for i, name in enumerate(order):
        p = usable[name]
        diff = pointwise[:, 0] - pointwise[:, i]
        with np.errstate(invalid="ignore"):
            dse = math.sqrt(diff.size * float(np.var(diff))) if i else 0.0
        rows.append(
            {
                "model": name,
                "rank": i,
                "elpd_loo": float(p.loo["elpd"]),
                "se": float(p.loo["se"]),
                "elpd_diff": float(best.loo["elpd"] - p.loo["elpd"]) if i else 0.0,
                "dse": dse,
                "p_loo": float(p.loo["p_loo"]),
                "weight": float(weights[i]),
                "warning": bool(p.loo["n_bad_k"]),
            }
        )
    return annotate(rows, posteriors, drops=drops)


def _sort_key(elpd: float) -> tuple[bool, float]:
    """Best (highest elpd) first; an elpd that is not a number last."""
    return (math.isnan(elpd), -elpd if not math.isnan(elpd) else 0.0)


def _pointwise(post: ModelPosterior, drops: int) -> np.ndarray:
    """A model's pointwise elpd (NaN where not known)."""
    e = np.asarray(post.loo_pointwise, dtype=np.float64).ravel()
    return e if e.size == drops else np.full(drops, np.nan)


#: A difference of elpd smaller than this many of its standard errors does not tell two
#: models apart.
DSE_MULTIPLE = 2.0
#: A difference of elpd [nats] below which two models are not told apart whatever its standard
#: error: their predictions differ little, and dse is then poorly estimated (Sivula et
#: al. 2020, arXiv:2008.10296).
ELPD_DIFF_MIN = 4.0
#: The Pareto k above which a drop's PSIS-LOO elpd is unreliable (Vehtari, Gelman & Gabry
#: 2017, doi:10.1007/s11222-016-9696-4): with such a drop in either model an elpd_diff is not
#: trusted to tell them apart.
PARETO_K_MAX = 0.7
NOT_DISTINGUISHABLE = "not distinguishable (elpd_diff < 2 dse)"
SMALL_DIFFERENCE = "not distinguishable (elpd_diff < 4)"
UNRELIABLE_LOO = "not distinguishable (Pareto k > 0.7: PSIS-LOO unreliable)"
#: The note of every row of a ranking over one drop.
NOT_RANKED = "not distinguishable (one drop: PSIS-LOO does not rank)"
NOT_CONVERGED = "not converged"
#: The note of a row whose model's best fit lies more than MISFIT_SIGMAS standard uncertainties
#: from a measured value (``misfit_max``): PSIS-LOO may still not tell it from the best (few
#: drops, large dse), but the model does not describe that value.
MISFIT = f"misfit (best fit > {MISFIT_SIGMAS:g} sigma from a measured value)"
#: The note of a row whose posterior lies against a finite bound of a prior
#: (``diagnostics.edge_note``): its interval there is the prior's cut, not the data's.
AT_BOUND = "at a prior bound (its interval is cut there)"


def misfit_max(post: Any) -> float:
    """The largest |z| of a model's best fit over the measured values (``ModelPosterior.ppc``'s
    ``z_best``: (best - observed) / sigma) [1]; infinite where a best fit is not a number, NaN
    where nothing was predicted."""
    zs = [abs(float(r["z_best"])) for r in getattr(post, "ppc", None) or ()]
    return max((z if math.isfinite(z) else math.inf for z in zs), default=math.nan)


def _why_not(row: Mapping[str, Any], drops: int | None) -> str:
    """Why a ranked row's elpd_diff does not tell it from the best (or ""): one ``drops``,
    elpd_diff below DSE_MULTIPLE of its standard error (a tie, a dse that is 0 or not a number
    too), or below ELPD_DIFF_MIN."""
    diff, dse = float(row["elpd_diff"]), float(row["dse"])
    if drops is not None and drops < 2:
        return NOT_RANKED
    if not (diff > 0.0 and dse > 0.0 and diff >= DSE_MULTIPLE * dse):
        return NOT_DISTINGUISHABLE
    return SMALL_DIFFERENCE if diff < ELPD_DIFF_MIN else ""


def distinguishable(row: Mapping[str, Any], drops: int | None = None) -> bool:
    """Whether a ranked model's elpd differs from the best's by at least DSE_MULTIPLE of its
    standard error and by ELPD_DIFF_MIN: never for a tie (elpd_diff 0), a standard error that
    is 0 or not a number (nothing to judge the difference by), or fewer than 2 ``drops``
    (None: not known). The Pareto k of the two models is ``annotate``'s."""
    return not _why_not(row, drops)


def _at_bound(post: Any) -> bool:
    """Whether a model's posterior lies against a finite bound of a prior (``edge_note``)."""
    samples = getattr(post, "samples", None)
    if samples is None or np.ndim(samples) != 2:
        return False
    return any(
        edge_note(p, samples[:, j]) is not None for j, p in enumerate(getattr(post, "params", ()))
    )


def _unreliable(post: Any) -> bool:
    """Whether a model's PSIS-LOO has a drop with Pareto k > PARETO_K_MAX."""
    return bool(float(post.loo.get("pareto_k_max", math.nan)) > PARETO_K_MAX)


def annotate(
    rows: list[dict[str, Any]],
    posteriors: Mapping[str, ModelPosterior],
    *,
    drops: int | None = None,
) -> list[dict[str, Any]]:
    """``rows`` (best first) with pareto_k_max, converged, law_extrapolated, misfit_max
    (``misfit_max``), distinguishable
    (from the best; the best's: from the runner-up; None for a single model, False for every
    row when there are fewer than 2 ``drops``, None: not known) and note (what makes the row's
    place unsure: ``NOT_RANKED`` over one drop, ``NOT_DISTINGUISHABLE`` or
    ``SMALL_DIFFERENCE``; ``UNRELIABLE_LOO`` when either model compared has a drop with
    Pareto k > 0.7 (its elpd_diff is not trusted; ``distinguishable`` False); ``NOT_CONVERGED``;
    ``MISFIT`` when misfit_max exceeds MISFIT_SIGMAS (``distinguishable`` is PSIS-LOO's alone);
    ``AT_BOUND`` when its posterior lies against a prior's bound; joined by "; ")."""
    for i, r in enumerate(rows):
        post = posteriors[r["model"]]
        r["pareto_k_max"] = float(post.loo.get("pareto_k_max", math.nan))
        r["converged"] = post.converged
        found = getattr(post, "law_extrapolated", None) or {}  # {}: not known
        r["law_extrapolated"] = float(found.get("share", math.nan))
        r["misfit_max"] = misfit_max(post)
        notes = []
        if len(rows) > 1:
            other = rows[1] if i == 0 else r
            why = _why_not(other, drops)
            notes = [why] if why else []
            pair = (rows[0]["model"], other["model"])
            if why != NOT_RANKED and any(_unreliable(posteriors[n]) for n in pair):
                notes.append(UNRELIABLE_LOO)
        r["distinguishable"] = None if len(rows) == 1 else not notes
        notes += [] if post.converged else [NOT_CONVERGED]
        notes += [MISFIT] if r["misfit_max"] > MISFIT_SIGMAS else []
        notes += [AT_BOUND] if _at_bound(post) else []
        r["note"] = "; ".join(notes)
    return rows
