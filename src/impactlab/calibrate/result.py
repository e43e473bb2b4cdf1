"""One model's calibration: posterior, best fit, diagnostics, leave-one-drop-out score and
posterior predictive checks (ArviZ for R-hat, ESS and PSIS-LOO)."""

from __future__ import annotations

import logging
import math
from collections.abc import Collection
from dataclasses import dataclass, field
from typing import Any

import emcee
import numpy as np
from scipy.special import logsumexp

from impactlab._html import grid_html
from impactlab.calibrate._arviz import az, quiet, recording
from impactlab.calibrate.diagnostics import MISFIT_SIGMAS, convergence_notes, misfit_text
from impactlab.calibrate.display import POSTERIOR_HEAD, posterior_rows, posterior_text
from impactlab.calibrate.models import Prediction
from impactlab.calibrate.posterior import LogPosterior
from impactlab.calibrate.priors import Parameter
from impactlab.calibrate.quantities import MEASURABLE

__all__ = ["ONE_DROP", "ModelPosterior", "summarise"]

#: What a calibration on one drop says (a note of each model and a warning of the calibration).
ONE_DROP = (
    "PSIS-LOO with one drop: leaving it out leaves no data, so elpd_loo does not rank the "
    "models (give at least two drops)"
)

#: Central credible interval reported (and checked by the coverage test): 90 %.
INTERVAL = (0.05, 0.95)


