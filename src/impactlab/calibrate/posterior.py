"""The log posterior of one candidate model, vectorised over walkers.

Likelihood: each measured value is the model's prediction plus independent Gaussian noise of
its stated standard uncertainty, ``log N(y | f(theta), sigma^2)``; a drop contributes the sum
over its measured quantities. A drop with correlation coefficients other than 0
(``Measurements.correlation``) contributes instead the multivariate normal density of its
measured values, covariance D R D (D = diag(sigma), R its correlation matrix;
``correlated_likelihood.correlated_loglik``). A case the model cannot run (a law's limit, a
refused input) or whose result is not ``ok`` (an invalidating flag: ``models.STATUS_FLAGGED``)
has a likelihood of zero (log -inf); it is counted by reason in ``failures``, never raised.
One call evaluates every walker on every drop in one batch (``models.predict``).
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.calibrate.correlated_likelihood import correlated_loglik
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.models import (
    STATUS_REFUSED,
    CandidateModel,
    Prediction,
    predict,
    status_message,
)
from impactlab.calibrate.priors import Parameter
from impactlab.sweep.engine import ENGINE, Evaluator

__all__ = ["LogPosterior", "pointwise_loglik"]

_LOG_2PI = math.log(2.0 * math.pi)


def pointwise_loglik(pred: Prediction, meas: Measurements) -> np.ndarray:
    """(W, D) log likelihood of each drop's measured values (a drop with correlated values:
    their multivariate normal density); -inf where the case failed or a prediction is not
    finite."""
    w = pred.status.shape[0]
    ll = np.zeros((w, meas.n_drops))
    for q in meas.quantities:
        y, s = meas.observed[q], meas.sigma[q]
        have = np.isfinite(y)
        if not have.any():
            continue
        f = pred.values[q][:, have]
        with np.errstate(over="ignore"):  # a residual of many sigmas: a likelihood of zero
            r = (f - y[have]) / s[have]
            term = -0.5 * (r * r + _LOG_2PI) - np.log(s[have])
        ll[:, have] += np.where(np.isfinite(term), term, -np.inf)
    if meas.correlation:
        correlated_loglik(pred.values, meas, ll)
    ll[pred.status != 0] = -np.inf
    return ll


@dataclass
class LogPosterior:
    """``log p(theta | data)`` up to a constant, for emcee's vectorised ensemble: called with
    (W, P) parameter vectors, it returns one (log posterior, pointwise log likelihood (D,))
    pair per walker. ``failures`` counts the failed cases by reason (status message);
    ``evaluations`` the model evaluations (cases run); ``draws`` the parameter vectors run
    (inside the prior's support) and ``failed_draws`` those of them with a failed case (a
    likelihood of zero)."""

    model: CandidateModel
    meas: Measurements
    params: Sequence[Parameter]
    evaluator: Evaluator = ENGINE
    engine: Mapping[str, Any] = field(default_factory=dict)
    failures: Counter[str] = field(default_factory=Counter)
    evaluations: int = 0
    draws: int = 0
    failed_draws: int = 0
    _refusals: dict[str, str] = field(default_factory=dict, repr=False)

    def log_prior(self, theta: np.ndarray) -> np.ndarray:
        """(W,) log prior density."""
        lp = np.zeros(theta.shape[0])
        for j, p in enumerate(self.params):
            lp += p.logpdf(theta[:, j])
        return lp

    def evaluate(self, theta: np.ndarray) -> tuple[np.ndarray, np.ndarray, Prediction | None]:
        """(log posterior (W,), pointwise log likelihood (W, D), the prediction of the walkers
        inside the prior's support or None)."""
        theta = np.atleast_2d(np.asarray(theta, dtype=np.float64))
        lp = self.log_prior(theta)
        ll = np.full((theta.shape[0], self.meas.n_drops), -np.inf)
        inside = np.isfinite(lp)
        pred = None
        if inside.any():
            pred = predict(
                self.model,
                self.meas,
                self.params,
                theta[inside],
                evaluator=self.evaluator,
                engine=self.engine,
            )
            self.evaluations += int(pred.status.size)
            self.draws += int(pred.status.shape[0])
            self.failed_draws += int(np.count_nonzero((pred.status != 0).any(axis=1)))
            self._count(pred)
            ll[inside] = pointwise_loglik(pred, self.meas)
        total = lp + ll.sum(axis=1)
        total[~np.isfinite(total)] = -np.inf
        return total, ll, pred

    def _count(self, pred: Prediction) -> None:
        """Add the failed cases of ``pred`` to ``failures``: a case ``simulate`` refused by the
        error's text (the first seen of each reason, ``one_by_one.refusal_key``)."""
        codes, counts = np.unique(pred.status[pred.status != 0], return_counts=True)
        for c, k in zip(codes.tolist(), counts.tolist(), strict=True):
            if c == STATUS_REFUSED and pred.refused:
                for key, (n, text) in pred.refused.items():
                    why = self._refusals.setdefault(key, f"simulate refused the case: {text}")
                    self.failures[why] += n
                    k -= n
            if k > 0:
                self.failures[status_message(c)] += k

    def __call__(self, theta: np.ndarray) -> list[tuple[float, np.ndarray]]:
        total, ll, _ = self.evaluate(theta)
        return [(float(t), row) for t, row in zip(total, ll, strict=True)]


def initial_walkers(post: LogPosterior, n: int, rng: np.random.Generator) -> np.ndarray:
    """``n`` starting points drawn from the prior where the likelihood is not zero (up to 20
    rounds of 4n draws, one batch each). ValueError when the prior holds no such point: the
    model cannot produce the measurements anywhere in the prior (the reasons are named)."""
    found: list[np.ndarray] = []
    by_drop = _DropFailures(post.meas.n_drops)
    for _ in range(20):
        theta = np.column_stack([p.sample(4 * n, rng) for p in post.params])
        total, ll, pred = post.evaluate(theta)
        found += list(theta[np.isfinite(total)])
        if len(found) >= n:
            return np.array(found[:n])
        by_drop.add(ll, pred, np.isfinite(post.log_prior(theta)))
    if len(found) >= max(2 * len(post.params), 2):  # enough to start: repeat with jitter
        base = np.array(found)
        pick = base[rng.integers(0, len(base), n)]
        return pick * (1.0 + 1e-6 * rng.standard_normal(pick.shape))
    why = ", ".join(f"{k} ({v})" for k, v in post.failures.most_common(3)) or (
        "every run case is possible but no measured value has a finite likelihood"
    )
    raise ValueError(
        f"model {post.model.name!r}: no parameter value drawn from the prior "
        f"({'; '.join(p.describe() for p in post.params)}) gives a likelihood above zero "
        f"for the measurements; failed cases: {why}{by_drop.text(post.meas)}"
    )


class _DropFailures:
    """Per drop, of the parameter values drawn inside the prior: how many were drawn, at how
    many its likelihood was zero, and the reasons of its failed cases (status message ->
    count); ``text`` names the drops at fault."""

    def __init__(self, n_drops: int) -> None:
        self.drawn = 0
        self.zero = np.zeros(n_drops, dtype=np.int64)
        self.reasons: list[Counter[str]] = [Counter() for _ in range(n_drops)]

    def add(self, ll: np.ndarray, pred: Prediction | None, inside: np.ndarray) -> None:
        """Count one batch: ``ll`` (W, D) of every walker, ``inside`` (W,) those in the prior's
        support (the rows of ``pred``)."""
        self.drawn += int(inside.sum())
        self.zero += (~np.isfinite(ll[inside])).sum(axis=0)
        if pred is None:
            return
        for d in range(len(self.reasons)):
            codes, counts = np.unique(pred.status[:, d], return_counts=True)
            for c, k in zip(codes.tolist(), counts.tolist(), strict=True):
                if c != 0:
                    self.reasons[d][status_message(c)] += k

    def text(self, meas: Measurements) -> str:
        """``"; drops whose likelihood is zero at every value drawn: 'slow' (angle 20 deg, vy
        -0.002 m/s): result flagged ... (120)"``: the drops at fault (at most 5) with their
        incoming state and reasons; when no drop fails at every value, those that fail at some,
        with their share of the values drawn (each value fails one drop or another); empty
        when nothing was drawn."""
        if self.drawn == 0:
            return ""
        always = [d for d in range(len(self.zero)) if self.zero[d] == self.drawn]
        head = "drops whose likelihood is zero at every value drawn"
        if not always:
            always = sorted((d for d in range(len(self.zero)) if self.zero[d]),
                            key=lambda d: -self.zero[d])  # fmt: skip
            head = "each value drawn fails one drop or another; drops at fault"
        parts = []
        for d in always[:5]:
            reasons = ", ".join(f"{k} ({v})" for k, v in self.reasons[d].most_common(2))
            why = reasons or "every case ran, but the measured values have a likelihood of zero"
            share = self.zero[d] / self.drawn
            at = "" if share == 1.0 else f"at {100 * share:.0f} % of the values drawn: "
            parts.append(f"{meas.labels[d]!r} ({_inputs_text(meas, d)}): {at}{why}")
        more = f" and {len(always) - 5} more" if len(always) > 5 else ""
        return f"; {head}: {'; '.join(parts)}{more}" if parts else ""


def _inputs_text(meas: Measurements, d: int) -> str:
    """A drop's incoming state: ``angle 20 deg, vy -0.002 m/s`` (vx, spin where not 0)."""
    x = {k: float(v[d]) for k, v in meas.inputs.items() if k in ("angle", "vx", "vy", "spin")}
    out = (
        []
        if meas.categories[d].get("body") == "sphere"
        else [f"angle {math.degrees(x['angle']):.4g} deg"]
    )
    out += [f"{k} {x[k]:.4g} {u}" for k, u in (("vx", "m/s"), ("vy", "m/s"), ("spin", "rad/s"))
            if k in x and math.isfinite(x[k]) and (k == "vy" or x[k] != 0.0)]  # fmt: skip
    return ", ".join(out)
