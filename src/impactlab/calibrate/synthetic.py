"""Synthetic measurements made by the engine: known parameters plus Gaussian noise (for the
parameter-recovery and coverage checks, and for trying a calibration before an experiment)."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

import numpy as np

from impactlab.calibrate.measurements import Measurements
from impactlab.calibrate.models import CandidateModel, predict
from impactlab.calibrate.priors import Parameter

__all__ = ["synthetic_measurements"]


def synthetic_measurements(
    template: Measurements,
    model: CandidateModel,
    params: Sequence[Parameter],
    truth: Sequence[float],
    rng: np.random.Generator,
    *,
    engine: Mapping[str, Any] | None = None,
) -> Measurements:
    """``template``'s drops and uncertainties with values predicted by ``model`` at ``truth``
    (the values of ``params``, SI) plus Gaussian noise of each value's sigma. ValueError when
    the model fails on a drop at ``truth``."""
    pred = predict(model, template, params, np.array([truth], dtype=np.float64), engine=engine)
    bad = np.flatnonzero(pred.status[0] != 0)
    if bad.size:
        raise ValueError(f"the model fails on drops {[template.labels[d] for d in bad]}")
    observed = {}
    for q, y in template.observed.items():
        s = template.sigma[q]
        noisy = pred.values[q][0] + s * rng.standard_normal(y.shape)
        observed[q] = np.where(np.isfinite(y), noisy, np.nan)
    return replace(template, observed=observed, source=None)