@dataclass(repr=False)
class ModelPosterior:
    """The calibration of one candidate model (SI units).

    samples : (N, P) posterior draws after burn-in (walkers x steps, flattened);
    chains : (walkers, draws, P) the same draws by walker (for the diagnostics);
    log_lik : (walkers, draws, D) pointwise log likelihood of each drop;
    summary : parameter -> {mean, sd, median, q05, q95, rhat, ess_bulk, tau};
    best : parameter -> value at the largest posterior density found;
    loo : {elpd, se, p_loo, pareto_k_max, n_bad_k} (PSIS-LOO over drops) or {} when it failed;
    ppc : one dict per measured value: drop, quantity, observed, sigma, best, median, q05, q95
        (the model's prediction) and pred_q05/q95 (with the measurement noise), z_best;
    failures : failed cases by reason; evaluations : cases run; draws, failed_draws : the
    parameter vectors run in this run (starting draws, proposals, predictive check) and those
    with a failed case; law_extrapolated : {share, impacts, basis}: the share of the ``impacts``
    predicted at ``basis`` (the predictive check's posterior draws, or the best fit when it
    re-ran none) whose contact law was used beyond its verified range (the advisory
    LAW_EXTRAPOLATED flag; share NaN when none ran); loo_pointwise : (D,) each drop's PSIS-LOO
    elpd (empty when PSIS-LOO failed); acceptance : the walkers' mean acceptance fraction over
    the ``steps`` used (``_acceptance``); steps, burn : the chain's steps used and discarded
    (a saved chain longer than ``steps``, from an earlier run, is used up to ``steps``);
    warnings : what the diagnostics found (R-hat, autocorrelation time, Pareto k, misfits, a
    prior's bound, an extrapolated law, many failed values); convergence : those of the
    warnings that say the chain has not converged or cannot tell (``converged`` is True when
    there are none).
    """

    model: str
    params: tuple[Parameter, ...]
    samples: np.ndarray
    chains: np.ndarray
    log_lik: np.ndarray
    summary: dict[str, dict[str, float]]
    best: dict[str, float]
    best_log_prob: float
    loo: dict[str, float]
    ppc: list[dict[str, Any]]
    failures: dict[str, int]
    evaluations: int
    acceptance: float
    steps: int
    burn: int
    warnings: list[str] = field(default_factory=list)
    convergence: list[str] = field(default_factory=list)
    draws: int = 0
    failed_draws: int = 0
    law_extrapolated: dict[str, Any] = field(default_factory=dict)
    loo_pointwise: np.ndarray = field(default_factory=lambda: np.zeros(0))

    @property
    def converged(self) -> bool:
        """True when the diagnostics found no convergence problem (``convergence``)."""
        return not self.convergence

    def __repr__(self) -> str:
        return posterior_text(self)

    def _repr_html_(self) -> str:
        return grid_html(self.model, POSTERIOR_HEAD, posterior_rows(self))

    @property
    def names(self) -> tuple[str, ...]:
        """The free parameters' names."""
        return tuple(p.name for p in self.params)

    def interval(self, name: str) -> tuple[float, float]:
        """The 90 % central credible interval of ``name``."""
        s = self.summary[name]
        return s["q05"], s["q95"]

    def idata(self) -> Any:
        """The posterior and pointwise log likelihood as ArviZ InferenceData (walkers as
        chains)."""
        post = {n: self.chains[:, :, j] for j, n in enumerate(self.names)}
        with quiet():
            return az.from_dict(posterior=post, log_likelihood={"drops": self.log_lik})

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready summary (no draws)."""
        return {
            "model": self.model,
            "parameters": {
                p.name: {"prior": p.describe(), "unit": p.unit, **self.summary[p.name]}
                for p in self.params
            },
            "best": {"values": self.best, "log_posterior": self.best_log_prob},
            "loo": self.loo,
            "ppc": self.ppc,
            "failures": self.failures,
            "evaluations": self.evaluations,
            "draws": self.draws,
            "failed_draws": self.failed_draws,
            "law_extrapolated": self.law_extrapolated,
            "acceptance": self.acceptance,
            "steps": self.steps,
            "burn": self.burn,
            "converged": self.converged,
            "warnings": self.warnings,
        }


def _loo(idata: Any) -> tuple[dict[str, float], list[str], np.ndarray]:
    """PSIS-LOO over drops, each drop's elpd, and the notes to show: drops with Pareto k > 0.7,
    one drop only, a result that is not finite. A drop whose log likelihood is the same at
    every draw has its exact elpd and k = 0 (``_exact_drops``). numpy's overflow warnings
    from inside ArviZ's smoothing are dropped: ``exp`` of the differences of the Pareto fit's
    log likelihoods over its grid (more than 709) gives that grid point the weight 0, its
    right limit (the loo package computes the same in log space), and ``expm1`` of a tail with
    a shape k far above 0.7 gives weights that ArviZ truncates to the largest raw one; what
    they point at, a tail the smoothing cannot tame, is the Pareto k note."""
    with recording() as caught:
        try:
            r = az.loo(idata, pointwise=True)
        except (ValueError, TypeError, IndexError) as exc:
            return {}, [f"PSIS-LOO failed: {exc}"], np.zeros(0)
    k = np.asarray(r.pareto_k, dtype=np.float64).ravel()
    loo_i = np.asarray(r.loo_i, dtype=np.float64).ravel()
    out = {"elpd": float(r.elpd_loo), "se": float(r.se), "p_loo": float(r.p_loo)}
    _exact_drops(idata, k, loo_i, out)
    out["pareto_k_max"] = float(np.max(k))
    out["n_bad_k"] = int(np.sum(k > 0.7))
    notes = [f"PSIS-LOO: {out['n_bad_k']} drop(s) with Pareto k > 0.7"] if out["n_bad_k"] else []
    if not (math.isfinite(out["elpd"]) and math.isfinite(out["se"])):
        notes.append(
            f"PSIS-LOO: elpd_loo = {out['elpd']:g} +- {out['se']:g} is not a finite number: "
            "this model's rank is unreliable"
        )
    for w in caught:
        text = str(w.message).splitlines()[0]
        if "Pareto" in text or (
            issubclass(w.category, RuntimeWarning) and text.startswith("overflow encountered")
        ):
            continue
        if "point-wise LOO is the same with the sum LOO" in text:  # ArviZ, one observation
            text = ONE_DROP
        if text not in notes:
            notes.append(text)
    return out, notes, loo_i


#: A drop whose log likelihood spreads less than this over the draws [nats] has an exact
#: leave-one-out density: its importance ratios are all 1 (within 1e-9).
CONSTANT_LOG_LIK = 1e-9


def _exact_drops(idata: Any, k: np.ndarray, loo_i: np.ndarray, out: dict[str, float]) -> None:
    """The drops whose log likelihood is the same at every draw (a model with no free
    parameter it uses: the rigid rod beside a free modal damping) have an exact leave-one-out
    elpd, the log of that likelihood (p(y_i | y_-i) = p(y_i | theta) for every theta), where
    ArviZ fits a Pareto tail to constant ratios and gives k = inf: set in ``k`` (to 0) and
    ``loo_i`` in place, ``out``'s elpd, se and p_loo recomputed as ArviZ does."""
    ll = np.asarray(idata.log_likelihood["drops"], dtype=np.float64)
    ll = ll.reshape(-1, ll.shape[-1])
    with np.errstate(invalid="ignore"):
        flat = np.ptp(ll, axis=0) <= CONSTANT_LOG_LIK
    if not flat.any() or ll.shape[1] != loo_i.size:
        return
    lppd = logsumexp(ll, axis=0) - math.log(ll.shape[0])
    k[flat], loo_i[flat] = 0.0, lppd[flat]
    out["elpd"] = float(loo_i.sum())
    out["se"] = math.sqrt(loo_i.size * float(np.var(loo_i)))
    out["p_loo"] = float(lppd.sum() - loo_i.sum())


