"""The tabulated contact law from FE indentation curves (``law="tabulated"``, built in
``impactlab.contact.tabulated``): the shipped curves' source, and FE runs for other pairs.

- ``curves_from_runs``: dimensionless ``IndentationCurves`` from FE runs of one pair (a shipped
  case's ``runs`` or ``indent`` results): the farthest loading curve and every converged
  (delta_max, delta_r); the law is Hertz up to delta_c.
- ``write_shipped_curves``: ``impactlab/contact/data/fe-curves.json`` from the shipped cases
  (``fe.curves``); a test checks that the file matches them.
- ``hardened_curves``, ``hardened_law``: the curves and the law of the shipped paper's pair
  with a strain-hardening flat (``fe/data/hardening``; not among the default candidates of
  ``law="tabulated"``, which would otherwise find two curves for one E*/S_y).
- ``tabulated_law(pair, radius)``: the law for any pair: from the shipped or cached curves
  when one matches the pair (E*/S_y, nu and the body that yields) and every FE option asked
  (``fe.tabulated_options``), else from new ``indent``
  runs of the pair itself, sphere elastic-plastic (CalculiX ``ccx`` needed; RuntimeError
  saying how to install it), whose curves, dimensionless in the FE problem's own delta_c and
  F_c and labelled with its E*/S_y and the body that yields, are kept in
  ``contact.tabulated.curves_cache_dir()`` (once the law built from them passed its checks)
  so that ``law="tabulated"`` then finds them too.
"""

from __future__ import annotations

import hashlib
import json
import math
import os
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any, Protocol

import numpy as np

from impactlab.contact import ContactModel
from impactlab.contact._common import jg_critical
from impactlab.contact.indentation_data import (
    SHIPPED_PATH,
    IndentationCurves,
    curves_file_record,
    yielding_body,
)
from impactlab.contact.tabulated import Tabulated, curves_cache_dir, select_curves
from impactlab.fe.curves import HARDENED_DIR, load_case, load_cases
from impactlab.fe.run import indent
from impactlab.fe.tabulated_checks import check_reach, check_unload, fe_pair, fe_yielding
from impactlab.fe.tabulated_options import (
    RECORD_KEY,
    file_record,
    mismatches,
    run_options,
    stored_curves,
)
from impactlab.materials import ContactPair

#: The maxima of new FE runs, in multiples of delta_c: where delta_r starts (1.5, 2) and about
#: two per decade up to 100 delta_c.
RUN_MAXIMA_OVER_DELTA_C: tuple[float, ...] = (1.0, 1.5, 2.0, 3.0, 10.0, 30.0, 100.0)


class _Run(Protocol):
    """One FE run: a shipped ``ReferenceRun`` or an ``IndentationResult``."""

    @property
    def delta_max(self) -> float: ...
    @property
    def loading_delta(self) -> np.ndarray: ...
    @property
    def loading_force(self) -> np.ndarray: ...
    @property
    def residual_depth(self) -> float: ...
    @property
    def converged(self) -> bool: ...


def _usable(run: _Run) -> bool:
    """Converged, and balanced where the run says (``IndentationResult.usable``; a runner's
    own run objects may have no ``usable``)."""
    return bool(getattr(run, "usable", run.converged))


def curves_from_runs(
    runs: Sequence[_Run],
    pair: ContactPair,
    radius: float,
    name: str,
    source: str,
    yielding: str = "flat",
) -> IndentationCurves:
    """Dimensionless curves of FE ``runs`` of ``pair`` with a sphere of ``radius`` [m]:
    the loading curve that reaches farthest and every converged run's delta_r (ValueError
    when fewer than two runs converged). ``yielding``: the body that yields in the runs,
    "flat" (an elastic or a harder sphere) or "sphere"."""
    done = [r for r in runs if _usable(r) and math.isfinite(r.residual_depth)]
    if len(done) < 2:
        raise ValueError(f"{name}: {len(done)} converged FE runs, at least 2 are needed")
    dc, fc = jg_critical(pair.E_star, radius, pair.yield_strength, pair.nu)
    far = max(done, key=lambda r: float(r.loading_delta[-1]))
    d, f = np.asarray(far.loading_delta), np.asarray(far.loading_force)
    keep = (d > 0.0) & (f > 0.0)
    dm = np.array([r.delta_max for r in done])
    dr = np.array([max(r.residual_depth, 0.0) for r in done])
    return IndentationCurves(
        name,
        source,
        pair.E_star / pair.yield_strength,
        pair.nu,
        d[keep] / dc,
        f[keep] / fc,
        dm / dc,
        dr / dm,
        elastic_limit=1.0,
        yielding=yielding,
    )


