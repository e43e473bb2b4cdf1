"""The tabulated law (``law="tabulated"``): a loading curve fitted to and residual depths
interpolated from indentation data (finite-element or measured), the engine's common Hertzian
unloading branch.

Construction (``curve_tables``, in ``contact.tabulated_fit``), from dimensionless curves
(``contact.indentation_data``), with x = log(delta / delta_c), z = log(F / F_c):

- loading: Hertz up to the elastic limit; from there a least-squares cubic spline of
  w = -log(F/F_Hertz) = 1.5 x - z, constrained to w = 0 at the limit (continuous with Hertz's
  force) and to 0 <= dw/dx <= 1.5 (F/F_Hertz never increases, F never decreases), its knot
  count chosen by generalised cross-validation (``contact.loading_fit``): FE points scatter
  by about 1 %, which an interpolant would follow; stored on ``N_LOAD``
  uniform nodes in x that include the knots, so the compiled cubic Hermite lookup
  (``contact.curve_table``: one log, one exp and a cubic) is the spline itself (C2);
- unloading: delta_r / delta_max as PCHIP (Fritsch & Carlson 1980) of log(delta_max /
  delta_c), resampled with its slopes onto ``N_RES`` uniform nodes (Fritsch-Carlson-limited,
  so still monotone), 0 below its zero: the data's last zero, or first yield (delta_c) where
  the data's first residual depth lies past it (``residual_points``); unloading itself is the
  engine's Hertzian branch through (delta_m, F_m) with that delta_r;
- hard limit ``p[P_DLIM]``: the last interference covered by both data sets (or R);
- a loading fit that departs from the data by more than ``TABLE_FIT_TOLERANCE`` (the bound
  the law states) is refused (``check_table_fit``), as ``register_law`` refuses it.

Curves of a pair with E*/S_y and nu apply to another pair only when both match within
``RATIO_TOLERANCE`` and ``NU_TOLERANCE`` and the same body yields in both (the flat, or a sphere
with the smaller C(nu) S_y: ``IndentationCurves.yielding``); refused otherwise (no interpolation).
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
from impactlab.contact.indentation_data import (
    IndentationCurves,
    read_curves,
    shipped_curves,
    yielding_body,
)
from impactlab.contact.names import Law
from impactlab.contact.range_note import note_source
from impactlab.contact.tabulated_fit import (
    TABLE_FIT_TOLERANCE,
    check_table_fit,
    curve_tables,
    interpolation_error,
    loading_fit,
    loading_fit_error,
    loading_points,
    residual_raised,
    table_values,
)
from impactlab.contact.tabulated_fit import residual_points as residual_points
from impactlab.materials import ContactPair, first_yield_factor

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
        why = ""  # where nu, not S_y, decides: the first-yield pressures (materials.pair)
        if (pair.body.yield_strength < pair.flat.yield_strength) != (side == "sphere"):
            b, f = (
                first_yield_factor(m.nu) * m.yield_strength / 1e6 for m in (pair.body, pair.flat)
            )
            nus = f"nu {pair.body.nu:g} and {pair.flat.nu:g}"
            why = f"; with {nus}, C(nu) S_y {b:.4g} and {f:.4g} MPa"
        raise ValueError(
            f"law {law!r}: the {side} yields first in this pair (S_y {sy[0]} for the sphere, "
            f"{sy[1]} for the flat{why}), but the indentation curves for its E*/S_y = "
            f"{ratio:.4g}, "
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

    #: A law sampled from callables (``contact.registered.sample_law``) is checked against
    #: them; any other is refused where its loading fit passes ``TABLE_FIT_TOLERANCE``.
    sampled: bool = False

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
        """The model of ``pair`` with a sphere of ``radius`` [m] (no law parameters).
        ValueError where the loading fit departs from a point of the curves by more than
        ``TABLE_FIT_TOLERANCE`` (``check_table_fit``: the bound the law states)."""
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
        if fit_max > TABLE_FIT_TOLERANCE and not self.sampled:  # the law states that bound
            check_table_fit(self.name, c, f"law {self.name!r}, curves {c.name!r}")
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
    """The tabulated law of ``curves`` for ``pair`` and a sphere of ``radius`` [m]; ValueError
    where its loading fit departs from the curves by more than ``TABLE_FIT_TOLERANCE``."""
    return Tabulated(curves).build(pair, radius)


__all__ = [
    "NU_TOLERANCE",
    "RATIO_TOLERANCE",
    "TABLE_FIT_TOLERANCE",
    "DamagedCurvesWarning",
    "Tabulated",
    "cached_curves",
    "check_table_fit",
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
