"""Measured accuracy of every contact law against the shipped FE reference curves.

For each built-in law (``impactlab.contact.builtin_law_names``) and each shipped case
(``impactlab.fe.curves``), the law is built for the case's contact pair and radius exactly as a
simulation builds it (``get_law(name).build(pair, radius)``, default parameters) and compared
with the FE results:

- **loading force**: the relative error ``F_law(delta) / F_FE(delta) - 1`` at every point of the
  FE loading curve from ``LOWEST_RATIO`` delta_c on (``ContactModel.force``);
- **permanent depth**: the error of delta_r / delta_max, ``law - FE``, at every FE maximum
  (``ContactModel.unload(delta_max).delta_r``).

Interferences are given as delta / delta_c, delta_c the pair's Jackson-Green first-yield
interference (the FE problem's). The **verified range** of a law for a case is the largest
delta / delta_c up to which both errors stay within :data:`FORCE_TOLERANCE` and
:data:`RESIDUAL_TOLERANCE`: the last checked point before the first one outside, for the
force and for delta_r / delta_max separately, the smaller of the two
(:func:`verified_range`). A law that stays inside up to the end of the data is verified "to the
end of the data", which is not a statement about larger interferences.

Tables, the docs page's markdown, the figures and the command line are in
``impactlab.fe.accuracy_views``.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab.contact import builtin_law_names, get_law
from impactlab.fe.curves import ReferenceCase, load_cases
from impactlab.fe.range_check import (
    FORCE_TOLERANCE,
    NOT_BUILT,
    RESIDUAL_TOLERANCE,
    VerifiedRange,
    verified_range,
)

#: The force is compared from this delta / delta_c on (below it the FE curve starts).
LOWEST_RATIO = 0.1
#: Where the fully plastic regime starts [delta_c], which the recommendation names on its own
#: (impacts such as the paper's reach 180-650 delta_c: a score over the whole span would
#: weigh the elastic-plastic onset, where most FE points lie, above them).
PLASTIC_FROM = 100.0
#: SI units of the numbers in :func:`report` (for ``impactlab._json.to_json``).
UNITS: dict[str, str] = {
    "radius": "m",
    "delta_c": "m",
    **dict.fromkeys(
        (
            "e_star_over_sy",
            "verified_delta_ratio",
            "first_failure_delta_ratio",
            "law_ref_over_delta_c",
            "score",
            "force_verified_delta_ratio",
            "residual_verified_delta_ratio",
            "rms_force_error",
            "rms_residual_ratio_error",
            "delta_ratio",
            "force_error",
            "residual_ratio_fe",
            "residual_ratio_law",
            "residual_ratio_error",
            "force_relative",
            "residual_ratio_absolute",
        ),
        "1",
    ),
}


@dataclass(frozen=True, repr=False)
class LawAccuracy:
    """One law against one FE case (ratios are delta / delta_c of the case).

    force_ratio, force_fe, force_error: the FE loading points checked (delta / delta_c and
    F [N]) and the law's relative force error there (nan beyond the law's validity limit);
    maxima_ratio: delta_max / delta_c of the converged FE runs; residual_fe, residual_law:
    delta_r / delta_max of FE and of the law there; verified: the verified range;
    law_ref_over_delta_c: the law's own reference interference (its critical interference,
    ``ContactModel.critical_interference``, what ``contact.ranges`` divides by) over the
    case's delta_c; message: why the law could not be built for the pair ("" if it could).
    """

    law: str
    case: str
    e_star_over_sy: float
    force_ratio: np.ndarray
    force_fe: np.ndarray
    force_error: np.ndarray
    maxima_ratio: np.ndarray
    residual_fe: np.ndarray
    residual_law: np.ndarray
    verified: VerifiedRange
    law_ref_over_delta_c: float
    message: str = ""

    built = property(lambda self: not self.message, doc="True when the law was built.")

    def __repr__(self) -> str:
        """One line: the law, the case, the verified range and the RMS errors."""
        from impactlab.fe.accuracy_display import law_repr

        return law_repr(self)

    @property
    def residual_error(self) -> np.ndarray:
        """delta_r / delta_max of the law less FE's, at ``maxima_ratio``."""
        return np.asarray(self.residual_law - self.residual_fe)

    def force_error_at(self, ratio: float) -> float:
        """Relative force error at delta / delta_c = ``ratio`` (interpolated in log delta;
        nan outside the checked points)."""
        r, e = self.force_ratio, self.force_error
        # the stored curves carry 7 significant digits: the maxima match to 1e-6
        if r.size == 0 or not r[0] * (1 - 1e-6) <= ratio <= r[-1] * (1 + 1e-6):
            return math.nan
        return float(np.interp(math.log(ratio), np.log(r), e))

    def residual_error_at(self, ratio: float) -> float:
        """delta_r / delta_max error at the FE maximum ``ratio`` (nan if there is none)."""
        hit = np.flatnonzero(np.isclose(self.maxima_ratio, ratio, rtol=1e-6))
        return float(self.residual_error[hit[0]]) if hit.size else math.nan

    def rms_force_error(self) -> float:
        """RMS of the relative force error over the checked points (inf if any is nan)."""
        e = self.force_error
        return float(np.sqrt(np.mean(e**2))) if e.size and np.all(np.isfinite(e)) else math.inf

    def rms_residual_error(self) -> float:
        """RMS of the delta_r / delta_max error over the maxima where FE resolves delta_r
        (inf if the law's is nan at any of them)."""
        e = self.residual_error[np.isfinite(self.residual_fe)]
        return float(np.sqrt(np.mean(e**2))) if e.size and np.all(np.isfinite(e)) else math.inf

    def score(self) -> float:
        """Closeness to FE over all checked points: the mean of the RMS force error over
        FORCE_TOLERANCE and the RMS delta_r / delta_max error over RESIDUAL_TOLERANCE (inf
        if the law could not be evaluated everywhere)."""
        return 0.5 * (
            self.rms_force_error() / FORCE_TOLERANCE
            + self.rms_residual_error() / RESIDUAL_TOLERANCE
        )

    def errors_from(self, low: float) -> tuple[np.ndarray, np.ndarray]:
        """(relative force errors, delta_r / delta_max errors) at delta / delta_c >= ``low``
        (the residual ones where FE resolves delta_r)."""
        at = low * (1.0 - 1e-6)  # the stored curves carry 7 significant digits
        force = self.force_error[self.force_ratio >= at]
        keep = (self.maxima_ratio >= at) & np.isfinite(self.residual_fe)
        return np.asarray(force), np.asarray(self.residual_error[keep])

    def score_from(self, low: float) -> float:
        """``score`` over the checked points at delta / delta_c >= ``low`` (inf if there is
        none, or the law is nan at one)."""
        force, residual = self.errors_from(low)
        if not (force.size and residual.size):
            return math.inf
        if not (np.all(np.isfinite(force)) and np.all(np.isfinite(residual))):
            return math.inf
        rms_f, rms_r = np.sqrt(np.mean(force**2)), np.sqrt(np.mean(residual**2))
        return float(0.5 * (rms_f / FORCE_TOLERANCE + rms_r / RESIDUAL_TOLERANCE))

    def describe(self) -> dict[str, Any]:
        """Plain data (``impactlab laws --accuracy --json``; SI, units in :data:`UNITS`)."""
        v = self.verified
        m = self.maxima_ratio
        return {
            "law": self.law,
            "case": self.case,
            "e_star_over_sy": self.e_star_over_sy,
            "verified_delta_ratio": v.upper,
            "verified_to_end_of_data": v.end_of_data,
            "limited_by": v.limited_by,
            "first_failure_delta_ratio": v.first_failure,
            "verified": v.text,
            "force_verified_delta_ratio": v.force_upper,
            "residual_verified_delta_ratio": v.residual_upper,
            "rms_force_error": self.rms_force_error(),
            "rms_residual_ratio_error": self.rms_residual_error(),
            "law_ref_over_delta_c": self.law_ref_over_delta_c,
            "score": self.score(),
            "maxima": {
                "delta_ratio": [float(r) for r in m],
                "force_error": [self.force_error_at(float(r)) for r in m],
                "residual_ratio_fe": [float(x) for x in self.residual_fe],
                "residual_ratio_law": [float(x) for x in self.residual_law],
                "residual_ratio_error": [float(x) for x in self.residual_error],
            },
            "message": self.message,
        }


