"""One-command reproduction of the seed paper (doi:10.1007/s00419-015-1108-2).

:func:`reproduce` regenerates, from the package alone, the comparison of Tables 2 and 3 (and our
own Table 4 for 70 deg) with impactlab's numbers, Figs. 4 and 5, force-time and force-penetration
plots, the sensitivity of the experimental T to the rod's inertia, the self-consistency checks of
the published rows, and a report (Markdown and HTML) that explains every published number
impactlab does not reproduce. It writes only into the folder it is given (see
:func:`prepare_output`); a file of the reproduction (:data:`FILES`) that this run does not
write is removed, with a :class:`ReproductionWarning` naming it, so the folder holds one run
whatever became of the earlier one (killed, or its marker damaged). The physics is never
adjusted to a published number.

The parts: :mod:`~impactlab.paper.analytic_rows` (experimental rows, inertia, consistency),
:mod:`~impactlab.paper.simulations`, :mod:`~impactlab.paper.comparison` (with
:mod:`~impactlab.paper.reasons`), :mod:`~impactlab.paper.figures`,
:mod:`~impactlab.paper.report_sections` and :mod:`~impactlab.paper.reproduction_folder` (the
folder's marker and stale files).
"""

from __future__ import annotations

import html
import json
import os
import time
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import Any

import pandas as pd

from impactlab._files import write_text_atomic
from impactlab._version import __version__
from impactlab.experiment.checks import check_path
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import (
    experimental_rows,
    inertia_sensitivity,
    length_readings,
    published_consistency,
)
from impactlab.paper.comparison import comparison_table, side_by_side
from impactlab.paper.fe_reference_rows import FE_LAW, fe_reference_table, run_fe_reference
from impactlab.paper.fe_reference_rows import FRICTION as FE_FRICTION
from impactlab.paper.figures import figure_alpha, figure_dent, figure_forces, figure_inertia
from impactlab.paper.physics import physics_table, run_physics
from impactlab.paper.physics_figures import figure_drop
from impactlab.paper.quantities import (
    Simulations,
    comparison_counts,
    count_extrapolated,
    verdict_counts,
)
from impactlab.paper.report import to_html, to_markdown
from impactlab.paper.report_sections import TITLE, ReportData, build_report
from impactlab.paper.reproduction_folder import (
    FILES,
    MARKER,
    TABLE_NAMES,
    ReproductionWarning,
    _marker_files,
    _marker_status,
    _partials,
    _remove_stale,
    _unlink_links,
    _write_marker,
    prepare_output,
)
from impactlab.paper.simulations import eq12_check, run_simulations, simulation_table

__all__ = [
    "FILES",
    "INPUTS_FILE",
    "MARKER",
    "ReproductionResult",
    "ReproductionWarning",
    "prepare_output",
    "reproduce",
    "simulation_records",
]

#: The file of every simulation's input (``simulation_records``), in the reproduction's folder.
INPUTS_FILE = "simulation_inputs.json"


@dataclass(frozen=True, repr=False)
class ReproductionResult:
    """What :func:`reproduce` produced. DataFrames in display units (um, ms, N) as their column
    names say; ``files`` maps a short name to the path written. Its ``repr`` and notebook
    summary give the folder, the report and the headline counts, not the tables."""

    out_dir: Path
    experimental: pd.DataFrame
    comparison: pd.DataFrame
    tables: Mapping[str, pd.DataFrame]
    consistency: pd.DataFrame
    inertia: pd.DataFrame
    eq12_check: pd.DataFrame
    simulations: pd.DataFrame
    files: Mapping[str, Path]
    report_md: Path
    report_html: Path
    elapsed_s: float
    extras: Mapping[str, Any] = field(default_factory=dict)

    def _summary(self) -> list[tuple[str, str]]:
        """``(label, text)`` of the headline: the published numbers reproduced, undecided and
        not reproduced (and not compared), the simulated impacts beyond their law's range."""
        bad, skipped = comparison_counts(self.comparison)
        good, undecided = verdict_counts(self.comparison)
        numbers = f"{good} reproduced, {undecided} undecided, {bad} not reproduced"
        rows = [("published numbers", numbers + (f", {skipped} not compared" if skipped else ""))]
        if self.extras.get("simulated", True):
            n, m = count_extrapolated(self.simulations)
            rows.append(("simulated impacts", f"{n} of {m} beyond their law's verified range"))
        else:
            rows.append(("simulated impacts", "none (simulations not run)"))
        return [*rows, ("files", str(len(self.files))), ("time", f"{self.elapsed_s:.3g} s")]

    def __repr__(self) -> str:
        rows = "; ".join(f"{k}: {v}" for k, v in self._summary())
        return f"ReproductionResult({self.out_dir}: {self.report_html.name}; {rows})"

    def _repr_html_(self) -> str:
        e, rep = html.escape, self.report_html
        href = rep.as_uri() if rep.is_absolute() else rep.as_posix()  # relative: as given
        link = f"<a href='{e(href)}'>{e(rep.name)}</a>"
        rows = [("folder", e(str(self.out_dir))), ("report", link)]
        rows += [(e(k), e(v)) for k, v in self._summary()]
        body = "".join(f"<tr><th>{k}</th><td>{v}</td></tr>" for k, v in rows)
        return f"<div><strong>ReproductionResult</strong><table>{body}</table></div>"


