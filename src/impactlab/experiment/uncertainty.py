"""Measured values with standard uncertainties, and first-order propagation.

Propagation is linear (first order, "GUM" style): for y = f(x) with covariance C_x, the covariance
of y is J C_x J^T with J the Jacobian of f at the estimate, here from central differences whose
steps are scaled to each input's standard deviation. Valid while f is close to linear over
+-1 sigma, which holds for the fits of this package (relative uncertainties of a few per cent).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

#: The unit of a dimensionless estimate (docs/json-schema.md); "" is read as it.
DIMENSIONLESS = "1"


@dataclass(frozen=True)
class Estimate:
    """A measured value with its standard uncertainty (1 sigma, same unit) and its unit
    (``"1"`` for a plain number, as the JSON schema writes it; ``""`` is taken as ``"1"``); a
    sigma of 0 means that none was computed (the pile-up height): it is shown without a ±, as
    the command line shows it, never as an exact value."""

    value: float
    sigma: float
    unit: str = DIMENSIONLESS

    def __post_init__(self) -> None:
        object.__setattr__(self, "unit", str(self.unit).strip() or DIMENSIONLESS)
        object.__setattr__(self, "value", float(self.value))
        s = float(self.sigma)
        if not (math.isfinite(s) and s >= 0.0):
            raise ValueError(f"sigma must be finite and >= 0, got {s!r}")
        object.__setattr__(self, "sigma", s)

    def pair(self) -> tuple[float, float]:
        """(value, sigma), the form :func:`impactlab.analytic.invert` accepts."""
        return (self.value, self.sigma)

    def to_dict(self) -> dict[str, Any]:
        """JSON-ready: value, sigma, unit ("1" for a plain number)."""
        return {"value": self.value, "sigma": self.sigma, "unit": self.unit}

    def scaled(self, factor: float, unit: str) -> Estimate:
        """The same estimate in another unit (value and sigma times ``factor``)."""
        return Estimate(self.value * factor, abs(self.sigma * factor), unit)

    def __format__(self, spec: str) -> str:
        spec = spec or ".4g"
        u = f" {self.unit}" if self.unit != DIMENSIONLESS else ""
        if self.sigma == 0.0:
            return f"{self.value:{spec}}{u}"
        return f"{self.value:{spec}} ± {self.sigma:.2g}{u}"

    def __str__(self) -> str:
        return format(self, "")


def jacobian(f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, steps: np.ndarray) -> np.ndarray:
    """Central-difference Jacobian of the vector function ``f`` at ``x`` (steps per input)."""
    x = np.asarray(x, dtype=np.float64)
    y0 = np.asarray(f(x), dtype=np.float64)
    J = np.zeros((y0.size, x.size))
    for i in range(x.size):
        h = float(steps[i])
        if h == 0.0:
            continue
        xp = x.copy()
        xm = x.copy()
        xp[i] += h
        xm[i] -= h
        J[:, i] = (np.asarray(f(xp), dtype=np.float64) - np.asarray(f(xm), dtype=np.float64)) / (
            2.0 * h
        )
    return J


def propagate(
    f: Callable[[np.ndarray], np.ndarray], x: np.ndarray, cov: np.ndarray, rel_step: float = 1e-3
) -> tuple[np.ndarray, np.ndarray]:
    """First-order propagation: (f(x), J cov J^T). Steps are ``rel_step`` times each input's sigma
    (inputs with zero variance are held fixed)."""
    x = np.asarray(x, dtype=np.float64)
    cov = np.asarray(cov, dtype=np.float64)
    sig = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    J = jacobian(f, x, rel_step * sig)
    y = np.asarray(f(x), dtype=np.float64)
    return y, J @ cov @ J.T


def fixed(x: float) -> str:
    """``x`` for a message in fixed point: two significant digits below 10, whole numbers from
    there (110, not 1.1e+02)."""
    return f"{x:.0f}" if math.isfinite(x) and abs(x) >= 10.0 else f"{x:.2g}"


__all__ = ["DIMENSIONLESS", "Estimate", "fixed", "jacobian", "propagate"]