def _rerun(
    post: LogPosterior, samples: np.ndarray, best: np.ndarray, rng: np.random.Generator, n: int
) -> Prediction | None:
    """The best fit (row 0) and ``n`` posterior draws re-run in one batch."""
    pick = samples[rng.choice(len(samples), size=min(n, len(samples)), replace=False)]
    return post.evaluate(np.vstack([best[None, :], pick]))[2]


def _extrapolated(pred: Prediction | None) -> dict[str, Any]:
    """{share, impacts, basis}: the share of the ok predicted impacts whose law was used
    beyond its verified range, over the re-run posterior draws (rows 1:), or the best fit (row
    0) when there are none; {} when not known."""
    if pred is None or pred.extrapolated is None:
        return {}
    n = pred.status.shape[0] - 1
    rows = slice(1, None) if n else slice(0, 1)
    ok = pred.status[rows] == 0
    impacts = int(np.count_nonzero(ok))
    share = float(np.count_nonzero(pred.extrapolated[rows] & ok)) / impacts if impacts else math.nan
    basis = f"{n} posterior draw{'s' if n != 1 else ''}" if n else "the best fit"
    return {"share": share, "impacts": impacts, "basis": basis}


def _ppc(
    post: LogPosterior, pred: Prediction | None, rng: np.random.Generator
) -> list[dict[str, Any]]:
    """Posterior predictive checks from ``pred`` (``_rerun``: the best fit, then the posterior
    draws); per measured value the prediction's median and 90 % band, the band with noise."""
    rows: list[dict[str, Any]] = []
    if pred is None:
        return rows
    meas = post.meas
    for q in meas.quantities:
        vals = pred.values[q]
        for d in np.flatnonzero(np.isfinite(meas.observed[q])):
            y, s = float(meas.observed[q][d]), float(meas.sigma[q][d])
            draws = vals[1:, d]
            ok = draws[np.isfinite(draws)]
            noisy = ok + s * rng.standard_normal(ok.size)
            qs = np.quantile(ok, [0.5, *INTERVAL]) if ok.size else [np.nan] * 3
            qn = np.quantile(noisy, INTERVAL) if ok.size else [np.nan] * 2
            rows.append(
                {
                    "drop": meas.labels[d],
                    "quantity": q,
                    "unit": MEASURABLE[q].unit,
                    "observed": y,
                    "sigma": s,
                    "best": float(vals[0, d]),
                    "median": float(qs[0]),
                    "q05": float(qs[1]),
                    "q95": float(qs[2]),
                    "pred_q05": float(qn[0]),
                    "pred_q95": float(qn[1]),
                    "z_best": float((vals[0, d] - y) / s),
                }
            )
    return rows


def _autocorr_time(chain: np.ndarray) -> np.ndarray:
    """emcee's integrated autocorrelation time per parameter [steps] (its note that the chain
    is short is replaced by the calibration's own warning)."""
    logger = logging.getLogger("emcee.autocorr")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.asarray(emcee.autocorr.integrated_time(chain, quiet=True))
    finally:
        logger.setLevel(level)


