"""The verified range of a law from its errors against FE at checked points: the largest
delta / delta_c up to which the loading force stays within :data:`FORCE_TOLERANCE` (relative)
and delta_r / delta_max within :data:`RESIDUAL_TOLERANCE` (absolute) of the FE results
(``impactlab.fe.accuracy`` measures the errors)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

__all__ = ["FORCE_TOLERANCE", "RESIDUAL_TOLERANCE", "VerifiedRange", "verified_range"]

#: Largest relative error of the loading force inside the verified range.
FORCE_TOLERANCE = 0.10
#: Largest absolute error of delta_r / delta_max inside the verified range.
RESIDUAL_TOLERANCE = 0.05


#: ``VerifiedRange.limited_by`` of a law that could not be built for the pair.
NOT_BUILT = "not built"


@dataclass(frozen=True)
class VerifiedRange:
    """Where a law stays within the tolerances of FE (ratios delta / delta_c).

    upper: the largest delta / delta_c verified (0: not even the first checked point);
    limited_by: ``"force"``, ``"delta_r"`` (the check that failed first, by ratio),
    ``"end of data"`` (neither failed) or ``NOT_BUILT`` (the law could not be built for the
    pair: nothing was checked); first_failure: delta / delta_c of the first checked
    point outside the tolerance of the limiting check (nan at the end of the data);
    force_upper, residual_upper: the range each check alone verifies; force_failure,
    residual_failure: where each check first fails (nan: it never does).
    """

    upper: float
    limited_by: str
    first_failure: float
    force_upper: float = math.nan
    residual_upper: float = math.nan
    force_failure: float = math.nan
    residual_failure: float = math.nan

    @property
    def end_of_data(self) -> bool:
        """True when the law stayed within the tolerances at every checked point."""
        return self.limited_by == "end of data"

    @property
    def text(self) -> str:
        """``<= 30 delta_c (delta_r fails at 100)``, ``>= 1000 delta_c (end of data)``."""
        if self.end_of_data:
            return f">= {self.upper:.3g} delta_c (end of data)"
        if self.limited_by == NOT_BUILT:
            return "not built for this pair"
        if self.upper <= 0.0:
            return f"none ({self.limited_by} fails at {self.first_failure:.3g})"
        return f"<= {self.upper:.3g} delta_c ({self.limited_by} fails at {self.first_failure:.3g})"


def _last_pass(ratio: np.ndarray, ok: np.ndarray) -> tuple[float, float]:
    """(last ratio before the first failure or the last ratio, ratio of the first failure or
    nan); ``ratio`` sorted increasing."""
    if ratio.size == 0:
        return 0.0, math.nan
    bad = np.flatnonzero(~ok)
    if bad.size == 0:
        return float(ratio[-1]), math.nan
    i = int(bad[0])
    return (float(ratio[i - 1]) if i > 0 else 0.0), float(ratio[i])


def verified_range(
    force_ratio: Any,
    force_error: Any,
    residual_ratio: Any,
    residual_error: Any,
    *,
    force_tolerance: float = FORCE_TOLERANCE,
    residual_tolerance: float = RESIDUAL_TOLERANCE,
) -> VerifiedRange:
    """The verified range from the errors at checked points (each check's ratios in any order).

    force_error: relative errors of the loading force at ``force_ratio`` (delta / delta_c);
    residual_error: errors of delta_r / delta_max at ``residual_ratio``. A nan error (the law
    cannot be evaluated there) counts as outside. Each check is verified up to its last point
    before its first point outside the tolerance; the range is the smaller of the two, limited
    by the check that gives it (the force on a tie).
    """
    out = []
    for name, r, e, tol in (
        ("force", force_ratio, force_error, force_tolerance),
        ("delta_r", residual_ratio, residual_error, residual_tolerance),
    ):
        r_a = np.asarray(r, dtype=np.float64).ravel()
        e_a = np.asarray(e, dtype=np.float64).ravel()
        if r_a.shape != e_a.shape:
            raise ValueError(f"{name}: {r_a.size} ratios but {e_a.size} errors")
        order = np.argsort(r_a, kind="stable")
        r_a, e_a = r_a[order], e_a[order]
        ok = np.isfinite(e_a) & (np.abs(e_a) <= tol)
        out.append((name, *_last_pass(r_a, ok)))
    (nf, uf, ff), (nr, ur, fr) = out
    name, u, f = (nf, uf, ff) if uf < ur or (uf == ur and not math.isnan(ff)) else (nr, ur, fr)
    return VerifiedRange(u, "end of data" if math.isnan(f) else name, f, uf, ur, ff, fr)
