"""Synthetic measurements made by the engine: known parameters plus Gaussian noise (for the
parameter-recovery and coverage checks, and for trying a calibration before an experiment).

A drop whose template gives correlation coefficients (``Measurements.correlation``,
``impactlab.calibrate.correlations``) gets noise of covariance D R D (D = diag(sigma), R its
correlation matrix), the covariance the likelihood gives its values: the same independent
standard normals as an independent drop, times the Cholesky factor of R. A drop without a
coefficient other than 0 keeps independent noise, bit for bit."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from impactlab.calibrate.correlations import check_drop
from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.models import CandidateModel, predict
from impactlab.calibrate.priors import Parameter

__all__ = ["synthetic_measurements"]


def _correlate(template: Measurements, normals: dict[str, np.ndarray]) -> None:
    """Turn, in ``normals`` (quantity -> (D,) independent standard normals), the values of
    each drop with a coefficient other than 0 into normals of its correlation matrix R (times
    the Cholesky factor of R); the other drops stay as they are."""
    for d in range(template.n_drops):
        pairs = {p: float(x[d]) for p, x in template.correlation.items() if not math.isnan(x[d])}
        if not any(pairs.values()):
            continue
        qs = [q for q in normals if math.isfinite(template.observed[q][d])]
        chol = np.linalg.cholesky(check_drop(f"drop {d + 1}", pairs, qs))
        mixed = chol @ np.array([normals[q][d] for q in qs])
        for q, v in zip(qs, mixed, strict=True):
            normals[q][d] = v


def synthetic_measurements(
    template: Measurements,
    model: CandidateModel,
    params: Sequence[Parameter],
    truth: Sequence[float],
    rng: np.random.Generator,
    *,
    engine: Mapping[str, Any] | None = None,
) -> Measurements:
    """``template``'s drops, uncertainties and correlation coefficients with values predicted
    by ``model`` at ``truth`` (the values of ``params``, SI) plus Gaussian noise of each
    value's sigma, correlated within a drop as its coefficients say (module docstring).
    ValueError when the model fails on a drop at ``truth``."""
    pred = predict(model, template, params, np.array([truth], dtype=np.float64), engine=engine)
    bad = np.flatnonzero(pred.status[0] != 0)
    if bad.size:
        raise ValueError(f"the model fails on drops {[template.labels[d] for d in bad]}")
    normals = {q: rng.standard_normal(y.shape) for q, y in template.observed.items()}
    _correlate(template, normals)
    observed = {}
    for q, y in template.observed.items():
        noisy = pred.values[q][0] + template.sigma[q] * normals[q]
        observed[q] = np.where(np.isfinite(y), noisy, np.nan)
    return replace(template, observed=observed, source=None)
