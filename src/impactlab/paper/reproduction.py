"""One-command reproduction of the seed paper (doi:10.1007/s00419-015-1108-2).

:func:`reproduce` regenerates, from the package alone, the comparison of Tables 2 and 3 (and our
own Table 4 for 70 deg) with impactlab's numbers, Figs. 4 and 5, force-time and force-penetration
plots, the sensitivity of the experimental T to the rod's inertia, the self-consistency checks of
the published rows, and a report (Markdown and HTML) that explains every published number
impactlab does not reproduce. It writes only into the folder it is given (see
:func:`prepare_output`). The physics is never adjusted to a published number.

The parts: :mod:`~impactlab.paper.analytic_rows` (experimental rows, inertia, consistency),
:mod:`~impactlab.paper.simulations`, :mod:`~impactlab.paper.comparison` (with
:mod:`~impactlab.paper.reasons`), :mod:`~impactlab.paper.figures` and
:mod:`~impactlab.paper.report_sections`.
"""

from __future__ import annotations

import json
import os
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

import pandas as pd

from impactlab._version import __version__
from impactlab.experiment.checks import check_path, output_folder
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import (
    experimental_rows,
    inertia_sensitivity,
    published_consistency,
)
from impactlab.paper.comparison import comparison_table, side_by_side
from impactlab.paper.fe_reference_rows import fe_reference_table, run_fe_reference
from impactlab.paper.figures import figure_alpha, figure_dent, figure_forces, figure_inertia
from impactlab.paper.physics import physics_table, run_physics
from impactlab.paper.physics_figures import figure_drop
from impactlab.paper.quantities import Simulations
from impactlab.paper.report import to_html, to_markdown
from impactlab.paper.report_sections import TITLE, ReportData, build_report
from impactlab.paper.simulations import eq12_check, run_simulations, simulation_table

#: Marker file that identifies a folder written by :func:`reproduce`.
MARKER = ".impactlab-reproduction.json"

_TABLE_NAMES = {20: "table2", 45: "table3", 70: "table4"}


@dataclass(frozen=True)
class ReproductionResult:
    """What :func:`reproduce` produced. DataFrames in display units (um, ms, N) as their column
    names say; ``files`` maps a short name to the path written."""

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


def prepare_output(out_dir: str | os.PathLike[str]) -> Path:
    """Create ``out_dir`` or accept it if it is empty or holds a previous reproduction (marker
    file). Refuses (ValueError) a non-empty folder without the marker and a path that is a file.
    Nothing outside ``out_dir`` is touched; inside it only the reproduction's own files are
    (re)written."""
    out = check_path(out_dir, "out_dir").expanduser()
    if out.is_dir():
        entries = list(out.iterdir())
        if entries and not (out / MARKER).is_file():
            raise ValueError(
                f"out_dir {str(out)!r} is not empty and was not written by 'impactlab "
                f"reproduce' (no {MARKER}); refusing to write there: choose a new or empty folder"
            )
    out = output_folder(out, "out_dir")  # refuses a file, or a file among its parents
    (out / MARKER).write_text(json.dumps({"tool": "impactlab reproduce", "status": "running"}))
    return out


def reproduce(
    out_dir: str | os.PathLike[str] = "reproduction",
    *,
    simulate: bool = True,
) -> ReproductionResult:
    """Regenerate the paper's comparison into ``out_dir`` (created if needed; a non-empty folder
    must come from a previous reproduction). ``simulate=False`` skips the engine (analytic part
    only). Returns a :class:`ReproductionResult`; writes report.md, report.html, CSV tables and
    PNG figures, nothing outside ``out_dir``."""
    t0 = time.perf_counter()
    out = prepare_output(out_dir)
    experimental = experimental_rows()
    consistency = published_consistency()
    inertia = inertia_sensitivity()
    sims = run_simulations() if simulate else None
    comparison = comparison_table(sims, experimental, consistency)
    tables = {ang: side_by_side(comparison, ang) for ang in D.ANGLES_DEG}
    simtab = simulation_table(sims) if sims else None
    eq12 = eq12_check(sims) if sims else None
    fe_ref = fe_reference_table(sims, run_fe_reference()) if sims else None
    physics = run_physics() if simulate else None
    phystab = physics_table(physics, experimental) if physics else None

    written = _write_tables(
        out,
        {
            "experimental_rows": experimental,
            "comparison": comparison,
            **{name: tables[ang] for ang, name in _TABLE_NAMES.items()},
            "published_consistency": consistency,
            "inertia_sensitivity": inertia,
            "simulations": simtab,
            "eq12_check": eq12,
            "fe_reference": fe_ref,
            "physics_comparison": phystab,
        },
    )
    figs = _write_figures(out, inertia, sims, written)
    if sims:
        written["simulation_inputs"] = _write_inputs(out / "simulation_inputs.json", sims)
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
            inputs_file="simulation_inputs.json" if sims else None,
            fe_reference=fe_ref,
        ),
        written,
    )
    return ReproductionResult(
        out_dir=out,
        experimental=experimental,
        comparison=comparison,
        tables=MappingProxyType({_TABLE_NAMES[a]: t for a, t in tables.items()}),
        consistency=consistency,
        inertia=inertia,
        eq12_check=eq12 if eq12 is not None else pd.DataFrame(),
        simulations=simtab if simtab is not None else pd.DataFrame(),
        files=MappingProxyType(written),
        report_md=md,
        report_html=html_path,
        elapsed_s=time.perf_counter() - t0,
        extras=MappingProxyType({"simulated": sims is not None, "physics": phystab}),
    )


def _write_report(out: Path, data: ReportData, written: dict[str, Path]) -> tuple[Path, Path]:
    """report.md and report.html (recorded in ``written``), then the completed marker file."""
    blocks = build_report(data)
    md = out / "report.md"
    md.write_text(to_markdown(blocks, TITLE), encoding="utf-8")
    html_path = out / "report.html"
    # one self-contained page: the figures (already written into ``out``) embedded
    html_path.write_text(to_html(blocks, TITLE, base=out), encoding="utf-8")
    written["report_md"], written["report_html"] = md, html_path
    (out / MARKER).write_text(
        json.dumps(
            {
                "tool": "impactlab reproduce",
                "status": "complete",
                "version": __version__,
                "files": sorted(p.name for p in written.values()),
                "elapsed_s": data.elapsed,
            },
            indent=2,
        )
    )
    return md, html_path


def _write_inputs(path: Path, sims: Simulations) -> Path:
    """What each simulation simulated (``ImpactResult.input``: bodies, materials, law, friction,
    tolerances, impactlab version), keyed ``"20 deg, ghaednia, coulomb"``."""
    records = {f"{ang} deg, {law}, {fr}": r.input for (ang, law, fr), r in sims.items()}
    path.write_text(json.dumps(records, indent=1) + "\n")
    return path


def _write_tables(out: Path, tables: Mapping[str, pd.DataFrame | None]) -> dict[str, Path]:
    """Each table (None: skipped) as ``out/<name>.csv``; returns name -> path."""
    written: dict[str, Path] = {}
    for name, df in tables.items():
        if df is None:
            continue
        p = out / f"{name}.csv"
        df.to_csv(p, index=False)
        written[name] = p
    return written


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
