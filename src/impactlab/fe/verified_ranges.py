"""The verified ranges of the contact laws, measured from the shipped FE curves.

:func:`verified_range_table` runs ``impactlab.fe.accuracy`` over every law it measures and
every shipped elastic-perfectly plastic case and keeps, per law and case, the verified range
(``fe.accuracy.verified_range``: 10 % in force, 0.05 in delta_r / delta_max); a law that cannot
be built for a case's pair (Brake's without both bodies' Brinell hardness) has no range there.
:func:`write_verified_ranges` stores it in ``impactlab/contact/data/verified-ranges.json``
(``contact.verified_ranges.VERIFIED_PATH``), which the engine's LAW_EXTRAPOLATED flag reads
(``impactlab.contact.ranges``); ``python3 tasks.py fe-reference`` rewrites it after the curves.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from pathlib import Path
from typing import Any

from impactlab.contact import get_law
from impactlab.contact.verified_ranges import BEYOND_FE, FORMAT, VERIFIED_PATH
from impactlab.fe.accuracy import CaseAccuracy, accuracy, tolerances

__all__ = ["verified_range_table", "write_verified_ranges"]

_DIGITS = 7


def _num(x: float) -> float | None:
    return None if not math.isfinite(x) else float(f"{x:.{_DIGITS}g}")


def _inputs_beyond_fe(law: str, case: Any) -> dict[str, Any]:
    """``{"inputs": {name: value}}``: the compiled inputs of ``law`` for ``case``'s pair that
    the FE reference does not fix (``contact.verified_ranges.BEYOND_FE``); empty for others."""
    slots = BEYOND_FE.get(law)
    if not slots:
        return {}
    params = get_law(law).build(case.pair, case.radius).params
    return {"inputs": {name: _num(params[slot]) for name, slot in slots.items()}}


def verified_range_table(results: Sequence[CaseAccuracy] | None = None) -> dict[str, Any]:
    """The content of the verified-ranges file (plain data) from ``results`` (default: every
    measured law against every shipped case, ``fe.accuracy.accuracy()``)."""
    chosen = list(results) if results is not None else accuracy()
    laws: dict[str, list[dict[str, Any]]] = {}
    for ca in chosen:
        for a in ca.built:
            v = a.verified
            laws.setdefault(a.law, []).append(
                {
                    "case": ca.case.name,
                    "e_star_over_sy": _num(ca.case.e_star_over_sy),
                    "verified_delta_ratio": _num(v.upper),
                    "limited_by": v.limited_by,
                    "first_failure_delta_ratio": _num(v.first_failure),
                    **_inputs_beyond_fe(a.law, ca.case),
                }
            )
    return {
        "format": FORMAT,
        "tolerances": tolerances(),
        "delta_ratio": "delta / delta_c, delta_c the pair's Jackson-Green first-yield "
        "interference (paper Eq. 15)",
        "e_star_over_sy": "E* / S_y of the pair (S_y of the body that yields first)",
        "cases": [
            {
                "case": ca.case.name,
                "description": ca.case.description,
                "e_star_over_sy": _num(ca.case.e_star_over_sy),
                "delta_c": _num(ca.case.delta_c),
            }
            for ca in chosen
        ],
        "laws": laws,
    }


def write_verified_ranges(path: Path = VERIFIED_PATH) -> Path:
    """Measure the verified ranges from the shipped curves and write them to ``path``."""
    path = Path(path)
    path.write_text(json.dumps(verified_range_table(), indent=1) + "\n")
    return path