def _acceptance(sampler: emcee.EnsembleSampler, steps: int) -> float:
    """The walkers' mean acceptance fraction over the chain's first ``steps`` steps: emcee's
    (its count of accepted proposals per walker over the steps run) when the chain holds no
    more; of a longer saved chain, emcee's count less the steps after ``steps`` at which a
    walker moved (a stretch move's accepted proposal moves it; a rejected one keeps it where
    it was), over ``steps``."""
    accepted = np.asarray(sampler.backend.accepted, dtype=np.float64)
    saved = sampler.iteration
    if saved > steps:
        tail = sampler.get_chain()[steps - 1 :]  # (saved - steps + 1, W, P)
        accepted = accepted - np.any(tail[1:] != tail[:-1], axis=2).sum(axis=0)
    return float(np.mean(accepted / min(saved, steps)))


def _assessable_ess(ess: float, draws: int) -> float:
    """ArviZ's bulk ESS, or NaN (not assessable) where it exceeds the number of ``draws``: the
    draws of an ensemble are positively correlated, and ArviZ reports up to N log10 N (80.7
    of 48 draws) when a chain is too short to estimate it."""
    return ess if ess <= draws else math.nan


def summarise(
    post: LogPosterior,
    sampler: emcee.EnsembleSampler,
    *,
    steps: int,
    burn: int,
    seed: int,
    n_ppc: int = 200,
    unused: Collection[str] = (),
) -> ModelPosterior:
    """The ModelPosterior of a finished chain: its first ``steps`` steps (a saved chain may
    hold more, from an earlier longer run), draws after ``burn``; the ``unused`` parameters
    (those the model does not use) get no convergence notes."""
    saved = sampler.iteration
    chain = sampler.get_chain()[burn:steps]  # (S, W, P)
    blobs = np.asarray(sampler.get_blobs(), dtype=np.float64)[burn:steps]
    logp = sampler.get_log_prob()[:steps]
    blobs = blobs.reshape(chain.shape[0], chain.shape[1], -1)
    names = [p.name for p in post.params]
    chains = np.ascontiguousarray(chain.transpose(1, 0, 2))
    log_lik = np.ascontiguousarray(blobs.transpose(1, 0, 2))
    samples = chain.reshape(-1, chain.shape[2])
    with quiet():
        post_idata = az.from_dict(posterior={n: chains[:, :, j] for j, n in enumerate(names)})
        rhat = az.rhat(post_idata)
        ess = az.ess(post_idata, method="bulk")
    tau = _autocorr_time(chain)
    summary: dict[str, dict[str, float]] = {}
    for j, n in enumerate(names):
        x = samples[:, j]
        q05, q50, q95 = np.quantile(x, [INTERVAL[0], 0.5, INTERVAL[1]])
        summary[n] = {
            "mean": float(x.mean()),
            "sd": float(x.std(ddof=1)),
            "median": float(q50),
            "q05": float(q05),
            "q95": float(q95),
            "rhat": float(rhat[n]),
            "ess_bulk": _assessable_ess(float(ess[n]), x.size),
            "tau": float(tau[j]),
        }
    i_best = np.unravel_index(np.argmax(logp), logp.shape)
    best = sampler.get_chain()[:steps][i_best]
    with quiet():
        idata = az.from_dict(log_likelihood={"drops": log_lik})
        idata.add_groups(posterior=post_idata.posterior)
    loo, notes, pointwise = _loo(idata)
    unconverged = convergence_notes(summary, chain.shape[0], burn, samples.shape[0], unused)
    notes += unconverged
    if saved > steps:
        notes.append(
            f"the saved chain holds {saved} steps; the first {steps} are used (steps = {steps})"
        )
    rng = np.random.default_rng(seed + 1)
    pred = _rerun(post, samples, best, rng, n_ppc)
    ppc = _ppc(post, pred, rng)
    notes += [misfit_text(r) for r in ppc if abs(r["z_best"]) > MISFIT_SIGMAS]
    return ModelPosterior(
        model=post.model.name,
        params=tuple(post.params),
        samples=samples,
        chains=chains,
        log_lik=log_lik,
        summary=summary,
        best={n: float(best[j]) for j, n in enumerate(names)},
        best_log_prob=float(logp[i_best]),
        loo=loo,
        ppc=ppc,
        failures=dict(post.failures),
        evaluations=post.evaluations,
        acceptance=_acceptance(sampler, steps),
        steps=steps,
        burn=burn,
        warnings=notes,
        convergence=unconverged,
        draws=post.draws,
        failed_draws=post.failed_draws,
        law_extrapolated=_extrapolated(pred),
        loo_pointwise=pointwise,
    )