def _law_values(model: Any, delta: np.ndarray) -> np.ndarray:
    """The law's loading force at ``delta`` [m], nan beyond its validity limit."""
    inside = delta <= model.max_interference
    out = np.full(delta.shape, np.nan)
    if inside.any():
        out[inside] = model.force(delta[inside])
    return out


def law_accuracy(law: str, case: ReferenceCase) -> LawAccuracy:
    """The accuracy of ``law`` (default parameters) against the FE ``case``."""
    dc = case.delta_c
    d, f = case.loading_curve()
    keep = (d >= LOWEST_RATIO * dc) & (f > 0.0)
    d, f = np.asarray(d[keep]), np.asarray(f[keep])
    runs = [r for r in case.runs if r.usable]  # delta_r nan: below the FE's resolution
    maxima = np.array([r.delta_max for r in runs])
    fe_res = np.array([r.residual_ratio for r in runs])
    try:
        model = get_law(law).build(case.pair, case.radius)
    except ValueError as exc:
        nan_f, nan_r = np.full(d.shape, np.nan), np.full(maxima.shape, np.nan)
        v = VerifiedRange(0.0, NOT_BUILT, math.nan)  # nothing evaluated: no check failed
        return LawAccuracy(
            law,
            case.name,
            case.e_star_over_sy,
            d / dc,
            f,
            nan_f,
            maxima / dc,
            fe_res,
            nan_r,
            v,
            math.nan,
            str(exc),
        )
    force_err = _law_values(model, d) / f - 1.0
    law_res = np.array(
        [model.unload(m).delta_r / m if m <= model.max_interference else math.nan for m in maxima]
    )
    known = np.isfinite(fe_res)  # an unresolved FE delta_r checks nothing
    v = verified_range(d / dc, force_err, (maxima / dc)[known], (law_res - fe_res)[known])
    return LawAccuracy(
        law=law,
        case=case.name,
        e_star_over_sy=case.e_star_over_sy,
        force_ratio=d / dc,
        force_fe=f,
        force_error=force_err,
        maxima_ratio=maxima / dc,
        residual_fe=fe_res,
        residual_law=law_res,
        verified=v,
        law_ref_over_delta_c=model.critical_interference / dc,
    )


