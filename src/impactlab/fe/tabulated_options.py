"""The FE options of stored tabulated-law curves, and which stored curves a request of
``fe.tabulated_law`` may use.

Options (``indent``'s): ``sphere``, ``flat_hardening``, ``sphere_hardening``, ``mu``,
``mesh_level``, and the reach ``maxima_over_delta_c`` (the largest maximum, in delta_c).
Shipped curves: their case's (``fe.curves``), perfectly plastic; curves that
``tabulated_law`` cached record theirs in their file (``"fe_inputs"``); a file without the
record (written by an earlier release) is taken as made with the defaults. Stored curves
serve a request only when each option matches: the hardening tables, ``mu`` and
``mesh_level`` always (the defaults where not given), ``sphere`` and the reach only when
given (a stored elastic sphere serves a pair whose flat yields; curves reach as far as they
reach)."""

from __future__ import annotations

import functools
import json
import math
import warnings
from collections.abc import Sequence
from typing import Any

from impactlab.contact.indentation_data import IndentationCurves, read_curves, shipped_curves
from impactlab.contact.tabulated import DamagedCurvesWarning, curves_cache_dir
from impactlab.fe.curves import load_cases
from impactlab.fe.problem import largest_delta_max, make_problem, perfectly_plastic
from impactlab.materials import ContactPair, Material

#: A hardening option that is the material's elastic-perfectly plastic table.
PLASTIC = "perfectly plastic"
#: ``indent``'s options that change the curves (``maxima_over_delta_c`` is the reach).
OPTIONS = ("sphere", "flat_hardening", "sphere_hardening", "mu", "mesh_level")
#: The options of runs asked with none given (``indent``'s defaults).
DEFAULTS: dict[str, Any] = {
    "sphere": "elastic-plastic",
    "flat_hardening": PLASTIC,
    "sphere_hardening": PLASTIC,
    "mu": 0.0,
    "mesh_level": 1,
}
#: The key of a cached curves file that records its options.
RECORD_KEY = "fe_inputs"


def _table(rows: tuple[tuple[float, float], ...], m: Material) -> Any:
    if rows == perfectly_plastic(m):
        return PLASTIC
    return [list(r) for r in rows] if rows else "elastic"


def run_options(
    pair: ContactPair, radius: float, kwargs: dict[str, Any], dc: float
) -> dict[str, Any]:
    """The options of ``indent`` runs of ``pair`` with ``kwargs`` as plain values, read as
    ``make_problem`` reads them (its ValueError for a bad one): hardening tables as rows of
    (true stress [Pa], true plastic strain), :data:`PLASTIC` or "elastic"; ``dc``: delta_c [m]."""
    given = {k: kwargs[k] for k in OPTIONS if k in kwargs}
    d = min(dc, 0.5 * largest_delta_max(radius))
    p = make_problem(pair.flat, pair.body, radius=radius, delta_max=d, **given)
    return {
        "sphere": p.sphere,
        "flat_hardening": _table(p.flat_hardening, pair.flat),
        "sphere_hardening": _table(p.sphere_hardening, pair.body),
        "mu": p.mu,
        "mesh_level": p.mesh_level,
    }


@functools.cache
def _shipped_options() -> dict[str, dict[str, Any]]:
    return {
        c.name: {**DEFAULTS, "sphere": c.sphere, "mu": c.mu, "mesh_level": c.mesh_level}
        for c in load_cases()
    }


def stored_curves() -> list[tuple[IndentationCurves, dict[str, Any]]]:
    """Every stored curve set with its options (:data:`OPTIONS` and ``reach``, in delta_c):
    the shipped ones, then those of ``curves_cache_dir()`` (a damaged file is skipped with a
    ``DamagedCurvesWarning`` naming it)."""
    shipped = _shipped_options()
    out = [
        (c, {**shipped[c.name], "reach": c.max_delta})
        for c in shipped_curves()
        if c.name in shipped
    ]
    folder = curves_cache_dir()
    for path in sorted(folder.glob("*.json")) if folder.is_dir() else ():
        try:
            sets = read_curves(path)
            record = json.loads(path.read_text()).get(RECORD_KEY) or {}
        except (OSError, ValueError, KeyError, TypeError, AttributeError) as exc:
            warnings.warn(
                f"curves cache file {path} is damaged ({exc}): skipped, as if missing "
                "(new FE curves of its pair are written over it)",
                DamagedCurvesWarning,
                stacklevel=3,
            )
            continue
        options = {**DEFAULTS, **{k: record[k] for k in OPTIONS if k in record}}
        asked = record.get("maxima_over_delta_c") or [0.0]
        out += [(c, {**options, "reach": max(c.max_delta, *asked)}) for c in sets]
    return out


def file_record(options: dict[str, Any], maxima: Sequence[float]) -> dict[str, Any]:
    """What a cached curves file records of the runs (:data:`RECORD_KEY`)."""
    return {**options, "maxima_over_delta_c": [float(m) for m in maxima]}


def _shown(option: str, value: Any) -> str:
    if isinstance(value, list):
        return f"a hardening table of {len(value)} rows"
    return f"{value:g}" if isinstance(value, float) else str(value)


def mismatches(
    stored: dict[str, Any], asked: dict[str, Any], given: set[str], reach: float | None
) -> list[str]:
    """How the ``stored`` options differ from the ``asked`` ones (each as ``option value,
    not asked``); ``given``: the options passed (``sphere`` is compared only then); ``reach``:
    the largest maximum asked (delta_c), None when ``maxima_over_delta_c`` was not given."""
    out = []
    for k in OPTIONS:
        s, a = stored[k], asked[k]
        if k == "sphere" and k not in given:
            continue
        if k == "sphere_hardening" and stored["sphere"] != "elastic-plastic":
            if a == PLASTIC:  # an elastic or rigid sphere's curves serve the default
                continue
            s = f"none ({stored['sphere']} sphere)"
        if k == "mu" and isinstance(s, float) and math.isclose(s, a, rel_tol=1e-9, abs_tol=0.0):
            continue
        if s != a:
            out.append(f"{k} {_shown(k, s)}, not {_shown(k, a)}")
    if reach is not None and stored["reach"] < reach * (1.0 - 1e-6):
        out.append(f"reach {stored['reach']:.4g} delta_c, not {reach:g}")
    return out
