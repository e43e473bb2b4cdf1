"""The likelihood of a drop's correlated measured values (``correlation_<a>_<b>``,
``impactlab.calibrate.correlations``): a multivariate normal with covariance D R D (D the
standard uncertainties, R the correlation matrix) through the Cholesky factor of R, the
coefficients as JSON rows, and the likelihood as the calibration's settings state it."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab.calibrate.correlations import check_drop
from impactlab.calibrate.measurements import Measurements

__all__ = ["correlated_loglik", "correlation_rows", "likelihood_text"]

_LOG_2PI = math.log(2.0 * math.pi)


def _factors(meas: Measurements) -> list[tuple[list[int], list[str], np.ndarray]]:
    """Groups of drops with a coefficient other than 0 that measure the same quantities:
    (drops, quantities, (n, k, k) Cholesky factors of their correlation matrices)."""
    groups: dict[tuple[str, ...], list[tuple[int, np.ndarray]]] = {}
    for d in range(meas.n_drops):
        pairs = {p: float(x[d]) for p, x in meas.correlation.items() if not math.isnan(x[d])}
        if not any(pairs.values()):
            continue
        qs = tuple(q for q in meas.quantities if math.isfinite(meas.observed[q][d]))
        groups.setdefault(qs, []).append((d, check_drop(f"drop {d + 1}", pairs, qs)))
    return [
        ([d for d, _ in g], list(qs), np.linalg.cholesky(np.array([r for _, r in g])))
        for qs, g in groups.items()
    ]


def correlated_loglik(values: Mapping[str, np.ndarray], meas: Measurements, ll: np.ndarray) -> None:
    """Replace, in ``ll`` (W, D), the column of each drop with a coefficient other than 0 by
    its multivariate normal log density: ``values`` quantity -> (W, D) predictions, ``meas``
    the Measurements; -inf where a prediction is not finite (as for an independent value)."""
    for drops, qs, chol in _factors(meas):
        y = np.stack([meas.observed[q][drops] for q in qs], axis=-1)  # (n, k)
        s = np.stack([meas.sigma[q][drops] for q in qs], axis=-1)
        f = np.stack([values[q][:, drops] for q in qs], axis=-1)  # (W, n, k)
        r = (f - y) / s
        bad = ~np.isfinite(r).all(axis=-1)
        z = np.linalg.solve(chol, np.where(np.isfinite(r), r, 0.0)[..., None])[..., 0]
        log_det = np.log(s).sum(axis=-1) + np.log(np.diagonal(chol, axis1=-2, axis2=-1)).sum(-1)
        term = -0.5 * ((z * z).sum(axis=-1) + len(qs) * _LOG_2PI) - log_det
        ll[:, drops] = np.where(bad, -np.inf, term)


def correlation_rows(meas: Measurements) -> list[dict[str, Any]]:
    """The coefficients given, one row per drop and pair: ``{"drop", "quantities": [a, b],
    "coefficient"}`` (empty: every value independent)."""
    return [
        {"drop": label, "quantities": [a, b], "coefficient": float(x[d])}
        for d, label in enumerate(meas.labels)
        for (a, b), x in meas.correlation.items()
        if not math.isnan(x[d])
    ]


def likelihood_text(meas: Measurements) -> str:
    """The likelihood as the calibration's settings state it."""
    if any(np.isfinite(x).any() for x in meas.correlation.values()):
        return (
            "Gaussian errors with the stated standard uncertainties, correlated within a drop "
            "where given (its correlation_<a>_<b> coefficients)"
        )
    return "independent Gaussian errors with the stated standard uncertainties"
