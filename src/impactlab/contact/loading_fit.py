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

The sampling error of a table (``cross_validated``) predicts each interior point from a fit
without it: leave-one-out up to ``LOO_MAX_POINTS`` interior points, ``FOLDS``-fold past it (an
indenter's export of thousands of rows: ``FOLDS`` fits instead of one per row; within 5 % of
leave-one-out on the shipped FE curves and on 300-row tables).
"""

from __future__ import annotations

import math
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
#: Interior points up to which the sampling error is leave-one-out (one fit per point: the
#: cost grows as the square of the points); past it ``FOLDS``-fold cross-validation.
LOO_MAX_POINTS = 100
#: Held-out sets of the cross-validation past ``LOO_MAX_POINTS`` interior points.
FOLDS = 10
#: Fewest departures from the fit for ``scatter_note`` to judge them.
SCATTER_MIN_POINTS = 10
#: Sign runs this many standard deviations fewer than random signs give show a trend, not
#: scatter (random signs fall that short about once in 160; the kinks, jumps and rises of
#: F/F_Hertz tried fall 3.2 or more short).
SCATTER_RUNS_SD = 2.5

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


def held_out_sets(n: int) -> list[np.ndarray]:
    """The sets of interior indices (1 to n - 2 of ``n`` points) each predicted from the other
    points: one point each (leave-one-out) up to ``LOO_MAX_POINTS`` interior points; past it
    ``FOLDS`` interleaved sets (every ``FOLDS``-th point: each held-out point keeps its
    neighbours), ``FOLDS`` fits instead of one per point."""
    inner = np.arange(1, n - 1)
    if inner.size <= LOO_MAX_POINTS:
        return [inner[i : i + 1] for i in range(inner.size)]
    return [inner[j::FOLDS] for j in range(min(FOLDS, inner.size))]


def held_out_method(n: int) -> str:
    """How ``held_out_sets`` predicts the interior points of ``n`` points, in words."""
    if n - 2 <= LOO_MAX_POINTS:
        return "leave-one-out"
    return f"{FOLDS}-fold cross-validation"


def cross_validated(x: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Fit minus datum at each interior point, the fit made without it (``held_out_sets``:
    leave-one-out, or ``FOLDS``-fold past ``LOO_MAX_POINTS`` interior points; same knots, same
    knot count as the full fit)."""
    k = choose_intervals(x, w)
    span = (x[0], x[-1])
    out = np.empty(max(x.size - 2, 0))
    for held in held_out_sets(x.size):
        keep = np.ones(x.size, dtype=bool)
        keep[held] = False
        out[held - 1] = fit_with(x[keep], w[keep], k, span)(x[held]) - w[held]
    return out


def scatter_note(rel: np.ndarray) -> str:
    """Where the departures ``rel`` (fit over data minus 1, in the data's order) look like
    scatter (a runs test: their signs change about as often as random signs do, Wald &
    Wolfowitz 1940; at least ``SCATTER_MIN_POINTS``), a sentence saying so and what to do;
    else empty (a trend: a rise of F/F_Hertz or a kink gives long runs of one sign)."""
    signs = np.sign(rel[rel != 0.0])
    n, pos = signs.size, int(np.sum(signs > 0.0))
    if n < SCATTER_MIN_POINTS or pos in (0, n):
        return ""
    runs = 1 + int(np.sum(signs[1:] != signs[:-1]))
    mean = 2.0 * pos * (n - pos) / n + 1.0
    sd = math.sqrt((mean - 1.0) * (mean - 2.0) / (n - 1.0))
    if runs < mean - SCATTER_RUNS_SD * sd:
        return ""
    rms = float(np.sqrt(np.mean(rel**2)))
    return (
        f"; the departures change sign {runs - 1} times over {n} points (rms "
        f"{100 * rms:.2g} %), as scatter does, with no trend: the data's scatter is the likely "
        f"cause, not the curve's shape; average repeated indentations, or smooth F/F_Hertz "
        f"(a running mean over 5 points: docs/laws/user.md, 'Scattered data'), before "
        f"registering"
    )


__all__ = [
    "FOLDS",
    "INTERVALS",
    "LOO_MAX_POINTS",
    "MAX_SLOPE",
    "POINTS_PER_COEFF",
    "SCATTER_MIN_POINTS",
    "SCATTER_RUNS_SD",
    "candidate_intervals",
    "choose_intervals",
    "cross_validated",
    "fit_loading",
    "fit_with",
    "held_out_method",
    "held_out_sets",
    "scatter_note",
]
