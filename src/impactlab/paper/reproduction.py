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
:mod:`~impactlab.paper.reasons`), :mod:`~impactlab.paper.figures` and
:mod:`~impactlab.paper.report_sections`.
"""

from __future__ import annotations

import json
import os
import re
import time
import warnings
from collections.abc import Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from types import MappingProxyType
from typing import Any

import pandas as pd

from impactlab._files import write_text_atomic
from impactlab._version import __version__
from impactlab.experiment.checks import check_path, output_folder
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import (
    experimental_rows,
    inertia_sensitivity,
    length_readings,
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

#: Marker file that identifies a folder written by :func:`reproduce`; it lists the files of the
#: reproduction in the folder (``"files"``), which the next run reads to remove the stale ones.
MARKER = ".impactlab-reproduction.json"

_TABLE_NAMES = {20: "table2", 45: "table3", 70: "table4"}

#: Every file a reproduction can write (besides :data:`MARKER`): one of these that a run does
#: not write is an earlier run's, whatever the marker says, and is removed.
FILES = frozenset(
    {
        "report.md",
        "report.html",
        *(f"{name}.csv" for name in _TABLE_NAMES.values()),
        "comparison.csv",
        "experimental_rows.csv",
        "published_consistency.csv",
        "simulations.csv",
        "simulation_inputs.json",
        "eq12_check.csv",
        "fe_reference.csv",
        "inertia_sensitivity.csv",
        "inertia_sensitivity.png",
        "fig5_alpha.png",
        "fig4_dent.png",
        *(f"forces_{ang}deg.png" for ang in D.ANGLES_DEG),
        "physics_comparison.csv",
        "physics_drop_20deg.png",
    }
)

# the temporary file of a write cut short (impactlab._files: ".<name>.<pid>.partial")
_PARTIAL = re.compile(r"\.(?P<name>.+)\.\d+\.partial")


class ReproductionWarning(UserWarning):
    """A file an earlier reproduction left in the folder was removed (or could not be)."""


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


def prepare_output(out_dir: str | os.PathLike[str], name: str = "out_dir") -> Path:
    """Create ``out_dir`` or accept it if it is empty or holds a previous reproduction (marker
    file). Refuses (ValueError naming ``name``, the folder as the user gave it: the command
    line's ``--out``) a non-empty folder without the marker and a path that is a file. Nothing
    outside ``out_dir`` is touched; inside it only the reproduction's own files are (re)written,
    and the marker keeps the earlier run's list of files until this run completes."""
    out = check_path(out_dir, name).expanduser()
    if out.is_dir():
        entries = list(out.iterdir())
        if entries and not (out / MARKER).is_file():
            raise ValueError(
                f"{name} {str(out)!r} is not empty and was not written by 'impactlab "
                f"reproduce' (no {MARKER}); refusing to write there: choose a new or empty folder"
            )
    out = output_folder(out, name)  # refuses a file, or a file among its parents
    _write_marker(out, "running", _marker_files(out))
    return out


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
    fe_ref = fe_reference_table(sims, run_fe_reference()) if sims else None
    physics = run_physics() if simulate else None
    phystab = physics_table(physics, experimental) if physics else None

    _write_tables(
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
        written,
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
            readings=readings,
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


def _marker_status(out: Path) -> str | None:
    """The status the marker in ``out`` records (None without a readable one): after a
    ``complete`` run only the files its marker lists are the reproduction's; after one killed
    (``running``), failed or with no readable marker, every name of :data:`FILES` is."""
    try:
        status = json.loads((out / MARKER).read_text()).get("status")
    except (OSError, ValueError, AttributeError):
        return None
    return status if isinstance(status, str) else None


def _unlink_links(out: Path) -> None:
    """Remove the symbolic links in ``out`` named as a file of the reproduction, so that its
    files are written in ``out`` and never through a link to a file elsewhere (the file a link
    names is left as it is)."""
    for name in sorted(FILES):
        path = out / name
        if path.is_symlink():
            path.unlink()
            warnings.warn(
                f"{str(path)!r} was a link; this run writes its own file there (the file it "
                "named is left as it was)",
                ReproductionWarning,
                stacklevel=3,
            )


def _marker_files(out: Path) -> set[str]:
    """The files the marker in ``out`` lists (none without a readable one) that a reproduction
    can write: names of :data:`FILES` (or the temporary file of a write of one cut short). Any
    other name the marker lists (a file of the user's, a path elsewhere) is ignored, so it is
    never removed whatever the marker says."""
    try:
        listed = json.loads((out / MARKER).read_text()).get("files", [])
    except (OSError, ValueError, AttributeError):
        return set()
    if not isinstance(listed, list):
        return set()
    return {f for f in listed if isinstance(f, str) and _is_ours(f)}


def _is_ours(name: str) -> bool:
    """Whether ``name`` is a file a reproduction can write: one of :data:`FILES`, or the
    temporary file of a write of one of them (or of :data:`MARKER`) cut short."""
    if name in FILES:
        return True
    m = _PARTIAL.fullmatch(name)
    return m is not None and m.group("name") in FILES | {MARKER}


def _write_marker(out: Path, status: str, files: set[str], elapsed: float | None = None) -> None:
    """The marker: the tool, the run's ``status``, the version and the reproduction's files."""
    record: dict[str, Any] = {
        "tool": "impactlab reproduce",
        "status": status,
        "version": __version__,
        "files": sorted(files),
    }
    if elapsed is not None:
        record["elapsed_s"] = elapsed
    write_text_atomic(out / MARKER, json.dumps(record, indent=2))


def _partials(out: Path) -> set[str]:
    """The temporary files in ``out`` of a write of one of :data:`FILES` cut short."""
    return {p.name for p in out.iterdir() if p.name not in FILES and _is_ours(p.name)}


def _remove_stale(out: Path, stale: set[str]) -> tuple[list[str], set[str]]:
    """Remove the files ``stale`` (an earlier run's, not written by this one) from ``out``, one
    ReproductionWarning each; returns the names removed and those that could not be."""
    removed: list[str] = []
    kept: set[str] = set()
    for name in sorted(n for n in stale if _is_ours(n)):  # never a file the user made
        path = out / name
        if not path.is_file() or path.is_symlink():
            continue  # gone already, or not a file of ours
        try:
            path.unlink()
        except OSError as exc:
            kept.add(name)
            warnings.warn(
                f"{str(path)!r} is left from an earlier run and could not be removed "
                f"({exc.strerror or exc}): it does not show this run",
                ReproductionWarning,
                stacklevel=3,
            )
        else:
            removed.append(name)
            warnings.warn(
                f"removed {str(path)!r}, left by an earlier run (this run does not write it)",
                ReproductionWarning,
                stacklevel=3,
            )
    return removed, kept


def _write_inputs(path: Path, sims: Simulations) -> Path:
    """What each simulation simulated (``ImpactResult.input``: bodies, materials, law, friction,
    tolerances, impactlab version), keyed ``"20 deg, ghaednia, coulomb"``."""
    records = {f"{ang} deg, {law}, {fr}": r.input for (ang, law, fr), r in sims.items()}
    write_text_atomic(path, json.dumps(records, indent=1) + "\n")
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
