"""``LawRange``: the range one contact law is held to, as a record (status, stand-in ratio,
sources, its verified ranges per FE case); the table of every law's is in
``impactlab.contact.ranges``."""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any

from impactlab.contact.names import Law
from impactlab.contact.verified_ranges import (
    BEYOND_FE,
    VerifiedCase,
    e_star_over_sy_span,
    tolerance_text,
    verified_cases,
)
from impactlab.references import cite

__all__ = ["STATUSES", "LawRange"]

#: The meaning of each ``LawRange.status``.
STATUSES: Mapping[str, str] = MappingProxyType(
    {
        "confirmed": "read in the source",
        "provisional": "stand-in value: the source's own range was not found",
        "theory": "limit of the theory itself",
        "analytical": "closed-form law, no fitted range (stand-in: its first yield)",
        "tabulated": "interpolated data: the hard limit is the data's end, nothing beyond",
        "verified": "measured against FE for the pair's E*/S_y (contact.verified_ranges)",
        "unverified": "the pair's E*/S_y lies outside the span of the FE cases: the stand-in "
        "range is kept",
    }
)


@dataclass(frozen=True)
class LawRange:
    """The fitted (validated) range of one contact law (see the module docstring)."""

    law: Law
    delta_ratio_max: float
    delta_ref: str
    status: str
    source: str
    reference_keys: tuple[str, ...]
    e_over_sy: tuple[float, float] | None = None

    def __post_init__(self) -> None:
        if self.status not in STATUSES:
            raise ValueError(f"status must be one of {sorted(STATUSES)}, got {self.status!r}")
        if not self.delta_ratio_max > 0.0:
            raise ValueError(f"delta_ratio_max must be > 0, got {self.delta_ratio_max!r}")
        cite(*self.reference_keys)  # every key is registered

    @property
    def confirmed(self) -> bool:
        """True only when the number was read in the source."""
        return self.status == "confirmed"

    @property
    def verified(self) -> tuple[VerifiedCase, ...]:
        """The law's verified range per FE case (``()``: none; contact.verified_ranges)."""
        return verified_cases(str(self.law))

    @property
    def reference(self) -> str:
        """The name of the ratio's reference interference: ``"delta_c"`` (Jackson-Green's) or
        ``"delta_y"`` (the law's own first yield: Kogut-Komvopoulos, Brake, Thornton)."""
        return self.delta_ref.split(" ")[0]

    @property
    def stand_in_text(self) -> str:
        """The stand-in in one line: ``delta <= 1 delta_y (analytical)``."""
        if math.isinf(self.delta_ratio_max):
            return f"no fitted range ({self.status}): never flagged as extrapolated"
        return f"delta <= {self.delta_ratio_max:g} {self.reference} ({self.status})"

    @property
    def text(self) -> str:
        """One line for people: the verified range per FE case and, outside their E*/S_y
        span, the stand-in; only the stand-in for a law without a verified range. A law of
        ``BEYOND_FE`` is verified at the cases' own pairs only, its inputs the FE reference
        does not use included: any other pair is held to the stand-in."""
        cases = self.verified
        if not cases:
            return self.stand_in_text
        per_case = ", ".join(
            f"{c.upper:.3g} delta_c at E*/S_y = {c.e_star_over_sy:.0f}" for c in cases
        )
        beyond = BEYOND_FE.get(str(self.law))
        if beyond is not None:
            names, other = " and ".join(beyond), " or ".join(beyond)
            return (
                f"verified range ({tolerance_text()}) at these FE cases' pairs only, their "
                f"{names} included (the FE reference does not use them): delta <= {per_case}; "
                f"any other pair (another E*/S_y, {other}) unverified: {self.stand_in_text}"
            )
        lo, hi = e_star_over_sy_span(str(self.law))
        return (
            f"verified range ({tolerance_text()}): delta <= {per_case} (between cases the "
            f"smaller); E*/S_y outside {lo:.0f}-{hi:.0f} unverified: {self.stand_in_text}"
        )

    def describe(self) -> dict[str, Any]:
        """Plain data (``impactlab laws``): JSON-ready, ``None`` for an unbounded ratio."""
        finite = math.isfinite(self.delta_ratio_max)
        return {
            "delta_ratio_max": self.delta_ratio_max if finite else None,
            "delta_ref": self.delta_ref,
            "e_over_sy": list(self.e_over_sy) if self.e_over_sy else None,
            "status": self.status,
            "status_meaning": STATUSES[self.status],
            "confirmed": self.confirmed,
            "source": self.source,
            "references": [r.doi or r.citation for r in cite(*self.reference_keys)],
            "verified": [
                {
                    "case": c.case,
                    "e_star_over_sy": c.e_star_over_sy,
                    "delta_ratio_max": c.upper,
                    "limited_by": c.limited_by,
                    "first_failure_delta_ratio": c.first_failure
                    if math.isfinite(c.first_failure)
                    else None,
                    **({"inputs": dict(c.inputs)} if c.inputs else {}),
                }
                for c in self.verified
            ],
            "text": self.text,
        }