def shipped_fe_curves() -> list[IndentationCurves]:
    """The curves of every shipped FE case (``fe.curves.load_cases``)."""
    out = []
    for case in load_cases():
        source = (
            f"FE reference case {case.name!r} ({case.description}; CalculiX {case.ccx_version}, "
            f"R = {case.radius:g} m, {case.sphere} sphere, mu = {case.mu:g}, mesh level "
            f"{case.mesh_level})"
        )
        side = fe_yielding(case.pair, case.sphere)
        out.append(curves_from_runs(case.runs, case.pair, case.radius, case.name, source, side))
    return out


def shipped_curves_record() -> dict[str, Any]:
    """The content of the shipped curves file."""
    return curves_file_record(shipped_fe_curves())


def write_shipped_curves(path: str | Path = SHIPPED_PATH) -> Path:
    """Write the shipped curves file (from ``fe/data``); returns its path."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(shipped_curves_record(), indent=1) + "\n")
    return path


#: The shipped FE case of the paper's pair whose flat strain-hardens.
HARDENED_PAPER_CASE = "paper-aisi201-on-aisi1010-hardening"


def hardened_curves(name: str = HARDENED_PAPER_CASE) -> IndentationCurves:
    """The dimensionless curves of the shipped hardened case ``name`` (``fe/data/hardening``):
    delta_c and F_c those of the pair's initial yield strength."""
    case = load_case(name, HARDENED_DIR)
    source = (
        f"FE reference case {case.name!r} ({case.description}; CalculiX {case.ccx_version}, "
        f"R = {case.radius:g} m, {case.sphere} sphere, mu = {case.mu:g}, mesh level "
        f"{case.mesh_level})"
    )
    side = fe_yielding(case.pair, case.sphere)
    return curves_from_runs(case.runs, case.pair, case.radius, case.name, source, side)


def hardened_law(pair: ContactPair, radius: float, name: str = HARDENED_PAPER_CASE) -> ContactModel:
    """The tabulated law of ``pair`` (sphere of ``radius`` [m]) from the hardened case
    ``name``; ValueError when the pair's E*/S_y or nu does not match the case's."""
    return Tabulated(hardened_curves(name)).build(pair, radius)


def _slug(text: str) -> str:
    return "".join(ch if ch.isalnum() else "-" for ch in text.lower()).strip("-")[:60]


#: Arguments of ``indent`` that do not change its results (left out of a curves file's key).
_NOT_RESULTS = frozenset({"workers", "cache_dir", "use_cache", "keep_files", "progress"})


def curves_file_name(
    pair: ContactPair, radius: float, maxima: Sequence[float], indent_kwargs: dict[str, Any]
) -> str:
    """The name of the curves file of FE runs of ``pair``: a readable slug of the bodies'
    names and a short SHA-256 of every value the runs depend on (E, nu, S_y of both bodies,
    R [m], the maxima / delta_c, ``indent``'s other arguments: hardening, sphere, mu, mesh),
    so that two pairs never share a file however alike their names."""
    values = {
        "bodies": [[m.E, m.nu, m.yield_strength] for m in (pair.body, pair.flat)],
        "radius": radius,
        "maxima": [float(m) for m in maxima],
        "indent": {k: v for k, v in indent_kwargs.items() if k not in _NOT_RESULTS},
    }
    blob = json.dumps(values, sort_keys=True, default=repr).encode()
    slug = _slug(f"fe-{pair.body.name}-on-{pair.flat.name}")[:48].strip("-")
    return f"{slug}-{hashlib.sha256(blob).hexdigest()[:12]}"


