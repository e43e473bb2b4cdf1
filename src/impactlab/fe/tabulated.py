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
  when one matches the pair's E*/S_y and nu, else from new ``indent`` runs (CalculiX ``ccx``
  needed; RuntimeError saying how to install it), whose curves are kept in
  ``contact.tabulated.curves_cache_dir()`` so that ``law="tabulated"`` then finds them too.
"""

from __future__ import annotations

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
)
from impactlab.contact.tabulated import Tabulated, curves_cache_dir, select_curves
from impactlab.fe.curves import HARDENED_DIR, load_case, load_cases
from impactlab.fe.run import indent
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


def curves_from_runs(
    runs: Sequence[_Run], pair: ContactPair, radius: float, name: str, source: str
) -> IndentationCurves:
    """Dimensionless curves of FE ``runs`` of ``pair`` with a sphere of ``radius`` [m]:
    the loading curve that reaches farthest and every converged run's delta_r (ValueError
    when fewer than two runs converged)."""
    done = [r for r in runs if r.converged and math.isfinite(r.residual_depth)]
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
        out.append(curves_from_runs(case.runs, case.pair, case.radius, case.name, source))
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
    return curves_from_runs(case.runs, case.pair, case.radius, case.name, source)


def hardened_law(pair: ContactPair, radius: float, name: str = HARDENED_PAPER_CASE) -> ContactModel:
    """The tabulated law of ``pair`` (sphere of ``radius`` [m]) from the hardened case
    ``name``; ValueError when the pair's E*/S_y or nu does not match the case's."""
    return Tabulated(hardened_curves(name)).build(pair, radius)


def _slug(text: str) -> str:
    return "".join(ch if ch.isalnum() else "-" for ch in text.lower()).strip("-")[:60]


def tabulated_law(
    pair: ContactPair,
    radius: float,
    *,
    run_fe: bool = True,
    maxima_over_delta_c: Sequence[float] = RUN_MAXIMA_OVER_DELTA_C,
    runner: Callable[..., Sequence[_Run]] = indent,
    **indent_kwargs: Any,
) -> ContactModel:
    """The tabulated law for ``pair`` and a sphere of ``radius`` [m].

    From the shipped or cached FE curves when one matches the pair (``contact.tabulated``'s
    tolerances); otherwise, with ``run_fe``, from new ``indent`` runs of the pair (an
    elastic-plastic sphere, frictionless; ``indent_kwargs`` go to ``indent``) loaded to
    ``maxima_over_delta_c`` times delta_c, whose curves are stored in the curves cache.
    Needs CalculiX ``ccx`` for the runs (RuntimeError with how to install it otherwise).
    The model's ``source`` names the curves used.
    """
    law = Tabulated()
    try:
        select_curves(pair, law.candidates())
    except ValueError:
        if not run_fe:
            raise
    else:
        return law.build(pair, radius)
    dc, _ = jg_critical(pair.E_star, radius, pair.yield_strength, pair.nu)
    runs = runner(
        pair.flat,
        pair.body,
        radius=radius,
        delta_max=[m * dc for m in maxima_over_delta_c],
        **indent_kwargs,
    )
    name = _slug(f"fe-{pair.body.name}-on-{pair.flat.name}")
    source = (
        f"FE runs of impactlab.fe.indent: {pair.body.name} sphere on {pair.flat.name}, "
        f"R = {radius:g} m, maxima {', '.join(f'{m:g}' for m in maxima_over_delta_c)} delta_c"
    )
    curves = curves_from_runs(runs, pair, radius, name, source)
    folder = curves_cache_dir()
    folder.mkdir(parents=True, exist_ok=True)
    text = json.dumps(curves_file_record([curves]), indent=1)
    tmp = folder / f".{name}.json.{os.getpid()}.tmp"  # whole, then renamed over a damaged one
    tmp.write_text(text)
    os.replace(tmp, folder / f"{name}.json")
    return Tabulated(curves).build(pair, radius)


__all__ = [
    "HARDENED_PAPER_CASE",
    "RUN_MAXIMA_OVER_DELTA_C",
    "curves_from_runs",
    "hardened_curves",
    "hardened_law",
    "shipped_curves_record",
    "shipped_fe_curves",
    "tabulated_law",
    "write_shipped_curves",
]
