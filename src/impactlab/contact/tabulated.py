"""The tabulated law (``law="tabulated"``): a loading curve fitted to and residual depths
interpolated from indentation data (finite-element or measured), the engine's common Hertzian
unloading branch.

Construction (``curve_tables``), from dimensionless curves (``contact.indentation_data``), with
x = log(delta / delta_c), z = log(F / F_c):

- loading: Hertz up to the elastic limit; from there a least-squares cubic spline of
  w = -log(F/F_Hertz) = 1.5 x - z, constrained to w = 0 at the limit (continuous with Hertz's
  force) and to 0 <= dw/dx <= 1.5 (F/F_Hertz never increases, F never decreases), its knot
  count chosen by generalised cross-validation (``contact.loading_fit``): FE points scatter
  by about 1 %, which an interpolant would follow; stored on ``N_LOAD``
  uniform nodes in x that include the knots, so the compiled cubic Hermite lookup
  (``contact.curve_table``: one log, one exp and a cubic) is the spline itself (C2);
- unloading: delta_r / delta_max as PCHIP (Fritsch & Carlson 1980) of log(delta_max /
  delta_c), resampled with its slopes onto ``N_RES`` uniform nodes (Fritsch-Carlson-limited,
  so still monotone), 0 below its first data point; unloading itself is the engine's
  Hertzian branch through (delta_m, F_m) with that delta_r;
- hard limit ``p[P_DLIM]``: the last interference covered by both data sets (or R).

Curves of a pair with E*/S_y and nu apply to another pair only when both match within
``RATIO_TOLERANCE`` and ``NU_TOLERANCE`` and the same body yields in both (the flat, or a sphere
softer than it: ``IndentationCurves.yielding``); refused otherwise (no interpolation).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._compiled_cache import default_cache_root
from impactlab._validation import check_positive
from impactlab.contact import kernels as k
from impactlab.contact._common import jg_critical
from impactlab.contact.base import ContactLaw, ContactModel
from impactlab.contact.curve_table import CURVE_MAGIC, N_LOAD, N_RES
from impactlab.contact.indentation_data import (
    IndentationCurves,
    read_curves,
    shipped_curves,
    yielding_body,
)
from impactlab.contact.loading_fit import cross_validated, fit_loading, held_out_sets
from impactlab.contact.names import Law
from impactlab.contact.range_note import note_source
from impactlab.materials import ContactPair

#: Largest relative difference between the pair's E*/S_y and the curves', and of nu.
RATIO_TOLERANCE = 0.05
NU_TOLERANCE = 0.03


def curves_cache_dir() -> Path:
    """Where curves made by FE runs are kept (``tabulated`` in impactlab's cache folder)."""
    return default_cache_root() / "tabulated"


class DamagedCurvesWarning(UserWarning):
    """A file of the curves cache that cannot be read as curves (cut short, not JSON, or JSON
    that is not a curves record): skipped, as if missing; new FE curves of its pair are
    written over it."""


def cached_curves() -> tuple[IndentationCurves, ...]:
    """Every curve set in ``curves_cache_dir()``; a damaged file is skipped with a
    :class:`DamagedCurvesWarning` naming it."""
    out: list[IndentationCurves] = []
    folder = curves_cache_dir()
    if folder.is_dir():
        for path in sorted(folder.glob("*.json")):
            try:
                out += read_curves(path)
            except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
                warnings.warn(
                    f"curves cache file {path} is damaged ({exc}): skipped, as if missing "
                    "(new FE curves of its pair are written over it)",
                    DamagedCurvesWarning,
                    stacklevel=2,
                )
    return tuple(out)


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
    [x of the elastic limit, x of the last point]; ``contact.loading_fit``)."""
    x, z = loading_points(c)
    return fit_loading(x, 1.5 * x - z)


def loading_fit_error(c: IndentationCurves) -> tuple[float, float]:
    """(largest, root-mean-square) relative difference F_fit / F_data - 1 over the loading
    points of ``c`` past the elastic limit."""
    x, z = loading_points(c)
    rel = np.expm1(1.5 * x[1:] - loading_fit(c)(x[1:]) - z[1:])
    return float(np.max(np.abs(rel))), float(np.sqrt(np.mean(rel**2)))


def residual_raised(c: IndentationCurves) -> float:
    """Largest rise of a delta_r/delta_max of ``c`` made by ``residual_points``."""
    return float(np.max(np.maximum.accumulate(c.residual_ratio) - c.residual_ratio))


def residual_points(c: IndentationCurves) -> tuple[np.ndarray, np.ndarray]:
    """(x, delta_r/delta_max) the residual table interpolates: from the last of the leading
    zero ratios (or the elastic limit, with ratio 0), then the data, each ratio raised to the
    largest before it (non-decreasing: see ``loading_points``)."""
    dm, r = c.delta_max, np.maximum.accumulate(c.residual_ratio)
    if r[0] > 0.0:
        if not c.elastic_limit < dm[0]:
            raise ValueError(
                f"delta_r > 0 at delta_max/delta_c = {dm[0]:.4g}, at or below the elastic limit "
                f"({c.elastic_limit:.4g}): the first residual depth must lie past it"
            )
        dm, r = np.concatenate(([c.elastic_limit], dm)), np.concatenate(([0.0], r))
    nz = np.flatnonzero(r > 0.0)
    i0 = max(int(nz[0]) - 1, 0) if nz.size else dm.size - 2
    i0 = min(i0, dm.size - 2)
    return np.log(dm[i0:]), r[i0:]


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


def select_curves(
    pair: ContactPair, candidates: Sequence[IndentationCurves], law: str = "tabulated"
) -> IndentationCurves:
    """The curves whose yielding body (``IndentationCurves.yielding``, ``yielding_body``),
    E*/S_y and nu match ``pair``'s (the closest in E*/S_y, within ``RATIO_TOLERANCE`` and
    ``NU_TOLERANCE``); ValueError naming the law ``law`` and the nearest curves otherwise."""
    ratio, side, nu = pair.E_star / pair.yield_strength, yielding_body(pair), pair.nu
    if not candidates:
        raise ValueError(f"law {law!r}: no indentation curves to choose from")

    def off(c: IndentationCurves) -> float:
        return abs(math.log(ratio / c.e_star_over_sy))

    tol = math.log1p(RATIO_TOLERANCE)
    fits = [c for c in candidates if off(c) <= tol and abs(c.nu - nu) <= NU_TOLERANCE]
    if mine := [c for c in fits if c.yielding == side]:
        return min(mine, key=off)
    make = (
        "make curves for this pair with impactlab.fe.tabulated_law(pair, radius) (runs "
        "CalculiX, the sphere elastic-plastic) or from measured data (IndentationCurves."
        f"from_arrays{', yielding=' + repr(side) if side != 'flat' else ''})"
    )
    if fits:  # the numbers match, the body that yields does not
        sy = [f"{m.yield_strength / 1e6:.4g} MPa" for m in (pair.body, pair.flat)]
        raise ValueError(
            f"law {law!r}: the {side} yields first in this pair (S_y {sy[0]} for the sphere, "
            f"{sy[1]} for the flat), but the indentation curves for its E*/S_y = {ratio:.4g}, "
            f"nu = {nu:g} ({min(fits, key=off).name!r}) are for a yielding {fits[0].yielding}: "
            f"curves differ once the other body yields (docs/laws/tabulated.md); {make}"
        )
    near = min([c for c in candidates if c.yielding == side] or candidates, key=off)
    of = " of a yielding sphere" if side == "sphere" else ""
    other = "" if near.yielding == side else f", a yielding {near.yielding}"
    raise ValueError(
        f"law {law!r}: no indentation curves for E*/S_y = {ratio:.4g}, nu = {nu:g} (within "
        f"{100 * RATIO_TOLERANCE:g} % and {NU_TOLERANCE:g}){of}; nearest: {near.name!r} (E*/S_y "
        f"= {near.e_star_over_sy:.4g}, nu = {near.nu:g}{other}); {make}"
    )


class Tabulated(ContactLaw):
    """Loading curve and residual depths interpolated from indentation curves: given ones
    (``curves``), else the shipped FE curves and those made by FE runs (``curves_cache_dir``)
    that match the pair."""

    law = Law.TABULATED
    title = "Tabulated from indentation data (FE or measured)"
    reference = (
        "FE or measured curves normalised by Jackson & Green (2005): loading a constrained "
        "least-squares cubic spline (de Boor 1978; knots by generalised cross-validation, "
        "Craven & Wahba 1979), residual depths PCHIP (Fritsch & Carlson 1980)"
    )
    validity = (
        "the pair of the curves: E*/S_y within 5 % and nu within 0.03, the same body yielding "
        "(flat, or a softer sphere); delta up to the last tabulated point (hard limit, never "
        "extrapolated); loading within 2.5 % of every FE "
        "point past delta_c it was fitted to (2.3 % largest, 1.0 % rms for the shipped curves; "
        "leave-one-out 3 %), delta_r/delta_max within 0.001 "
        "of the FE maxima (leave-one-out 0.015; 0.021 for PMMA's 6 maxima); unloading Hertzian "
        "(energy returned "
        "0.91-0.98 of the FE's past delta_c)"
    )

    def __init__(self, curves: IndentationCurves | Sequence[IndentationCurves] | None = None):
        if isinstance(curves, IndentationCurves):
            curves = (curves,)
        self.curves: tuple[IndentationCurves, ...] | None = (
            None if curves is None else tuple(curves)
        )
        for c in self.curves or ():
            if not isinstance(c, IndentationCurves):
                raise ValueError(f"curves must be IndentationCurves, got {type(c).__name__}")

    def candidates(self) -> tuple[IndentationCurves, ...]:
        """The curves this law chooses from."""
        if self.curves is not None:
            return self.curves
        return shipped_curves() + cached_curves()

    def build(self, pair: ContactPair, radius: float, **params: float) -> ContactModel:
        """The model of ``pair`` with a sphere of ``radius`` [m] (no law parameters)."""
        if not isinstance(pair, ContactPair):
            raise ValueError(f"pair must be a ContactPair, got {type(pair).__name__}")
        R = check_positive("radius", radius, "m")
        self.parameter_values(params)
        c = select_curves(pair, self.candidates(), self.name)
        E, Sy, nu = pair.E_star, pair.yield_strength, pair.nu
        dc, fc = jg_critical(E, R, Sy, nu)
        p = np.full(k.NPARAM, np.nan)
        p[k.P_ESTAR], p[k.P_R], p[k.P_SY], p[k.P_NU] = E, R, Sy, nu
        p[k.P_DY], p[k.P_FY] = dc, fc
        p[k.P_DSW] = dc * c.elastic_limit
        p[k.P_DLIM] = min(R, dc * c.max_delta)
        p[k.P_TB_DC], p[k.P_TB_FC] = dc, fc
        p[k.P_TB_RATIO], p[k.P_TB_NU] = c.e_star_over_sy, c.nu
        full = np.concatenate((p, curve_tables(c)))
        fit_max, fit_rms = loading_fit_error(c)
        self._check_loading_curve(full, pair, published=False)
        details = {
            "delta_c": dc,
            "F_c": fc,
            # the curves' elastic_limit (delta/delta_c); in m it is the switch_interference
            "elastic_limit_over_delta_c": c.elastic_limit,
            "curves_e_star_over_sy": c.e_star_over_sy,
            "curves_nu": c.nu,
            "ratio_offset": E / Sy / c.e_star_over_sy - 1.0,
            "loading_fit_max": fit_max,
            "loading_fit_rms": fit_rms,
            "residual_raised": residual_raised(c),
        }
        source = f"{c.name}: {c.source}"
        note_source(full, source)  # for the law's range line (``range_note``)
        model = ContactModel(self.name, self.law_id, full, details, self.references, source)
        object.__setattr__(model, "pair", pair)
        return model

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> None:
        raise NotImplementedError("Tabulated.build fills the parameters itself")

    def describe(self) -> dict[str, Any]:
        out = super().describe()
        keys = ("name", "source", "e_star_over_sy", "nu", "yielding")
        out["curves"] = [{k: getattr(c, k) for k in keys} for c in self.candidates()]
        return out


def tabulated_model(curves: IndentationCurves, pair: ContactPair, radius: float) -> ContactModel:
    """The tabulated law of ``curves`` for ``pair`` and a sphere of ``radius`` [m]."""
    return Tabulated(curves).build(pair, radius)


__all__ = [
    "NU_TOLERANCE",
    "RATIO_TOLERANCE",
    "DamagedCurvesWarning",
    "Tabulated",
    "cached_curves",
    "curve_tables",
    "curves_cache_dir",
    "interpolation_error",
    "loading_fit",
    "loading_fit_error",
    "loading_points",
    "residual_raised",
    "select_curves",
    "table_values",
    "tabulated_model",
]