def _stored_law(
    pair: ContactPair, radius: float, asked: dict[str, Any], given: set[str], reach: float | None
) -> tuple[ContactModel | None, str]:
    """The law of ``pair`` from the stored curves whose options match the ``asked`` ones
    (``tabulated_options.mismatches``), or None and why none serves (ValueError of
    ``select_curves`` when no stored curves fit the pair at all)."""
    stored = stored_curves()
    fits = [c for c, o in stored if not mismatches(o, asked, given, reach)]
    try:
        chosen = select_curves(pair, fits)
    except ValueError:
        near = select_curves(pair, [c for c, _ in stored])  # none for the pair: its message
    else:  # a law that fails its own checks says why (not "no curves")
        return Tabulated(chosen).build(pair, radius), ""
    options = next(o for c, o in stored if c is near)
    return None, (
        f"the stored curves that fit the pair ({near.name!r}) do not match the options "
        f"asked: {'; '.join(mismatches(options, asked, given, reach))}"
    )


def tabulated_law(
    pair: ContactPair,
    radius: float,
    *,
    run_fe: bool = True,
    maxima_over_delta_c: Sequence[float] | None = None,
    runner: Callable[..., Sequence[_Run]] = indent,
    **indent_kwargs: Any,
) -> ContactModel:
    """The tabulated law for ``pair`` and a sphere of ``radius`` [m].

    From the shipped or cached FE curves when one matches the pair (``contact.tabulated``'s
    tolerances, the same body yielding) and every option asked (``fe.tabulated_options``:
    ``flat_hardening``, ``sphere_hardening``, ``mu`` and ``mesh_level``, given or their
    defaults; ``sphere`` and the reach of ``maxima_over_delta_c`` where given); otherwise,
    with ``run_fe``, from new ``indent`` runs of the pair (default: an elastic-plastic
    sphere, frictionless; ``indent_kwargs`` go to ``indent``; the curves labelled with the
    body that yields in them, ``yielding_body``) loaded to ``maxima_over_delta_c`` times
    delta_c (default ``RUN_MAXIMA_OVER_DELTA_C``; delta_c, F_c and E*/S_y those of the FE
    problem, ``Problem.pair``), whose curves and options are stored in the curves cache (a
    file per pair and inputs: ``curves_file_name``) once the law built from them passed its
    checks (``Tabulated.build``: a law that fails them is never stored). Without ``run_fe``,
    ValueError naming each option the stored curves of the pair do not match. Needs
    CalculiX ``ccx`` for the runs (RuntimeError with how to install it otherwise);
    ValueError, before any run, when a maximum is too large for the radius (a soft flat's
    delta_c is large: pass smaller ``maxima_over_delta_c``), when ``sphere`` or
    ``flat_hardening`` would make the other body yield than in the pair, when
    ``sphere="rigid"`` makes a problem whose E*/S_y is not the pair's (the flat's E* alone:
    ``fe_pair``), or when ``unload`` is not True (a loading-only run has no residual depth).
    The model's ``source`` names the curves used.
    """
    check_unload(indent_kwargs.get("unload", True))
    maxima = RUN_MAXIMA_OVER_DELTA_C if maxima_over_delta_c is None else maxima_over_delta_c
    reach = None if maxima_over_delta_c is None else max(float(m) for m in maxima)
    dc, _ = jg_critical(pair.E_star, radius, pair.yield_strength, pair.nu)
    asked = run_options(pair, radius, indent_kwargs, dc)
    try:
        law, why = _stored_law(pair, radius, asked, set(indent_kwargs), reach)
    except ValueError:
        if not run_fe:
            raise
        law, why = None, ""
    if law is not None:
        return law
    if not run_fe:
        raise ValueError(f"{why}; run_fe=True makes curves with these options (FE runs: CalculiX)")
    sphere = indent_kwargs.get("sphere", "elastic-plastic")
    side = fe_yielding(pair, sphere, indent_kwargs.get("flat_hardening"))
    if side != yielding_body(pair):  # curves that would not fit the pair: minutes for nothing
        what = f"sphere={sphere!r}" if side == "flat" else "flat_hardening='elastic'"
        raise ValueError(
            f"{what} makes FE curves whose {side} yields, but the {yielding_body(pair)} yields "
            f"first in {pair.body.name} on {pair.flat.name}: the law would refuse them; leave "
            "sphere='elastic-plastic' and the flat plastic, so that the FE models the pair"
        )
    fe = fe_pair(pair, sphere)
    dc, _ = jg_critical(fe.E_star, radius, fe.yield_strength, fe.nu)
    check_reach(pair, radius, maxima, dc, maxima_over_delta_c is None)
    runs = runner(
        pair.flat, pair.body, radius=radius, delta_max=[m * dc for m in maxima], **indent_kwargs
    )
    name = curves_file_name(pair, radius, maxima, indent_kwargs)
    source = (
        f"FE runs of impactlab.fe.indent: {pair.body.name} sphere on {pair.flat.name}, "
        f"R = {radius:g} m, maxima {', '.join(f'{m:g}' for m in maxima)} delta_c"
    )
    curves = curves_from_runs(runs, fe, radius, name, source, side)
    law = Tabulated(curves).build(pair, radius)  # before the cache: a bad law is never kept
    folder = curves_cache_dir()
    folder.mkdir(parents=True, exist_ok=True)
    record = {**curves_file_record([curves]), RECORD_KEY: file_record(asked, maxima)}
    tmp = folder / f".{name}.json.{os.getpid()}.tmp"  # whole, then renamed over a damaged one
    tmp.write_text(json.dumps(record, indent=1))
    os.replace(tmp, folder / f"{name}.json")
    return law


