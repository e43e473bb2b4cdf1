"""The tabulated law's tables made from indentation curves (dimensionless: x = log(delta /
delta_c), z = log(F / F_c)): the points of the loading fit and of the residual depths' PCHIP,
the tables in ``contact.curve_table``'s layout (``curve_tables``) with their Python
interpolant (``table_values``), and the fit's and the interpolation's errors.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.contact.curve_table import CURVE_MAGIC, N_LOAD, N_RES
from impactlab.contact.indentation_data import IndentationCurves
from impactlab.contact.loading_fit import (
    cross_validated,
    fit_loading,
    held_out_sets,
    scatter_note,
)

__all__ = [
    "FIRST_YIELD",
    "TABLE_FIT_TOLERANCE",
    "check_table_fit",
    "curve_tables",
    "interpolation_error",
    "loading_fit",
    "loading_fit_error",
    "loading_points",
    "residual_points",
    "residual_raised",
    "table_values",
]

#: First yield in the curves' units (delta/delta_c: they are dimensionless in their pair's
#: Jackson-Green delta_c): no residual depth is interpolated below it (``residual_points``).
FIRST_YIELD = 1.0
#: Largest relative difference allowed between a table's loading fit and any of its loading
#: points past the first: the bound the tabulated law states for its fit (docs/laws/tabulated.md).
TABLE_FIT_TOLERANCE = 0.025


def _monotone(x: np.ndarray, y: np.ndarray, m: np.ndarray) -> np.ndarray:
    """Slopes ``m`` (dy/dx at the nodes ``x``) limited so that the cubic Hermite interpolant of
    ``y`` is monotone on every interval (Fritsch & Carlson 1980: the secant's sign, and
    alpha^2 + beta^2 <= 9 with alpha, beta the end slopes over the secant)."""
    m = m.copy()
    secant = np.diff(y) / np.diff(x)
    for i, s in enumerate(secant):
        if s == 0.0:
            m[i] = m[i + 1] = 0.0
            continue
        a, b = max(m[i] / s, 0.0), max(m[i + 1] / s, 0.0)
        q = a * a + b * b
        if q > 9.0:
            t = 3.0 / math.sqrt(q)
            a, b = t * a, t * b
        m[i], m[i + 1] = a * s, b * s
    return m


def _resample(x: np.ndarray, y: np.ndarray, n: int, first_slope: float | None) -> np.ndarray:
    """(values, slopes per node step) of the PCHIP of y(x) (its first slope ``first_slope``
    where given) on ``n`` uniform nodes, limited to stay monotone between them."""
    from scipy.interpolate import CubicHermiteSpline, PchipInterpolator

    # a nearly flat segment overflows PCHIP's harmonic mean of the secants to inf, whose
    # reciprocal is the zero slope wanted there: not a failure, so not a warning
    with np.errstate(over="ignore", divide="ignore"):
        slopes = PchipInterpolator(x, y).derivative()(x)
    if not np.isfinite(slopes).all():
        raise ValueError("the tabulated curve's slopes are not finite (points too close?)")
    if first_slope is not None:
        slopes[0] = first_slope
    spline = CubicHermiteSpline(x, y, _monotone(x, y, slopes))
    xg = np.linspace(x[0], x[-1], n)
    yg = spline(xg)
    return np.concatenate((yg, _monotone(xg, yg, spline.derivative()(xg)) * (xg[1] - xg[0])))


def loading_points(c: IndentationCurves) -> tuple[np.ndarray, np.ndarray]:
    """(x, z) the loading fit is made to: the Hertz point at the elastic limit, then the data
    past it. ValueError where the data starts below the Hertz force at the limit."""
    keep = c.delta > c.elastic_limit
    x = np.log(np.concatenate(([c.elastic_limit], c.delta[keep])))
    z = np.concatenate(([1.5 * x[0]], np.log(c.force[keep])))
    if z[1] < z[0]:
        raise ValueError(
            f"force at delta/delta_c = {float(c.delta[keep][0]):.4g} "
            f"({float(c.force[keep][0]):.4g} F_c) is below Hertz's at the elastic limit "
            f"delta/delta_c = {c.elastic_limit:.4g}: the loading curve would decrease"
        )
    return x, z


def loading_fit(c: IndentationCurves) -> Any:
    """The fitted w(x) = -log(F/F_Hertz) of ``c``'s loading curve (a ``scipy`` BSpline over
    [x of the elastic limit, x of the last point]; ``contact.loading_fit``). Fitted once per
    curves (they are immutable) and kept with them: a law of a dense indenter export (20 000
    rows) took 0.4 s a fit, twice in each build of a model, once per case of a sweep over
    materials."""
    fit = c.__dict__.get(_FIT)
    if fit is None:
        x, z = loading_points(c)
        fit = fit_loading(x, 1.5 * x - z)
        object.__setattr__(c, _FIT, fit)
    return fit


#: Where ``loading_fit`` keeps a curves' fit (an attribute outside the dataclass's fields).
_FIT = "_loading_fit"


def loading_fit_error(c: IndentationCurves) -> tuple[float, float]:
    """(largest, root-mean-square) relative difference F_fit / F_data - 1 over the loading
    points of ``c`` past the elastic limit."""
    x, z = loading_points(c)
    rel = np.expm1(1.5 * x[1:] - loading_fit(c)(x[1:]) - z[1:])
    return float(np.max(np.abs(rel))), float(np.sqrt(np.mean(rel**2)))


def check_table_fit(name: str, curves: IndentationCurves, label: str = "") -> None:
    """ValueError where the law's loading fit of ``curves`` departs from a loading point past
    the first by more than ``TABLE_FIT_TOLERANCE`` in force, naming the largest departure,
    the point (index, delta/delta_c, the data's F/F_Hertz) and what to check: scatter where
    the departures look like it (``scatter_note``), else a rise of F/F_Hertz or a kink.
    The message starts with ``label`` (default: ``law 'name'``)."""
    x, z = loading_points(curves)
    rel = np.expm1(1.5 * x[1:] - loading_fit(curves)(x[1:]) - z[1:])
    j = int(np.argmax(np.abs(rel)))
    if abs(rel[j]) <= TABLE_FIT_TOLERANCE:
        return
    i = int(np.flatnonzero(curves.delta > curves.elastic_limit)[j])
    d, n = float(curves.delta[i]), curves.delta.size
    scatter = scatter_note(rel)
    what = scatter or (
        ": check that F/F_Hertz never rises past the first point (the tabulated law keeps it "
        "from rising, so that no impact gains energy) and that the forces hold no jump or kink"
    )
    raise ValueError(
        f"{label or f'law {name!r}'}: the law's loading fit departs from the data's force by "
        f"{float(rel[j]):+.3g} (relative) at loading point index {i} (data row {i + 1} of "
        f"{n}; delta/delta_c = {d:.4g}, the data's F/F_Hertz = {curves.force[i] / d**1.5:.4g}); "
        f"the fit must stay within {100 * TABLE_FIT_TOLERANCE:g} % of every point{what}"
    )


def residual_raised(c: IndentationCurves) -> float:
    """Largest rise of a delta_r/delta_max of ``c`` made by ``residual_points``."""
    return float(np.max(np.maximum.accumulate(c.residual_ratio) - c.residual_ratio))


def residual_points(c: IndentationCurves) -> tuple[np.ndarray, np.ndarray]:
    """(x, delta_r/delta_max) the residual table interpolates: from a zero ratio, then the
    data from its first positive ratio on, each ratio raised to the largest before it
    (non-decreasing: see ``loading_points``). The zero is the data's last leading zero ratio
    (or the elastic limit, where the first ratio is positive), moved up to first yield,
    delta_c (``FIRST_YIELD``), where it lies below it and the first positive ratio above it:
    the law is Hertz and leaves no dent below first yield, so no residual depth is
    interpolated there (measured data whose first point lies in the elastic range)."""
    dm, r = c.delta_max, np.maximum.accumulate(c.residual_ratio)
    nz = np.flatnonzero(r > 0.0)
    if not nz.size:
        return np.log(dm[-2:]), r[-2:]
    first = int(nz[0])
    zero = float(dm[first - 1]) if first else c.elastic_limit
    if zero < FIRST_YIELD < dm[first]:
        zero = FIRST_YIELD
    if not zero < dm[first]:
        raise ValueError(
            f"delta_r > 0 at delta_max/delta_c = {dm[0]:.4g}, at or below the elastic limit "
            f"({c.elastic_limit:.4g}): the first residual depth must lie past it"
        )
    return np.log(np.concatenate(([zero], dm[first:]))), np.concatenate(([0.0], r[first:]))


def curve_tables(c: IndentationCurves) -> np.ndarray:
    """The tables appended to a tabulated law's parameters (``contact.curve_table`` layout)."""
    x, _z = loading_points(c)
    xr, rr = residual_points(c)
    # z = 1.5 x - w: values and slopes per node step of the fitted spline, whose knots are
    # nodes (the cubic Hermite pieces are the spline's pieces)
    w = loading_fit(c)
    xg = np.linspace(x[0], x[-1], N_LOAD)
    h = xg[1] - xg[0]
    load = np.concatenate((1.5 * xg - w(xg), (1.5 - w.derivative()(xg)) * h))
    res = _resample(xr, rr, N_RES, None)
    head = [
        CURVE_MAGIC,
        x[0],
        (N_LOAD - 1) / (x[-1] - x[0]),
        xr[0],
        (N_RES - 1) / (xr[-1] - xr[0]),
    ]
    return np.concatenate((head, load, res))


def _hermite(y: np.ndarray, m: np.ndarray, x0: float, inv_h: float, x: Any) -> np.ndarray:
    """The uniform-grid cubic Hermite interpolant (values ``y``, slopes ``m`` per node step,
    first node at ``x0``) at ``x``, linear beyond the ends: ``curve_table``'s arithmetic."""
    n = y.size
    u = (np.asarray(x, dtype=float) - x0) * inv_h
    j = np.clip(np.floor(u).astype(int), 0, n - 2)
    t = u - j
    d = y[j + 1] - y[j]
    cubic = y[j] + t * (m[j] + t * ((3 * d - 2 * m[j] - m[j + 1]) + t * (m[j] + m[j + 1] - 2 * d)))
    out = np.where(u >= n - 1, y[-1] + m[-1] * (u - n + 1), cubic)
    return np.where(u <= 0.0, y[0] + m[0] * u, out)


def table_values(tables: np.ndarray, x: Any, residual: bool = False) -> np.ndarray:
    """The tables' interpolant at ``x`` = log(delta/delta_c): z = log(F/F_c), or with
    ``residual`` delta_r/delta_max (0 below the first node, constant past the last)."""
    if not residual:
        y, m = tables[5 : 5 + N_LOAD], tables[5 + N_LOAD : 5 + 2 * N_LOAD]
        return _hermite(y, m, tables[1], tables[2], x)
    at = 5 + 2 * N_LOAD
    y, m = tables[at : at + N_RES], tables[at + N_RES : at + 2 * N_RES]
    xc = np.minimum(np.asarray(x, dtype=float), tables[3] + (N_RES - 1) / tables[4])
    r = _hermite(y, m, tables[3], tables[4], xc)
    return np.where(xc <= tables[3], 0.0, np.maximum(r, 0.0))


def _loo(x: np.ndarray, y: np.ndarray, n: int, first_slope: float | None) -> np.ndarray:
    """Cross-validated errors of the PCHIP table (``held_out_sets``: leave-one-out, or k-fold
    past ``LOO_MAX_POINTS`` interior points): each interior point predicted without it, minus
    it."""
    out = np.empty(max(x.size - 2, 0))
    for held in held_out_sets(x.size):
        keep = np.ones(x.size, dtype=bool)
        keep[held] = False
        t = _resample(x[keep], y[keep], n, first_slope)
        out[held - 1] = _hermite(t[:n], t[n:], x[0], (n - 1) / (x[-1] - x[0]), x[held]) - y[held]
    return out


def interpolation_error(c: IndentationCurves) -> tuple[float, float]:
    """Cross-validated error: (largest relative force error of the loading fit, largest
    absolute error of the delta_r/delta_max interpolation) at the interior data points, each
    predicted from the others (leave-one-out; ``LOO_MAX_POINTS``: k-fold for more points)."""
    x, z = loading_points(c)
    xr, rr = residual_points(c)
    ef = -cross_validated(x, 1.5 * x - z)
    er = _loo(xr, rr, N_RES, None)
    worst_f = float(np.max(np.abs(np.expm1(ef)))) if ef.size else 0.0
    worst_r = float(np.max(np.abs(er))) if er.size else 0.0
    return worst_f, worst_r
