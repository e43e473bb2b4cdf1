"""The tabulated law's loading curve as a shape-constrained least-squares cubic spline.

The curve fitted is w(x) = -log(F / F_Hertz) against x = log(delta / delta_c), from the
elastic limit x_0 on (where w = 0: the Hertz point). FE indentation curves scatter by about
1 % from point to point (mesh), so an interpolant through every point has a local slope
d log F / d log delta that jumps between 0.8 and 1.5: the impact integrator's error control
sees those jumps as steps in the contact stiffness and takes up to 1.6 times the steps. A
least-squares fit with few knots keeps the trend and drops the scatter.

The fit: a clamped cubic B-spline on ``intervals`` equal knot intervals over [x_0, x_last],
coefficients c_i with

- c_0 = 0: w = 0 at x_0, so the force is continuous with Hertz's at the switch; its slope
  there is the data's (dw/dx = 0, Hertz's d log F / d log delta = 1.5, for every shipped FE
  curve, whose first plastic points follow Hertz; a sampled law with a kink at the switch
  keeps its kink);
- 0 <= c_{i+1} - c_i <= (t_{i+4} - t_{i+1}) / 2: the spline's derivative is a quadratic
  B-spline with coefficients 3 (c_{i+1} - c_i) / (t_{i+4} - t_{i+1}), so 0 <= dw/dx <= 1.5
  everywhere (a B-spline lies between its smallest and largest coefficient: de Boor, A
  Practical Guide to Splines, 2001): F / F_Hertz never increases (no impact gains energy)
  and F never decreases;

solved as bounded least squares (``scipy.optimize.lsq_linear``, BVLS) in the increments.
The number of knot intervals is the one of ``INTERVALS`` (with at least ``POINTS_PER_COEFF``
data points per free coefficient) that minimises generalised cross-validation, n RSS /
(n - p)^2 with p free coefficients (Craven & Wahba 1979). The choices divide
``curve_table.N_LOAD - 1``, so the knots are nodes of the compiled table and its cubic
Hermite pieces are the spline's own pieces (the table is the spline: C2, not only C1).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from impactlab.contact.curve_table import N_LOAD

if TYPE_CHECKING:
    from scipy.interpolate import BSpline

#: Knot intervals the fit chooses from (each divides N_LOAD - 1): few for scattered FE curves
#: (tens of points), many for dense samples of a smooth curve (``register_law``'s callables).
INTERVALS = (1, 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64, 96)
#: Fewest data points (past the Hertz point) per free spline coefficient.
POINTS_PER_COEFF = 4
#: Largest d(-log(F/F_Hertz))/d log delta: 1.5, where F stops rising.
MAX_SLOPE = 1.5

if any((N_LOAD - 1) % n for n in INTERVALS):  # pragma: no cover - layout guard
    raise ImportError("every knot interval count must divide N_LOAD - 1")


def _knots(x0: float, x1: float, intervals: int) -> np.ndarray:
    return np.concatenate(([x0] * 3, np.linspace(x0, x1, intervals + 1), [x1] * 3))


def fit_with(x: np.ndarray, w: np.ndarray, intervals: int, span: tuple[float, float]) -> BSpline:
    """The constrained fit of w(x) (x[0] = span[0] is the Hertz point, w[0] = 0) with
    ``intervals`` equal knot intervals over ``span``."""
    from scipy.interpolate import BSpline as _BSpline  # on first use: import impactlab stays light
    from scipy.optimize import lsq_linear

    t = _knots(span[0], span[1], intervals)
    nc = t.size - 4
    basis = _BSpline.design_matrix(np.clip(x, span[0], span[1]), t, 3).toarray()
    cumulative = np.tril(np.ones((nc, nc)))[:, 1:]  # c = cumulative @ increments, c0 = 0
    upper = MAX_SLOPE / 3.0 * (t[4 : nc + 3] - t[1:nc])
    sol = lsq_linear(basis @ cumulative, w, bounds=(0.0, upper), method="bvls")
    return _BSpline(t, cumulative @ sol.x, 3)


def candidate_intervals(points: int) -> tuple[int, ...]:
    """The knot interval counts allowed for ``points`` data points past the Hertz point."""
    return tuple(n for n in INTERVALS if n == 1 or POINTS_PER_COEFF * (n + 1) <= points)


def choose_intervals(x: np.ndarray, w: np.ndarray) -> int:
    """The knot interval count of the least generalised cross-validation score."""
    n = x.size - 1  # the Hertz point is a constraint, not a datum
    best, score = 1, np.inf
    for k in candidate_intervals(n):
        s = fit_with(x, w, k, (x[0], x[-1]))
        p = k + 1
        gcv = n * float(np.sum((s(x[1:]) - w[1:]) ** 2)) / max(n - p, 1) ** 2
        if gcv < score * (1.0 - 1e-9):
            best, score = k, gcv
    return best


def fit_loading(x: np.ndarray, w: np.ndarray) -> BSpline:
    """The fitted w(x) over [x[0], x[-1]] (knot count by ``choose_intervals``)."""
    return fit_with(x, w, choose_intervals(x, w), (x[0], x[-1]))


def leave_one_out(x: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Fit minus datum at each interior point, the fit made without it (same knots, same
    knot count as the full fit)."""
    k = choose_intervals(x, w)
    span = (x[0], x[-1])
    out = []
    for i in range(1, x.size - 1):
        keep = np.arange(x.size) != i
        out.append(float(fit_with(x[keep], w[keep], k, span)(x[i])) - w[i])
    return np.asarray(out)


__all__ = [
    "INTERVALS",
    "MAX_SLOPE",
    "POINTS_PER_COEFF",
    "candidate_intervals",
    "choose_intervals",
    "fit_loading",
    "fit_with",
    "leave_one_out",
]
