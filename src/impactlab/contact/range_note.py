"""One line for people on the range a result's contact law is held to for its pair: verified
against FE (``impactlab.contact.ranges``, ``range_status`` "verified"), or not, and why.

An impact that stays below the law's stand-in range carries no flag, so its result alone would
not say whether the law was ever checked against FE for the pair; ``ImpactResult.summary()``,
``DropResult.summary()`` and their ``to_dict()`` (``impactlab simulate`` / ``drop``, with
``--json``) show this line (``law_range``) next to the flags.
"""

from __future__ import annotations

import hashlib
import math
from typing import Any

import numpy as np

from impactlab.contact import kernels as k
from impactlab.contact.custom_parameters import custom_parameters
from impactlab.contact.names import Law
from impactlab.contact.ranges import STATUSES, law_range, range_limit, range_status
from impactlab.contact.verified_ranges import (
    BEYOND_FE,
    differing_inputs,
    e_star_over_sy_span,
    verified_cases,
    verified_upper,
)

__all__ = ["note_source", "range_note"]

#: The source of the curves behind each table of the tabulated law built in this process
#: (``Tabulated.build``: ``note_source``), by the digest of the table.
_SOURCES: dict[str, str] = {}


def _digest(params: Any) -> str:
    """SHA-256 of the curve table of a tabulated law's SI parameters ``params``."""
    table = np.ascontiguousarray(np.asarray(params, dtype=np.float64)[k.NPARAM :])
    return hashlib.sha256(table[: k.CURVE_LENGTH].tobytes()).hexdigest()


def note_source(params: Any, source: str) -> None:
    """Remember ``source`` (the curves' name and source) for the table of the tabulated law's
    SI parameters ``params``: ``range_note`` names it."""
    _SOURCES[_digest(params)] = source


def _tabulated(p: np.ndarray) -> str:
    """The tabulated law's line: its table's end (the hard limit) in m and delta_c, and the
    source of its curves where a law of this process built them."""
    end, dc = float(p[k.P_DLIM]), float(p[k.P_TB_DC])
    source = _SOURCES.get(_digest(p), "")
    source = f"; source: {source}" if source else ""
    return (
        f"tabulated: interpolated from its curves up to their end, {end:.4g} m "
        f"({end / dc:.4g} delta_c), and refused beyond it{source}"
    )


def _beyond_fe(name: str, ratio: float, p: np.ndarray, upper: str) -> str:
    """The unverified line of a law of ``BEYOND_FE`` within its cases' E*/S_y span: the inputs
    that differ from those of the FE case at the pair's E*/S_y, or, between the cases' E*/S_y,
    that its range holds for the cases' own pairs only."""
    differ = differing_inputs(name, ratio, p)
    if differ:
        names, one = " and ".join(differ), len(differ) == 1
        return (
            f"unverified: {name}'s {names} {'is not that' if one else 'are not those'} of the "
            f"FE case's pair at E*/S_y = {ratio:.4g} (the FE reference does not use "
            f"{'it' if one else 'them'}); stand-in limit {upper}"
        )
    cases = ", ".join(f"{c.e_star_over_sy:.0f}" for c in verified_cases(name))
    return (
        f"unverified: E*/S_y = {ratio:.4g} is not that of an FE case ({cases}); {name} is "
        f"verified for those cases' own pairs only, their {' and '.join(BEYOND_FE[name])} "
        f"included; stand-in limit {upper}"
    )


#: (law_id, the parameters' bytes) -> range_note's line: a batch asks for it on every call,
#: for the same few models (0.1 ms of a 16-impact batch). The tabulated law's line, which
#: names where this process built its curves, is not kept.
_NOTES: dict[tuple[int, bytes], str | None] = {}


def range_note(law_id: int, params: Any) -> str | None:
    """``verified against FE up to 1 delta_c (E*/S_y = 360; FE cases 28-1731)``, or
    ``unverified: E*/S_y = 2198 outside the FE cases' 28-1731; stand-in limit 1 delta_c``,
    or the stand-in's status (``contact.ranges.STATUSES``) and limit for a law without a
    verified range (the tabulated law: its data's end in m and delta_c, and the source of its
    curves where this process built the law: ``note_source``); None for an unknown law or
    without parameters (SI parameters ``params`` of ``ContactModel.params``).

    A verified upper end is in Jackson-Green's delta_c, as in the docs and ``impactlab laws
    --accuracy``; where the law's own reference interference differs (Kogut-Komvopoulos' and
    Brake's delta_y, the unit of a result's ``max_delta_ratio``) the line also gives it in
    that one (``... 0.3 delta_c (Jackson-Green's; = 0.305 delta_y, the law's own; ...``). A
    stand-in limit is in the law's own reference (``LawRange.delta_ref``)."""
    if params is None:
        return None
    key = (int(law_id), np.asarray(params, dtype=np.float64).tobytes())
    if key in _NOTES:
        return _NOTES[key]
    note = _note(law_id, params)
    if range_status(law_id, params) != "tabulated":
        if len(_NOTES) >= 256:
            _NOTES.clear()
        _NOTES[key] = note
    return note


def _note(law_id: int, params: Any) -> str | None:
    """:func:`range_note`, worked out."""
    status = range_status(law_id, params)
    if status is None or params is None:
        return None
    p = np.asarray(params, dtype=np.float64)
    ratio = float(p[k.P_ESTAR] / p[k.P_SY])
    limit = float(range_limit(law_id, params))
    name = next((str(law) for law in Law if law.law_id == int(law_id)), "")
    lo, hi = e_star_over_sy_span(name)
    ref = law_range(name).reference  # the law's own: delta_c or delta_y
    upper = "no upper end" if math.isinf(limit) else f"{limit:.3g} {ref}"
    if status == "verified":
        jg = float(verified_upper(name, ratio, p))  # in Jackson-Green's delta_c, as the docs
        own = f"Jackson-Green's; = {upper}, the law's own; "
        if math.isclose(limit, jg, rel_tol=5e-4):
            own = ""
        return (
            f"verified against FE up to {jg:.3g} delta_c ({own}E*/S_y = {ratio:.4g}; FE cases "
            f"{lo:.0f}-{hi:.0f})"
        )
    custom = custom_parameters(params)
    if status == "unverified" and custom is not None and np.isfinite(limit):
        jg = float(verified_upper(name, ratio, p))
        if math.isfinite(jg):
            return (
                f"unverified: the law parameters {custom} are not the defaults the FE comparison "
                f"used; with the defaults it is verified up to {jg:.3g} delta_c (E*/S_y = "
                f"{ratio:.4g})"
            )
    if status == "unverified" and name in BEYOND_FE and lo * (1 - 1e-6) <= ratio <= hi * (1 + 1e-6):
        return _beyond_fe(name, ratio, p, upper)
    if status == "unverified":
        return (
            f"unverified: E*/S_y = {ratio:.4g} outside the FE cases' {lo:.0f}-{hi:.0f}; "
            f"stand-in limit {upper}"
        )
    meaning = STATUSES.get(status, "")
    if status == "tabulated":  # its data are its range: FE curves, or a user's own
        return _tabulated(p)
    if math.isinf(limit):
        return f"{status}, not verified against FE: {meaning}"
    return f"{status}, not verified against FE ({meaning}): limit {upper}"