#: How docs/laws/tabulated.md names the shipped FE cases.
CASE_LABELS: dict[str, str] = {
    "paper-aisi201-on-aisi1010": "paper's pair",
    "aisi201-on-al6061t6": "aluminium",
    "elastic-sphere-on-aisi4340": "hard steel",
    "aisi201-on-pmma": "PMMA",
    "elastic-52100-on-aisi304": "AISI 304",
    "elastic-52100-on-copper-ofhc": "copper",
}


def unloading_energy_ratios() -> dict[str, dict[float, float]]:
    """Energy returned on unloading, the shipped law's Hertzian branch over the FE's
    (``W_u``: the trapezoid of the FE unloading curve), by case and delta_max / delta_c, for
    every converged FE run the law reaches (``law="tabulated"`` built for the case's pair)."""
    out: dict[str, dict[float, float]] = {}
    for case in load_cases():
        model = Tabulated().build(case.pair, case.radius)
        row = out.setdefault(case.name, {})
        for run in case.runs:
            if not (_usable(run) and run.delta_max <= model.max_interference):
                continue
            d, f = np.asarray(run.unloading_delta), np.asarray(run.unloading_force)
            order = np.argsort(d)
            fe_work = float(np.trapezoid(f[order], d[order]))
            ratio = model.unload(run.delta_max).energy_returned() / fe_work
            row[round(run.delta_max / case.delta_c, 6)] = ratio
    return out


def unloading_energy_table() -> str:
    """:func:`unloading_energy_ratios` as the Markdown table of docs/laws/tabulated.md
    (3 decimals; a blank where a case has no run)."""
    ratios = unloading_energy_ratios()
    order = list(CASE_LABELS)
    names = sorted(ratios, key=lambda n: (order.index(n) if n in order else len(order), n))
    maxima = sorted({m for row in ratios.values() for m in row})
    lines = [
        "| `delta_max/delta_c` | " + " | ".join(CASE_LABELS.get(n, n) for n in names) + " |",
        "| --- |" + " --- |" * len(names),
    ]
    for m in maxima:
        cells = [f"{ratios[n][m]:.3f}" if m in ratios[n] else "" for n in names]
        lines.append(f"| {m:g} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


__all__ = [
    "CASE_LABELS",
    "HARDENED_PAPER_CASE",
    "RUN_MAXIMA_OVER_DELTA_C",
    "curves_file_name",
    "curves_from_runs",
    "hardened_curves",
    "hardened_law",
    "shipped_curves_record",
    "shipped_fe_curves",
    "tabulated_law",
    "unloading_energy_ratios",
    "unloading_energy_table",
    "write_shipped_curves",
]
