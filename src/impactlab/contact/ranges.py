"""The range over which each contact law is verified against FE, or its stand-in: status, sources.

**Verified range.** Every law but the tabulated one has a range measured against the shipped
finite-element (CalculiX) reference curves (``impactlab.contact.verified_ranges``): the
interference up to which it stays within 10 % of the FE loading force and 0.05 of its
delta_r / delta_max, for the pair's E*/S_y (the shipped cases' own value at their E*/S_y, the
smaller of the two neighbouring cases' between them). That is the range the engine's
LAW_EXTRAPOLATED flag uses wherever the pair's E*/S_y lies within the span of the FE cases
(status ``"verified"``). Outside that span the range is ``"unverified"`` and the flag's message
says so.

**Outside the span** an unmeasured pair is trusted no further than every measured one: the
limit is the law's **smallest verified range over its FE cases** (in Jackson-Green's delta_c,
converted to the law's own reference per pair, :func:`smallest_verified`), and never more than
its first yield for Hertz, Brake and Thornton (with their default parameters the two agree:
Thornton's and Hertz's first yield is delta_c, Brake's delta_y lies within 0.3 % of it).

**Stand-in** (the law's own record; the tabulated law's only range). Each :class:`LawRange`
states

- ``delta_ratio_max``: the upper end of the range as a ratio ``delta / delta_ref`` (``inf``: the
  source states no fitted range); for the FEM-fitted laws (``ghaednia``, ``jackson-green``,
  ``kogut-komvopoulos``: no range found in their sources) it is the smallest verified range,
  in Jackson-Green's delta_c (:class:`SmallestVerified`);
- ``delta_ref``: the reference interference of that ratio. For every law it is the law's own
  critical (first-yield) interference, ``p[P_DY]`` (:func:`critical_interference`): Jackson-Green's
  ``delta_c = (pi C S_y / (2 E*))^2 R`` for ``ghaednia`` and ``jackson-green`` (paper Eq. 15),
  Kogut-Komvopoulos' ``delta_y`` (``delta/r' = 1.78 S_y/E*``), Brake's ``delta_y`` (Eq. 23),
  Thornton's ``delta_y`` (``p_0 = p_y``); for ``hertz``, which has no yield, the Jackson-Green
  ``delta_c`` of the pair (first yield);
- ``e_over_sy``: the range of E/S_y the source covers (``None``: not found; informative);
- ``status``: ``"confirmed"`` (read in the source), ``"provisional"`` (a labelled stand-in, the
  source's own range was not found), ``"theory"`` (a limit of the theory itself: Hertz holds up
  to first yield) or ``"analytical"`` (a closed-form law with no fitted range: its stand-in is
  its first yield, so a plastic impact on a pair outside the FE span is marked, as Hertz's);
- ``source`` (what the number rests on) and ``reference_keys`` (``impactlab.references``).

An impact whose largest interference exceeds the upper end sets LAW_EXTRAPOLATED
(:func:`extrapolation_flags`, :func:`law_extrapolated`); docs/laws/index.md lists what was
searched for the stand-ins.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from types import MappingProxyType
from typing import Any, Protocol

import numpy as np

from impactlab.contact import kernels as k
from impactlab.contact.custom_parameters import custom_parameters
from impactlab.contact.names import Law
from impactlab.contact.range_record import STATUSES, LawRange
from impactlab.contact.verified_ranges import (
    verified_cases,
    verified_upper,
)
from impactlab.flags import FLAG_LAW_EXTRAPOLATED


class _Model(Protocol):
    """What :func:`law_extrapolated` reads of a ``contact.base.ContactModel``."""

    @property
    def law_id(self) -> int: ...

    @property
    def params(self) -> np.ndarray: ...


__all__ = [
    "RANGES",
    "STATUSES",
    "LawRange",
    "SmallestVerified",
    "alias_range",
    "calibrated_max",
    "critical_interference",
    "delta_ratio",
    "extrapolation",
    "extrapolation_flags",
    "law_extrapolated",
    "law_range",
    "range_limit",
    "range_status",
    "reference_name",
    "smallest_verified",
]

#: Kogut & Etsion's (2002) FEM range, 1 <= delta/delta_c <= 110 (as quoted in the literature
#: on their model, not re-read in the source; an independent implementation of their model,
#: TaoYang1999/SCHC-framework asperity_f_cal.m, uses the same breakpoints 1, 6 and 110
#: delta_c): the FEM-fitted laws' former stand-in, kept for the record only (no limit uses it).
KOGUT_ETSION_FEM_RATIO = 110.0

_SMALLEST_SOURCE = (
    "stand-in outside the FE cases' E*/S_y span: the smallest verified range over the FE "
    "cases (contact/data/verified-ranges.json), so that a pair no FE case covers is trusted no "
    "further than every measured one; the {who} range was not found in the sources searched "
    "(publisher pages and full texts were not available); the former stand-in, Kogut & "
    "Etsion's FEM range (2002, 1 <= delta/delta_c <= 110, second-hand), is not used: every "
    "measured pair leaves 0.05 of FE's delta_r/delta_max far below it"
)


def smallest_verified(law: str | Law) -> float:
    """The smallest verified upper end delta / delta_c of ``law`` over the shipped FE cases
    (``contact/data/verified-ranges.json``); NaN for a law without a verified range."""
    cases = verified_cases(str(law))
    return min(c.upper for c in cases) if cases else math.nan


@dataclass(frozen=True)
class SmallestVerified(LawRange):
    """The range of a FEM-fitted law whose source states none: outside the FE cases' span, its
    smallest verified range over them. ``delta_ratio_max`` is in Jackson-Green's delta_c (the
    unit of the verified ranges; a pair's limit in the law's own ``reference`` is
    :func:`range_limit`)."""

    @property
    def stand_in_text(self) -> str:
        """``delta <= 0.3 delta_c, the smallest verified range over the FE cases (provisional)``."""
        return (
            f"delta <= {self.delta_ratio_max:g} delta_c, the smallest verified range over the FE "
            f"cases ({self.status})"
        )

    def describe(self) -> dict[str, Any]:
        """``LawRange.describe`` with ``delta_ref`` the unit of ``delta_ratio_max``: delta_c."""
        return {**super().describe(), "delta_ref": _JG_DC}


_JG_DC = "delta_c (Jackson-Green, paper Eq. 15: (pi C S_y / (2 E*))^2 R)"

_ALL = (
    LawRange(
        Law.HERTZ,
        1.0,
        "delta_c (Jackson-Green first yield of the pair; Hertz itself has no yield)",
        "theory",
        "linear elasticity holds up to first yield; beyond delta_c the pair deforms plastically "
        "and Hertz over-predicts the force (Johnson 1985; C(nu) of Green 2005)",
        ("johnson-1985", "green-2005"),
    ),
    SmallestVerified(
        Law.GHAEDNIA,
        smallest_verified(Law.GHAEDNIA),
        _JG_DC,
        "provisional",
        _SMALLEST_SOURCE.format(who="Ghaednia et al. (2016)"),
        ("ghaednia-2016-contact", "kogut-etsion-2002"),
    ),
    SmallestVerified(
        Law.JACKSON_GREEN,
        smallest_verified(Law.JACKSON_GREEN),
        _JG_DC,
        "provisional",
        _SMALLEST_SOURCE.format(who="Jackson & Green (2005) FEM")
        + "; the abstract (read) says only 'a wide range of interferences and materials'; "
        "second-hand (a public digest of the paper): FEM over delta/delta_c = 0 to 110+, hardness "
        "fit for a/R <= 0.412, E = 200 GPa, nu = 0.32 and five S_y (E/S_y = 124-952)",
        ("jackson-green-2005", "kogut-etsion-2002"),
        e_over_sy=(124.0, 952.0),
    ),
    SmallestVerified(
        Law.KOGUT_KOMVOPOULOS,
        smallest_verified(Law.KOGUT_KOMVOPOULOS),
        "delta_y (Kogut-Komvopoulos yield, delta/r' = 1.78 S_y/E*)",
        "provisional",
        _SMALLEST_SOURCE.format(who="Kogut & Komvopoulos (2004)")
        + "; their law fits the indentation of a half-space by a rigid sphere, so Kogut & "
        "Etsion's flattening range is not its own",
        ("kogut-komvopoulos-2004", "kogut-etsion-2002"),
    ),
    LawRange(
        Law.BRAKE,
        1.0,
        "delta_y (Brake, paper Eq. 23)",
        "analytical",
        "analytical transition model, no fitted range; Brake (2015) validates it against impact "
        "experiments from the literature (abstract, OSTI 1146110, read); outside the FE cases' "
        "E*/S_y its plastic part is not verified: the stand-in is its first yield (or its "
        "smallest verified range over the FE cases, where that is lower)",
        ("brake-2015",),
    ),
    LawRange(
        Law.THORNTON,
        1.0,
        "delta_y (Thornton: Hertz peak pressure = p_y)",
        "analytical",
        "analytical elastic-perfectly plastic model (limiting pressure p_y), no fitted range; "
        "outside the FE cases' E*/S_y its plastic part is not verified: the stand-in is its "
        "first yield (or its smallest verified range over the FE cases, where that is lower)",
        ("thornton-1997",),
    ),
    LawRange(
        Law.TABULATED,
        math.inf,
        "delta_c (Jackson-Green, paper Eq. 15), the curves' unit of interference",
        "tabulated",
        "indentation data (FE or measured), loading fitted, residual depths interpolated: "
        "valid up to the last tabulated interference, the law's hard limit (the engine stops "
        "beyond it), never extrapolated",
        ("fritsch-carlson-1980", "jackson-green-2005", "de-boor-1978", "craven-wahba-1979"),
    ),
)

#: Law -> its range (read-only); every registered law has one.
RANGES: Mapping[Law, LawRange] = MappingProxyType({r.law: r for r in _ALL})
_BY_NAME = {str(r.law): r for r in _ALL}
_RATIO_BY_ID = np.full(k.N_LAWS, np.inf)
for _r in _ALL:
    _RATIO_BY_ID[_r.law.law_id] = _r.delta_ratio_max
_STATUS_BY_ID = {r.law.law_id: r.status for r in _ALL}
#: Law id -> its smallest verified range over the FE cases (delta / delta_c; NaN: none).
_SMALLEST_BY_ID = np.full(k.N_LAWS, np.nan)
for _r in _ALL:
    _SMALLEST_BY_ID[_r.law.law_id] = smallest_verified(_r.law)
#: Laws whose own stand-in (their first yield) also caps the range outside the FE span.
_FIRST_YIELD_CAP = frozenset(r.law.law_id for r in _ALL if r.status in ("theory", "analytical"))
_NAME_BY_ID = {r.law.law_id: str(r.law) for r in _ALL}


def alias_range(name: str, law: Law) -> None:
    """Let the law registered as ``name`` (``contact.registry.register_law``) share ``law``'s
    range (a user's law is the tabulated law under its own name)."""
    _BY_NAME.setdefault(name, RANGES[law])


def law_range(law: str | Law) -> LawRange:
    """The range of the law named ``law``; ValueError listing the known names otherwise."""
    try:
        return _BY_NAME[str(law)]
    except KeyError:
        raise ValueError(
            f"unknown contact law {law!r}; known laws: {', '.join(map(str, RANGES))}"
        ) from None


def calibrated_max(law: Law, delta_ref: float, hard_limit: float, params: Any = None) -> float:
    """Upper end of ``law``'s range [m] for a pair whose reference interference is
    ``delta_ref`` [m], capped at the law's hard limit (``inf`` for a law without one): the
    verified range for the pair of ``params`` (its parameter vector) where there is one, else
    the stand-in."""
    ratio = RANGES[law].delta_ratio_max if params is None else range_limit(law.law_id, params)
    return math.inf if math.isinf(ratio) else min(float(ratio) * delta_ref, hard_limit)


def critical_interference(law_id: int, params: Any) -> Any:
    """The reference interference ``delta_ref`` [m] of law ``law_id`` for parameter vectors
    ``params`` (``(NPARAM,)``: a float; ``(N, NPARAM)``: an array): ``p[P_DY]``, for Hertz the
    Jackson-Green ``delta_c`` of the pair (from ``P_ESTAR``, ``P_R``, ``P_SY``, ``P_NU``)."""
    p = np.asarray(params, dtype=np.float64)
    ref = _jg_delta_c(p) if int(law_id) == k.HERTZ else p[..., k.P_DY]
    return float(ref) if np.ndim(ref) == 0 else ref


def _jg_delta_c(p: np.ndarray) -> Any:
    """The pair's Jackson-Green delta_c [m] from ``P_ESTAR``, ``P_R``, ``P_SY``, ``P_NU``."""
    c = 1.295 * np.exp(0.736 * p[..., k.P_NU])
    return (np.pi * c * p[..., k.P_SY] / (2.0 * p[..., k.P_ESTAR])) ** 2 * p[..., k.P_R]


#: (law_id, one parameter vector's bytes) -> _verified's answer: a result's flag, ratio and
#: warning each ask for it, always for the same few models.
_ONE_PAIR: dict[tuple[int, bytes], tuple[np.ndarray, bool]] = {}


def _verified(law_id: int, params: Any) -> tuple[np.ndarray, bool]:
    """(the verified upper end in the law's own ratio delta / delta_ref, NaN where the pair's
    E*/S_y is outside the FE span; whether the law has a verified range at all)."""
    p = np.asarray(params, dtype=np.float64)
    if p.ndim == 2 and p.shape[0] == 1:  # a batch's one shared vector (with its table)
        own, has = _verified(law_id, p[0])
        return own.reshape(1), has
    if p.ndim == 1:
        key = (int(law_id), p[: k.NPARAM].tobytes())
        hit = _ONE_PAIR.get(key)
        if hit is None:
            if len(_ONE_PAIR) >= 256:
                _ONE_PAIR.clear()
            hit = _ONE_PAIR[key] = _measure_verified(int(law_id), p[: k.NPARAM])
        return hit
    return _measure_verified(int(law_id), p)


def _measure_verified(law_id: int, p: np.ndarray) -> tuple[np.ndarray, bool]:
    """``_verified`` computed (vectorised over rows of ``p``)."""
    name = _NAME_BY_ID.get(law_id, "")
    if not verified_cases(name):
        return np.full(p.shape[:-1], np.nan), False
    with np.errstate(divide="ignore", invalid="ignore"):
        upper = np.asarray(verified_upper(name, p[..., k.P_ESTAR] / p[..., k.P_SY], p))
        own = upper * _jg_delta_c(p) / np.asarray(critical_interference(law_id, p))
    return np.asarray(own, dtype=np.float64), True


def _outside_span(law_id: int, p: np.ndarray) -> np.ndarray:
    """The limit (delta / delta_ref) of law ``law_id`` for pairs ``p`` outside the FE span: its
    smallest verified range over the FE cases in the pair's own ratio, capped at its first
    yield for Hertz, Brake and Thornton; the stand-in ``LawRange.delta_ratio_max`` for a law
    without a verified range (or where the pair's delta_ref is not a positive number)."""
    stand_in = _RATIO_BY_ID[law_id]
    with np.errstate(divide="ignore", invalid="ignore"):
        ref = np.asarray(critical_interference(law_id, p))
        own = _SMALLEST_BY_ID[law_id] * _jg_delta_c(p) / ref
    if law_id in _FIRST_YIELD_CAP:
        own = np.minimum(own, stand_in)
    return np.where(np.isfinite(own) & (own > 0.0), own, stand_in)


def range_limit(law_id: int, params: Any) -> Any:
    """The upper end of law ``law_id``'s range as delta_max / delta_ref for pairs ``params``
    (float or array): the verified range where the pair's E*/S_y is covered, else the smallest
    verified range over the FE cases (at most the first yield of Hertz, Brake and Thornton;
    :func:`_outside_span`), else the stand-in ``LawRange.delta_ratio_max``."""
    own, _ = _verified(law_id, params)
    inside = np.isfinite(own)
    if np.all(inside):
        out = own
    else:
        p = np.asarray(params, dtype=np.float64)[..., : k.NPARAM]
        out = np.where(inside, own, _outside_span(int(law_id), p))
    return float(out) if np.ndim(out) == 0 else np.asarray(out)


def delta_ratio(law_id: int, params: Any, delta_max: Any) -> Any:
    """``delta_max / delta_ref`` (float or array; NaN where either is unknown)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        r = np.asarray(delta_max, dtype=np.float64) / critical_interference(law_id, params)
    return float(r) if np.ndim(r) == 0 else r


def extrapolation(law_id: int, params: Any, delta_max: float) -> tuple[float, float]:
    """(max delta/delta_ref, the law's ``delta_ratio_max``) of one impact; (NaN, inf) when the
    law is unknown (``law_id < 0`` or ``params`` None)."""
    if params is None or not 0 <= int(law_id) < k.N_LAWS:
        return math.nan, math.inf
    return float(delta_ratio(law_id, params, delta_max)), float(range_limit(law_id, params))


def reference_name(law_id: int) -> str:
    """The name of law ``law_id``'s ratio reference (``LawRange.reference``: ``"delta_c"`` or
    ``"delta_y"``); ``"delta_c"`` for an unknown law."""
    record = next((r for r in _ALL if r.law.law_id == int(law_id)), None)
    return "delta_c" if record is None else record.reference


def range_status(law_id: int, params: Any = None) -> str | None:
    """The status of law ``law_id``'s range for the pair of ``params``: ``"verified"`` where
    its E*/S_y is covered by the FE cases, ``"unverified"`` where a law with a verified range
    meets a pair outside their span, else (and without ``params``) the stand-in's
    ``LawRange.status``; None for an unknown law."""
    if not 0 <= int(law_id) < k.N_LAWS:
        return None
    if params is not None:
        own, has = _verified(law_id, params)
        if has and np.ndim(own) == 0:  # parameters other than the FE comparison's: not verified
            ok = math.isfinite(float(own)) and custom_parameters(params) is None
            return "verified" if ok else "unverified"
    return _STATUS_BY_ID.get(int(law_id))


def extrapolation_flags(law_id: int, params: Any, delta_max: Any) -> Any:
    """``FLAG_LAW_EXTRAPOLATED`` where ``delta_max / delta_ref`` exceeds the law's range
    (:func:`range_limit`: verified, else the stand-in), else 0
    (int or int64 array; 0 for NaN, for an unknown law and for laws without a fitted range)."""
    if params is None or not 0 <= int(law_id) < k.N_LAWS:
        return 0
    ratio = np.asarray(delta_ratio(law_id, params, delta_max))
    limit = range_limit(law_id, params)
    out = np.where(ratio > limit, FLAG_LAW_EXTRAPOLATED, 0).astype(np.int64)
    return int(out) if out.ndim == 0 else out


def law_extrapolated(model: _Model, delta_max: Any) -> Any:
    """True where an impact that reached ``delta_max`` [m] (a float or an array) left the fitted
    range (verified, else the stand-in) of ``model``'s law, a ``ContactModel`` (bool or bool
    array)."""
    out = np.asarray(extrapolation_flags(model.law_id, model.params, delta_max)) != 0
    return bool(out) if out.ndim == 0 else out