def reproduce(
    out_dir: str | os.PathLike[str] = "reproduction",
    *,
    simulate: bool = True,
) -> ReproductionResult:
    """Regenerate the paper's comparison into ``out_dir`` (created if needed; a non-empty folder
    must come from a previous reproduction). ``simulate=False`` skips the engine (analytic part
    only). Returns a :class:`ReproductionResult`; writes report.md, report.html, CSV tables and
    PNG figures, nothing outside ``out_dir``. The files of an earlier run that this one does not
    write (the simulations' after a run with them) are removed, each with a
    :class:`ReproductionWarning` (``extras["removed"]``: their names), and so is any file of
    :data:`FILES` this run does not write when the earlier run did not complete (killed, or its
    marker damaged); a link named as one of :data:`FILES` is replaced by this run's file."""
    if not isinstance(simulate, bool):
        raise TypeError(f"simulate must be True or False, got {simulate!r}")
    check_path(out_dir, "out_dir")  # one line naming out_dir (None, a number, "")
    t0 = time.perf_counter()
    earlier = _marker_status(Path(out_dir).expanduser())  # before this run is marked running
    out = prepare_output(out_dir)
    previous = _marker_files(out)
    _unlink_links(out)
    written: dict[str, Path] = {}
    try:
        res = _reproduce(out, simulate, written, t0)
    except BaseException:  # the marker still lists every file of ours in the folder
        _write_marker(out, "failed", previous | {p.name for p in written.values()})
        raise
    ours = {p.name for p in written.values()}
    unfinished = set() if earlier == "complete" else FILES  # a killed run's, or no marker
    removed, kept = _remove_stale(out, (previous | unfinished | _partials(out)) - ours)
    _write_marker(out, "complete", ours | kept, time.perf_counter() - t0)
    return replace(res, extras=MappingProxyType({**res.extras, "removed": tuple(removed)}))


def _reproduce(
    out: Path, simulate: bool, written: dict[str, Path], t0: float
) -> ReproductionResult:
    """The reproduction into the prepared folder ``out``; every file written is recorded in
    ``written`` as soon as it is."""
    experimental = experimental_rows()
    consistency = published_consistency()
    inertia = inertia_sensitivity()
    readings = length_readings()
    sims = run_simulations() if simulate else None
    comparison = comparison_table(sims, experimental, consistency)
    tables = {ang: side_by_side(comparison, ang) for ang in D.ANGLES_DEG}
    simtab = simulation_table(sims) if sims else None
    eq12 = eq12_check(sims) if sims else None
    fe_runs = run_fe_reference() if sims else None
    fe_ref = fe_reference_table(sims, fe_runs) if sims and fe_runs else None
    physics = run_physics() if simulate else None
    records = simulation_records(sims, fe_runs, physics) if sims else None
    phystab = physics_table(physics, experimental) if physics else None

    _write_tables(
        out,
        {
            "experimental_rows": experimental,
            "comparison": comparison,
            **{name: tables[ang] for ang, name in TABLE_NAMES.items()},
            "published_consistency": consistency,
            "inertia_sensitivity": inertia,
            "simulations": simtab,
            "eq12_check": eq12,
            "fe_reference": fe_ref,
            "physics_comparison": phystab,
        },
        written,
    )
    figs = _write_figures(out, inertia, sims, written)
    if records:
        written["simulation_inputs"] = _write_inputs(out / INPUTS_FILE, records)
    if physics:
        p = figure_drop(out / "physics_drop_20deg.png", physics[("flexible rod", 20)])
        written["physics_drop_20"] = p
        figs["physics_drop_20"] = p.name

    md, html_path = _write_report(
        out,
        ReportData(
            experimental=experimental,
            comparison=comparison,
            consistency=consistency,
            inertia=inertia,
            simulations=simtab,
            eq12=eq12,
            figures=figs,
            tables=tables,
            elapsed=time.perf_counter() - t0,
            version=__version__,
            physics=phystab,
            inputs_file=INPUTS_FILE if records else None,
            inputs={kind: tuple(r) for kind, r in records.items()} if records else None,
            fe_reference=fe_ref,
            readings=readings,
        ),
        written,
    )
    return ReproductionResult(
        out_dir=out,
        experimental=experimental,
        comparison=comparison,
        tables=MappingProxyType({TABLE_NAMES[a]: t for a, t in tables.items()}),
        consistency=consistency,
        inertia=inertia,
        eq12_check=eq12 if eq12 is not None else pd.DataFrame(),
        simulations=simtab if simtab is not None else pd.DataFrame(),
        files=MappingProxyType(written),
        report_md=md,
        report_html=html_path,
        elapsed_s=time.perf_counter() - t0,
        extras=MappingProxyType(
            {"simulated": sims is not None, "physics": phystab, "length_readings": readings}
        ),
    )


