"""chi2 of a drop whose measured values are correlated (its ``correlation_<a>_<b>``
coefficients, ``impactlab.calibrate.correlations``): the Mahalanobis form z^T R^-1 z over the
values compared, R their correlation matrix (the part of the drop's for those values), the
likelihood's own measure of misfit; z of each value stays the marginal (predicted - measured)
/ sigma. A drop without a coefficient other than 0 among the values keeps the sum of z^2."""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from impactlab.calibrate.correlations import correlation_column
from impactlab.calibrate.measurements import Measurements

__all__ = ["Pairs", "correlated_chi2", "correlation_note", "drop_pairs"]

#: A drop's coefficients: ordered pair of measured quantities -> coefficient [1].
Pairs = Mapping[tuple[str, str], float]


def drop_pairs(meas: Measurements, d: int) -> dict[tuple[str, str], float]:
    """The coefficients drop ``d`` of ``meas`` gives (those not given left out)."""
    return {p: float(x[d]) for p, x in meas.correlation.items() if not math.isnan(x[d])}


def correlated_chi2(z: Mapping[str, float], pairs: Pairs) -> float | None:
    """z^T R^-1 z of the values ``z`` (quantity -> z) with the drop's coefficients ``pairs``;
    None when no coefficient other than 0 joins two of them (the sum of z^2 holds)."""
    used = {p: x for p, x in pairs.items() if x and p[0] in z and p[1] in z}
    if not used:
        return None
    qs = list(z)
    index = {q: i for i, q in enumerate(qs)}
    r = np.eye(len(qs))
    for (a, b), x in used.items():
        r[index[a], index[b]] = r[index[b], index[a]] = x
    v = np.array([z[q] for q in qs], dtype=np.float64)
    return float(v @ np.linalg.solve(r, v))


def correlation_note(pairs: Pairs) -> str:
    """The note of a drop whose chi2 takes its coefficients ("" for none other than 0)."""
    given = [f"{correlation_column(a, b)} = {x:g}" for (a, b), x in pairs.items() if x]
    if not given:
        return ""
    return (
        f"chi2 takes the drop's correlation coefficients ({', '.join(given)}): z^T R^-1 z over "
        "the values compared, R their correlation matrix; each z is of its value alone"
    )
