"""Correlated measured inputs of the inversion (``invert``'s ``correlation``): the coefficients
checked and put in the order of the inputs, their first-order propagation (J C J^T) and the
factor that turns independent standard normals into correlated ones for the Monte Carlo."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab.analytic.result import Measured, measured

__all__ = [
    "PSD_TOLERANCE",
    "Correlation",
    "check_correlation",
    "correlate",
    "linear_sigmas",
    "sign_flipped",
]

#: A correlation matrix whose smallest eigenvalue lies below minus this is refused as not
#: positive semi-definite (rounding of coefficients computed from a covariance stays above it).
PSD_TOLERANCE = 1e-9
#: The inputs ``invert`` takes the magnitude of (a value given negative flips the sign of its
#: correlations).
_MAGNITUDES = ("v_i", "delta_p", "sliding_length")
#: Units of the inputs, to read a value given with one (only its sign matters here).
_UNITS = {"v_i": "m/s", "delta_p": "m", "sliding_length": "m"}

#: Checked correlations: (name_a, name_b) -> coefficient, each pair in the inputs' order.
Correlation = dict[tuple[str, str], float]


def sign_flipped(given: Mapping[str, Any]) -> frozenset[str]:
    """The inputs among ``v_i``, ``delta_p``, ``sliding_length`` given negative, whose
    magnitude ``invert`` uses (``given``: the keywords as passed; each already valid)."""
    out = set()
    for k in _MAGNITUDES:
        if given.get(k) is not None and measured(k, given[k], _UNITS[k]).value < 0.0:
            out.add(k)
    return frozenset(out)


def _pair(key: Any, meas: Mapping[str, Measured]) -> tuple[str, str]:
    """``key`` as a pair of distinct input names given with a sigma > 0, in ``meas``'s order."""
    if not (isinstance(key, tuple | list) and len(key) == 2):
        raise ValueError(f"correlation: a key must be a pair of input names, got {key!r}")
    a, b = key
    for name in (a, b):
        if not isinstance(name, str) or name not in meas:
            raise ValueError(
                f"correlation: {name!r} in {tuple(key)!r} is not an input given to invert "
                f"(allowed: {', '.join(meas)})"
            )
        if not meas[name].sigma > 0:
            raise ValueError(
                f"correlation: {name!r} in {tuple(key)!r} has no sigma (given exact): only "
                "inputs with an uncertainty can be correlated"
            )
    if a == b:
        raise ValueError(f"correlation: {tuple(key)!r} pairs {a!r} with itself (always 1)")
    order = list(meas)
    return (a, b) if order.index(a) < order.index(b) else (b, a)


def _coefficient(key: Any, rho: Any) -> float:
    """``rho`` as a real number in [-1, 1]; ValueError naming the pair otherwise."""
    ok = isinstance(rho, int | float | np.integer | np.floating) and not isinstance(rho, bool)
    if not ok or not -1.0 <= float(rho) <= 1.0:
        raise ValueError(
            f"correlation: the coefficient of {tuple(key)!r} must be a number in [-1, 1], "
            f"got {rho!r}"
        )
    return float(rho)


def check_correlation(
    correlation: Any, meas: Mapping[str, Measured], flipped: frozenset[str] = frozenset()
) -> Correlation:
    """``invert``'s ``correlation`` checked: None or a mapping of input-name pairs to
    coefficients in [-1, 1], each name an input of ``meas`` with a sigma > 0, each pair once,
    the matrix positive semi-definite. The coefficients are those of the inputs as given;
    returned as those of the inputs as used (``meas``: a pair with one input in ``flipped``,
    given negative and used as its magnitude, changes sign). ValueError naming the fault."""
    if correlation is None:
        return {}
    if not isinstance(correlation, Mapping):
        raise ValueError(
            "correlation must be None or a mapping of (name, name) pairs to coefficients, "
            f"e.g. {{('e', 'dv_cy'): 0.94}}, got {correlation!r}"
        )
    out: Correlation = {}
    for key, rho in correlation.items():
        pair = _pair(key, meas)
        if pair in out:
            raise ValueError(f"correlation: the pair {pair!r} is given twice")
        sign = -1.0 if (pair[0] in flipped) != (pair[1] in flipped) else 1.0
        out[pair] = sign * _coefficient(key, rho)
    names, matrix = _matrix(out, meas)
    if names:
        smallest = float(np.linalg.eigvalsh(matrix)[0])
        if smallest < -PSD_TOLERANCE:
            raise ValueError(
                f"correlation: the coefficients {dict(correlation)!r} form no correlation "
                f"matrix (not positive semi-definite: its smallest eigenvalue is "
                f"{smallest:.3g} < 0); no set of measurements can be correlated so"
            )
    return out


def _matrix(corr: Correlation, meas: Mapping[str, Measured]) -> tuple[list[str], Any]:
    """The correlated inputs (in ``meas``'s order) and their correlation matrix."""
    involved = {k for pair in corr for k in pair}
    names = [k for k in meas if k in involved]
    matrix = np.eye(len(names))
    for (a, b), rho in corr.items():
        i, j = names.index(a), names.index(b)
        matrix[i, j] = matrix[j, i] = rho
    return names, matrix


def linear_sigmas(
    meas: Mapping[str, Measured],
    sens_T: Mapping[str, float],
    sens_F: Mapping[str, float],
    corr: Correlation | None = None,
) -> tuple[float, float]:
    """First-order standard deviations of T [s] and F [N] from the sensitivities: the square
    root of J C J^T, the covariance C from the sigmas and the correlations ``corr``."""
    names = [k for k in meas if meas[k].sigma > 0]
    out = []
    for sens in (sens_T, sens_F):
        var = sum((sens[k] * meas[k].sigma) ** 2 for k in names)
        for (a, b), rho in (corr or {}).items():
            var += 2.0 * rho * sens[a] * meas[a].sigma * sens[b] * meas[b].sigma
        out.append(math.sqrt(max(var, 0.0)))
    return out[0], out[1]


def correlate(z: dict[str, Any], meas: Mapping[str, Measured], corr: Correlation) -> None:
    """Make the independent standard normals ``z`` (input -> draws) of the correlated inputs
    correlated as ``corr`` says, in place: a Cholesky factor L of their correlation matrix
    (an eigen-factor where it is singular, a coefficient of +-1) applied to them."""
    names, matrix = _matrix(corr, meas)
    if not names:
        return
    try:
        factor = np.linalg.cholesky(matrix)
    except np.linalg.LinAlgError:  # semi-definite: C = V W V^T, factor V W^(1/2)
        w, v = np.linalg.eigh(matrix)
        factor = v * np.sqrt(np.clip(w, 0.0, None))
    mixed = factor @ np.stack([z[k] for k in names])
    z.update(zip(names, mixed, strict=True))