def _write_report(out: Path, data: ReportData, written: dict[str, Path]) -> tuple[Path, Path]:
    """report.md and report.html (recorded in ``written``)."""
    blocks = build_report(data)
    md = out / "report.md"
    write_text_atomic(md, to_markdown(blocks, TITLE))
    written["report_md"] = md
    html_path = out / "report.html"
    # one self-contained page: the figures (already written into ``out``) embedded
    write_text_atomic(html_path, to_html(blocks, TITLE, base=out))
    written["report_html"] = html_path
    return md, html_path


def simulation_records(
    sims: Simulations,
    fe: Mapping[int, Any] | None = None,
    physics: Mapping[tuple[str, int], Any] | None = None,
) -> dict[str, dict[str, Any]]:
    """Every simulation behind the report, by kind, each ``{key: result.input}`` (what it
    simulated: body, materials, law and its parameters, friction, tolerances, impactlab
    version; ``impactlab.rerun`` runs one again): ``"simulations"``, the (angle, law, friction)
    impacts of Sections 4, 5 and 7 keyed ``"20 deg, ghaednia, coulomb"``; ``"fe_reference"``,
    the FE law's impacts (``fe``, by angle [deg]) keyed ``"20 deg, tabulated, coulomb"``;
    ``"physics"``, the drops of "Can physics explain the experiment?" (``physics``, keyed
    (configuration, angle)) keyed ``"20 deg, flexible rod"``."""
    return {
        "simulations": {f"{a} deg, {law}, {fr}": r.input for (a, law, fr), r in sims.items()},
        "fe_reference": {
            f"{a} deg, {FE_LAW}, {FE_FRICTION}": r.input for a, r in (fe or {}).items()
        },
        "physics": {f"{a} deg, {name}": r.input for (name, a), r in (physics or {}).items()},
    }


def _write_inputs(path: Path, records: Mapping[str, Mapping[str, Any]]) -> Path:
    """The records of :func:`simulation_records`, one JSON object keyed by each record's key
    (the keys of the kinds do not collide)."""
    flat = {key: rec for kind in records.values() for key, rec in kind.items()}
    if len(flat) != sum(len(kind) for kind in records.values()):
        raise ValueError("simulation records: two simulations share a key")
    write_text_atomic(path, json.dumps(flat, indent=1) + "\n")
    return path


def _write_tables(
    out: Path, tables: Mapping[str, pd.DataFrame | None], written: dict[str, Path]
) -> None:
    """Each table (None: skipped) as ``out/<name>.csv``, recorded in ``written`` (name ->
    path)."""
    for name, df in tables.items():
        if df is None:
            continue
        p = out / f"{name}.csv"
        write_text_atomic(p, df.to_csv(index=False))
        written[name] = p


def _write_figures(
    out: Path, inertia: pd.DataFrame, sims: Simulations | None, written: dict[str, Path]
) -> dict[str, str]:
    """The figures into ``out`` (recorded in ``written``); returns figure key -> file name."""
    figs: dict[str, str] = {}
    written["fig5_alpha"] = figure_alpha(out / "fig5_alpha.png")
    figs["alpha"] = "fig5_alpha.png"
    written["inertia_plot"] = figure_inertia(out / "inertia_sensitivity.png", inertia)
    figs["inertia"] = "inertia_sensitivity.png"
    if sims:
        for ang in D.ANGLES_DEG:
            p = figure_forces(out / f"forces_{ang}deg.png", sims, ang)
            written[f"forces_{ang}"] = p
            figs[f"forces_{ang}"] = p.name
        g20 = sims.get((20, "ghaednia", "impulse_ratio"))
        if g20 is not None:
            written["fig4_dent"] = figure_dent(out / "fig4_dent.png", g20)
            figs["dent"] = "fig4_dent.png"
    return figs