@dataclass(frozen=True, repr=False)
class CaseAccuracy:
    """Every law against one FE case, and the recommendation for that pair."""

    case: ReferenceCase
    laws: tuple[LawAccuracy, ...]

    def __repr__(self) -> str:
        """One line: the case, E*/S_y, delta_c, the laws, the closest and best verified."""
        from impactlab.fe.accuracy_display import case_repr

        return case_repr(self, PLASTIC_FROM)

    def _repr_html_(self) -> str:
        """The table of ``impactlab laws --accuracy`` for this case and its recommendation."""
        from impactlab.fe.accuracy_display import case_html

        return case_html(self)

    @property
    def built(self) -> tuple[LawAccuracy, ...]:
        """The laws that could be built for the pair (Brake's needs Brinell hardnesses)."""
        return tuple(a for a in self.laws if a.built)

    def closest(self) -> LawAccuracy:
        """The law closest to FE over the whole checked span (smallest ``score``)."""
        return min(self.built, key=lambda a: a.score())

    def closest_in_force(self) -> LawAccuracy:
        """The law with the smallest RMS force error."""
        return min(self.built, key=lambda a: a.rms_force_error())

    def closest_in_residual(self) -> LawAccuracy:
        """The law with the smallest RMS delta_r / delta_max error."""
        return min(self.built, key=lambda a: a.rms_residual_error())

    def closest_fully_plastic(self) -> LawAccuracy | None:
        """The law closest to FE from :data:`PLASTIC_FROM` delta_c on (smallest
        ``score_from``); None when the case has fewer than two FE maxima there."""
        at = PLASTIC_FROM * (1.0 - 1e-6)
        if np.count_nonzero(self.case_maxima() >= at) < 2:
            return None
        best = min(self.built, key=lambda a: a.score_from(PLASTIC_FROM))
        return best if math.isfinite(best.score_from(PLASTIC_FROM)) else None

    def case_maxima(self) -> np.ndarray:
        """delta_max / delta_c of the case's converged FE runs."""
        return np.asarray(self.built[0].maxima_ratio) if self.built else np.array([])

    def recommendation(self) -> str:
        """One line: which law is closest to FE for this pair (overall, in force alone, in
        delta_r / delta_max alone), how close, and how far the best one is verified."""
        c = self.case
        best, bf, br = self.closest(), self.closest_in_force(), self.closest_in_residual()
        top = float(np.max(best.force_ratio))
        ef = float(np.max(np.abs(best.force_error)))
        er = float(np.nanmax(np.abs(best.residual_error)))
        most = max(a.verified.upper for a in self.built)
        who = ", ".join(a.law for a in self.built if a.verified.upper == most)
        return (
            f"{c.description} (E*/S_y = {c.e_star_over_sy:.0f}): closest to FE over "
            f"{LOWEST_RATIO:g}-{top:.4g} delta_c: {best.law} (force within {100 * ef:.0f} %, "
            f"delta_r/delta_max within {er:.2f}); in force alone {bf.law} (RMS "
            f"{100 * bf.rms_force_error():.0f} %), in delta_r/delta_max alone {br.law} (RMS "
            f"{br.rms_residual_error():.2f}); largest verified range {most:.3g} delta_c "
            f"({who})" + self._plastic_text()
        )

    def _plastic_text(self) -> str:
        """``; from 100 delta_c on (fully plastic): ghaednia (force within 7 %, ...)`` or ""."""
        p = self.closest_fully_plastic()
        if p is None:
            return ""
        force, residual = p.errors_from(PLASTIC_FROM)
        return (
            f"; from {PLASTIC_FROM:g} delta_c on (fully plastic, where impacts such as the "
            f"paper's lie): {p.law} (force within {100 * np.max(np.abs(force)):.0f} %, "
            f"delta_r/delta_max within {np.max(np.abs(residual)):.2f})"
        )

    def describe(self, only: str | None = None) -> dict[str, Any]:
        """Plain data (``only``: the one law to list; the recommendation weighs them all)."""
        c = self.case
        return {
            "case": c.name,
            "description": c.description,
            "flat": c.flat.name,
            "sphere": f"{c.sphere_material.name} ({c.sphere})",
            "radius": c.radius,
            "delta_c": c.delta_c,
            "e_star_over_sy": c.e_star_over_sy,
            "closest": self.closest().law,
            "closest_fully_plastic": getattr(self.closest_fully_plastic(), "law", None),
            "recommendation": self.recommendation(),
            "laws": {a.law: a.describe() for a in self.laws if only in (None, a.law)},
        }


