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

__all__ = ["Pairs", "chi2_floor", "correlated_chi2", "correlation_note", "drop_pairs"]

#: A drop's coefficients: ordered pair of measured quantities -> coefficient [1].
Pairs = Mapping[tuple[str, str], float]


def drop_pairs(meas: Measurements, d: int) -> dict[tuple[str, str], float]:
    """The coefficients drop ``d`` of ``meas`` gives (those not given left out)."""
    return {p: float(x[d]) for p, x in meas.correlation.items() if not math.isnan(x[d])}


def _matrix(qs: list[str], pairs: Pairs) -> np.ndarray | None:
    """R of the quantities ``qs`` (in their order) with the coefficients ``pairs``; None
    when no coefficient other than 0 joins two of them."""
    used = {p: x for p, x in pairs.items() if x and p[0] in qs and p[1] in qs}
    if not used:
        return None
    index = {q: i for i, q in enumerate(qs)}
    r = np.eye(len(qs))
    for (a, b), x in used.items():
        r[index[a], index[b]] = r[index[b], index[a]] = x
    return r


def correlated_chi2(z: Mapping[str, float], pairs: Pairs) -> float | None:
    """z^T R^-1 z of the values ``z`` (quantity -> z) with the drop's coefficients ``pairs``;
    None when no coefficient other than 0 joins two of them (the sum of z^2 holds)."""
    qs = list(z)
    r = _matrix(qs, pairs)
    if r is None:
        return None
    v = np.array([z[q] for q in qs], dtype=np.float64)
    return float(v @ np.linalg.solve(r, v))


def chi2_floor(z: Mapping[str, float], pairs: Pairs) -> float:
    """A lower bound of the chi2 of any z' with |z'_q| >= ``z[q]`` >= 0 each: the sum of z^2,
    over the largest eigenvalue of R where coefficients join the values (z'^T R^-1 z' >=
    |z'|^2 / lambda_max(R))."""
    total = float(sum(v * v for v in z.values()))
    r = _matrix(list(z), pairs)
    return total if r is None else total / float(np.linalg.eigvalsh(r)[-1])


def correlation_note(pairs: Pairs) -> str:
    """The note of a drop whose chi2 takes its coefficients ("" for none other than 0)."""
    given = [f"{correlation_column(a, b)} = {x:g}" for (a, b), x in pairs.items() if x]
    if not given:
        return ""
    return (
        f"chi2 takes the drop's correlation coefficients ({', '.join(given)}): z^T R^-1 z over "
        "the values compared, R their correlation matrix; each z is of its value alone"
    )
