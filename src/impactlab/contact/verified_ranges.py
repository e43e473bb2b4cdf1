"""The contact laws' verified ranges: how far each law stays close to the FE reference.

The **verified range** of a law for a material pair is the largest interference, as a ratio
delta / delta_c (delta_c the pair's Jackson-Green first-yield interference, paper Eq. 15), up
to which the law stays within 10 % of the finite-element (CalculiX) loading force and within
0.05 of its delta_r / delta_max, measured by ``impactlab.fe.accuracy`` against the shipped FE
reference curves (``impactlab/fe/data``; docs/laws/accuracy.md). The measured numbers are in
``contact/data/verified-ranges.json`` (:data:`VERIFIED_PATH`), written from the shipped curves
by ``python3 tasks.py fe-reference`` (``impactlab.fe.verified_ranges``): never typed by hand.

Each FE case is one E*/S_y (E* the pair's reduced modulus, S_y the yield strength of the body
that yields first). For a pair between two shipped cases the range is bounded conservatively:
the smaller of the two cases' verified ranges (nothing assumes how the range varies between
them). Outside the span of the shipped cases the range is **unverified**: :func:`verified_upper`
returns NaN and ``impactlab.contact.ranges`` keeps the law's former stand-in and says so.

A law that reads inputs the elastic-perfectly plastic FE reference does not
(:data:`BEYOND_FE`: Brake's P0 from the Brinell hardnesses and its Meyer index) is verified only
for a case's own pair, those inputs included (``inputs`` of its rows): another hardness is
another law curve against the same FE curves, and the measured range moves with it (at the
paper's E*/S_y a flat of HB 150 instead of 105 keeps Brake within the tolerances to 1 delta_c,
not 2). Such a pair is never interpolated between cases.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from impactlab.contact import kernels as k

__all__ = [
    "BEYOND_FE",
    "FORMAT",
    "VERIFIED_PATH",
    "VerifiedCase",
    "differing_inputs",
    "e_star_over_sy_span",
    "tolerance_text",
    "verified_cases",
    "verified_laws",
    "verified_upper",
]

VERIFIED_PATH = Path(__file__).resolve().parent / "data" / "verified-ranges.json"
#: The ``format`` field of the data file.
FORMAT = "impactlab verified ranges v1"
#: Relative tolerance when matching an E*/S_y to a shipped case's (the file's 7 digits).
_MATCH_RTOL = 1e-6
#: The compiled parameters (name -> slot of ``ContactModel.params``) of laws that read inputs
#: the FE reference does not: their verified range holds for a case's own values only.
BEYOND_FE: dict[str, dict[str, int]] = {"brake": {"P0": k.P_BR_P0, "meyer_index": k.P_BR_N}}


@dataclass(frozen=True)
class VerifiedCase:
    """One law against one FE case: the case, its E*/S_y [1], the verified upper end
    ``upper`` (delta / delta_c; 0: not even the first checked point), the check that limits it
    (``"force"``, ``"delta_r"`` or ``"end of data"``), where that check first fails
    (delta / delta_c; nan at the end of the data) and, for a law of :data:`BEYOND_FE`, the
    values of its inputs the FE reference does not fix (name -> SI value)."""

    case: str
    e_star_over_sy: float
    upper: float
    limited_by: str
    first_failure: float
    inputs: tuple[tuple[str, float], ...] = ()

    @property
    def text(self) -> str:
        """``<= 1 delta_c at E*/S_y = 360 (delta_r fails at 1.5)``."""
        at = f"at E*/S_y = {self.e_star_over_sy:.0f}"
        if self.limited_by == "end of data":
            return f">= {self.upper:.3g} delta_c {at} (end of data)"
        return (
            f"<= {self.upper:.3g} delta_c {at} ({self.limited_by} fails at "
            f"{self.first_failure:.3g})"
        )


def _float(v: Any) -> float:
    return math.nan if v is None else float(v)


@cache
def _data() -> dict[str, Any]:
    record: dict[str, Any] = json.loads(VERIFIED_PATH.read_text())
    if record.get("format") != FORMAT:
        raise ValueError(f"{VERIFIED_PATH}: not a verified-ranges file ({record.get('format')!r})")
    return record


@cache
def _table() -> dict[str, tuple[VerifiedCase, ...]]:
    out = {}
    for law, rows in _data()["laws"].items():
        cases = (
            VerifiedCase(
                str(r["case"]),
                float(r["e_star_over_sy"]),
                float(r["verified_delta_ratio"]),
                str(r["limited_by"]),
                _float(r["first_failure_delta_ratio"]),
                tuple((str(n), float(v)) for n, v in r.get("inputs", {}).items()),
            )
            for r in rows
        )
        out[law] = tuple(sorted(cases, key=lambda c: c.e_star_over_sy))
    return out


def verified_laws() -> tuple[str, ...]:
    """The laws that have a verified range (every law measured against FE)."""
    return tuple(_table())


def verified_cases(law: str) -> tuple[VerifiedCase, ...]:
    """The verified range of ``law`` per shipped FE case, by increasing E*/S_y (``()`` for a
    law without one)."""
    return _table().get(str(law), ())


def tolerance_text() -> str:
    """``FE, 10 % force / 0.05 delta_r/delta_max``: the tolerances of the verified range."""
    t = _data()["tolerances"]
    return (
        f"FE, {100 * t['force_relative']:g} % force / {t['residual_ratio_absolute']:g} "
        "delta_r/delta_max"
    )


def e_star_over_sy_span(law: str | None = None) -> tuple[float, float]:
    """(smallest, largest) E*/S_y of the shipped FE cases (``law``: of those it was measured
    on; (nan, nan) for a law without a verified range)."""
    table = _table()
    chosen = table.values() if law is None else [table.get(str(law), ())]
    values = [c.e_star_over_sy for cases in chosen for c in cases]
    return (min(values), max(values)) if values else (math.nan, math.nan)


def differing_inputs(law: str, e_star_over_sy: float, params: Any) -> tuple[str, ...] | None:
    """For a law of :data:`BEYOND_FE`: the names of its inputs the FE reference does not use
    whose values in the compiled ``params`` differ from those of the FE case at
    ``e_star_over_sy`` (``()``: none); None where no case has that E*/S_y, or for another
    law."""
    slots = BEYOND_FE.get(str(law))
    if slots is None:
        return None
    p = np.asarray(params, dtype=np.float64)
    for c in verified_cases(law):
        if math.isclose(float(e_star_over_sy), c.e_star_over_sy, rel_tol=_MATCH_RTOL):
            return tuple(
                name
                for name, value in c.inputs
                if not math.isclose(float(p[slots[name]]), value, rel_tol=_MATCH_RTOL)
            )
    return None


def _matches(a: Any, b: Any) -> Any:
    """``np.isclose(a, b, rtol=_MATCH_RTOL, atol=0)`` for finite ``b``, without its cost (a
    batch's flags ask it for every call): |a - b| <= _MATCH_RTOL |b|, False for NaN."""
    return np.abs(np.subtract(a, b)) <= _MATCH_RTOL * np.abs(b)


def verified_upper(law: str, e_star_over_sy: Any, params: Any = None) -> Any:
    """The verified upper end delta / delta_c of ``law`` for pairs of ratio ``e_star_over_sy``
    (float or array): a shipped case's own value at its E*/S_y, the smaller of the two
    neighbouring cases' between them, NaN outside the span (unverified) or for a law without
    a verified range. A law of :data:`BEYOND_FE` needs the pairs' compiled ``params`` (rows
    of ``ContactModel.params``): a case's own value where they hold its inputs, else NaN."""
    x = np.asarray(e_star_over_sy, dtype=np.float64)
    out = np.full(x.shape, np.nan)
    cases = verified_cases(law)
    if cases and str(law) in BEYOND_FE:
        if params is None:
            return float(out) if out.ndim == 0 else out
        p = np.asarray(params, dtype=np.float64)
        slots = BEYOND_FE[str(law)]
        for c in cases:
            same = _matches(x, c.e_star_over_sy)
            for name, value in c.inputs:
                same &= _matches(p[..., slots[name]], value)
            out = np.where(same, c.upper, out)
    elif cases:
        xs = np.array([c.e_star_over_sy for c in cases])
        us = np.array([c.upper for c in cases])
        lo, hi = xs[0] * (1 - _MATCH_RTOL), xs[-1] * (1 + _MATCH_RTOL)
        inside = np.isfinite(x) & (x >= lo) & (x <= hi)
        xi = np.clip(x[inside], xs[0], xs[-1])
        right = np.clip(np.searchsorted(xs, xi, side="left"), 0, xs.size - 1)
        left = np.clip(right - 1, 0, xs.size - 1)
        bound = np.minimum(us[left], us[right])
        at_right = _matches(xi, xs[right])
        at_left = _matches(xi, xs[left])
        out[inside] = np.where(at_right, us[right], np.where(at_left, us[left], bound))
    return float(out) if out.ndim == 0 else out