def measured_laws() -> tuple[str, ...]:
    """The laws measured here: every registered law but the tabulated one, which is built
    from these very curves (its round trip: docs/laws/tabulated.md)."""
    return tuple(n for n in builtin_law_names() if n != "tabulated")


def accuracy(
    laws: Sequence[str] | None = None, cases: Sequence[ReferenceCase] | None = None
) -> list[CaseAccuracy]:
    """Every law (default: ``measured_laws()``) against every case (default: all shipped)."""
    names = list(laws) if laws is not None else list(measured_laws())
    chosen = list(cases) if cases is not None else load_cases()
    return [CaseAccuracy(c, tuple(law_accuracy(n, c) for n in names)) for c in chosen]


def tolerances() -> dict[str, float]:
    """The tolerances of the verified range (plain data)."""
    return {"force_relative": FORCE_TOLERANCE, "residual_ratio_absolute": RESIDUAL_TOLERANCE}


def report(results: Sequence[CaseAccuracy], only: str | None = None) -> dict[str, Any]:
    """Everything as plain data (``only``: list one law)."""
    return {
        "tolerances": tolerances(),
        "definitions": {
            "delta_ratio": "delta / delta_c, delta_c the pair's Jackson-Green first-yield "
            "interference",
            "force_error": "F_law / F_FE - 1 on loading",
            "residual_ratio_error": "delta_r/delta_max of the law less FE's, at the FE maxima",
        },
        "cases": [r.describe(only) for r in results],
    }
