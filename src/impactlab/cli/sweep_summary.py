"""The summaries of ``impactlab sweep run``, ``impactlab sweep info`` and ``impactlab sweep
uncertainty``: the table's texts ("0 case(s) not ok; advisory (the result stays ok): law
extrapolated: 63; 63 flagged in all", "1 of 1") and the JSON's integer counts
(docs/json-schema.md: ``"flagged": {"total": 63, "not_ok": 0, "law_extrapolated": 63}``,
``"chunks_done": 1, "chunks_total": 1``), the uncertainty reports in display units."""

from __future__ import annotations

import json
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from impactlab._display import field_row, format_number
from impactlab._json import quantity as quantity_json
from impactlab._json import to_json
from impactlab.cli._common import print_rows
from impactlab.cli.printing import KEEP, print_wrapped, versioned
from impactlab.flags import invalidating_names

if TYPE_CHECKING:
    from impactlab.sweep import SweepResult


def flagged_json(counts: Mapping[str, int]) -> dict[str, int]:
    """``impactlab.sweep.flag_counts``' counts as JSON (``impactlab.sweep.summary.
    flagged_values``): ``total``, ``not_ok``, then each flag that marks a case, by its
    ``ResultFlag`` name in lower case (``law_extrapolated``, ``beyond_tip``)."""
    from impactlab.sweep.summary import flagged_values

    return flagged_values(counts)


def info_table(info: Mapping[str, Any]) -> dict[str, Any]:
    """The table rows of ``impactlab.sweep.store_info``'s values (``impactlab sweep info``):
    ``chunks_done`` as "7 of 8", ``flagged`` as ``sweep.summary.flagged_text``, one row per
    ``body_yields_first`` pair (``sweep.summary.flattening_rows``), one row per law of
    ``law_ranges``, ``law range: NAME`` -> its range (the sources are long: ``--json`` and the
    store's attributes hold them; a ``law ranges`` row says when the store records none); no
    ``impactlab_version``."""
    from impactlab.sweep.summary import flagged_text, flattening_rows

    rows: dict[str, Any] = {}
    for key, value in info.items():
        if key == "chunks_done":
            rows[key] = f"{value} of {info.get('chunks_total')}"
        elif key == "flagged" and isinstance(value, Mapping):
            rows[key] = flagged_text(value)
        elif key == "body_yields_first":
            rows |= flattening_rows(value)
        elif key == "law_ranges":
            rows |= _law_rows(value)
        elif key not in ("chunks_total", "impactlab_version"):
            rows[key] = value
    return rows


def _law_rows(ranges: Any) -> dict[str, Any]:
    """``law range: NAME`` -> its range, per law of a store's ``law_ranges``."""
    if not isinstance(ranges, Mapping) or not ranges:
        return {"law ranges": "not recorded in this store"}
    return {
        f"law range: {law}": rec.get("range", rec) if isinstance(rec, Mapping) else rec
        for law, rec in ranges.items()
    }


def run_summary(
    res: SweepResult, ds: Any, netcdf: Path | None, files: list[str], *, as_json: bool
) -> dict[str, Any]:
    """The summary of a finished ``sweep run``: the store, the counts of cases and chunks, the
    cases this run computed, its wall time [s], its throughput (``display.run_throughput``: the
    cases computed over the wall time, the engine's load included; [1/s] with ``as_json``, None
    when the run computed nothing; for the table a text that says so), the first task [s] (the
    engine's load; None when the run computed nothing: every chunk was stored), the status
    counts, the flagged cases (text for the table, integer counts with ``as_json``) and, when a
    material pair's body yields first, those pairs (``sweep.summary.body_yields_first_pairs``:
    ``body_yields_first`` with ``as_json``, one row each for the table)."""
    from impactlab.sweep import status_counts
    from impactlab.sweep.display import run_throughput, throughput_text, warm_up_s
    from impactlab.sweep.summary import (
        body_yields_first_pairs,
        dataset_flag_counts,
        flattening_rows,
        format_flag_counts,
    )

    s = res.stats
    summary: dict[str, Any] = {
        "store": str(res.path),
        "cases": s.n_cases,
        "chunks": s.n_chunks,
        "chunks_resumed": s.chunks_before,
        "chunks_computed": s.chunks_computed,
        "cases_computed": s.cases_computed,
        "wall_time": s.wall_s,
        "throughput": run_throughput(s) if as_json else throughput_text(s),
        "first_task": warm_up_s(s) if s.chunks_computed else None,  # None: nothing computed
        "backend": s.backend,
        "status": status_counts(ds),
    }
    if "flags" in ds.data_vars:
        counts = dataset_flag_counts(ds)
        summary["flagged"] = flagged_json(counts) if as_json else format_flag_counts(counts)
    pairs = body_yields_first_pairs(ds)
    if pairs:
        summary |= {"body_yields_first": pairs} if as_json else flattening_rows(pairs)
    if netcdf is not None:
        summary["netcdf"] = str(netcdf)
    if files:
        summary["plots"] = files
    return summary


def warn_incomplete(store: Path) -> None:
    """A warning on stderr when the store at ``store`` has chunks still to compute (what is
    exported or reported of it covers the finished chunks only; the others read status -1)."""
    from impactlab.sweep.summary import incomplete_note

    note = incomplete_note(store)
    if note is not None:
        print_wrapped(f"warning: {note}")


def print_uncertainty(
    ds: Any,
    outputs: list[str] | None,
    percentiles: list[float] | None,
    as_json: bool,
    include_flagged: bool = False,
) -> None:
    """The uncertainty reports of the sweep ``ds`` (one per grid point), as tables or, with
    ``as_json``, one JSON object keyed by the points' titles (:func:`uncertainty_json`)."""
    from impactlab.sweep import uncertainty_reports

    reports = uncertainty_reports(ds, outputs, percentiles, include_flagged)
    if as_json:
        doc = {k: _uncertainty_json(r.to_dict()) for k, r in reports.items()}
        print(json.dumps(versioned(doc), indent=2))  # the version beside the points' titles
        return
    for title, rep in reports.items():
        _print_report(rep.to_dict(), f"uncertainty: {title}")


def uncertainty_json(ds: Any) -> dict[str, Any]:
    """The uncertainty reports of the sweep ``ds`` with the study's outputs and percentiles,
    as ``sweep uncertainty --json`` prints them: one object per grid point, keyed by its
    title (``sweep run --json`` holds it as ``uncertainty``)."""
    from impactlab.sweep import uncertainty_reports

    reports = uncertainty_reports(ds, None, None, False)
    return {k: _uncertainty_json(r.to_dict()) for k, r in reports.items()}


def _print_report(report: dict[str, Any], title: str) -> None:
    """One uncertainty report in display units: per output its mean ± standard deviation and
    its percentiles, the cases used whose law was extrapolated (when any), then the inputs
    ranked by their influence (squared rank correlation)."""
    from impactlab.sweep.uncertainty import extrapolated_note

    rows = []
    for rec in report["summary"]:
        out, unit = str(rec.get("output")), str(rec.get("unit") or "1")
        rows.append(field_row(out, rec.get("mean"), unit, rec.get("std")))
        for key, value in rec.items():
            if key.startswith("p") and isinstance(value, float):
                _n, text, shown = field_row(out, value, unit)
                rows.append((f"{out} {key}", text, shown))
    n = f"{report['n_cases']} cases, {report['n_invalid']} excluded (invalid: status > 0)"
    if report.get("n_not_computed"):
        n += f", {report['n_not_computed']} not computed (status -1)"
    flagged = int(report.get("n_flagged", 0))
    n += f", {flagged} flagged ({invalidating_names()}) " + (
        "included" if report.get("flagged_included") else "excluded"
    )
    print_rows(rows, f"{title}: {n}; mean ± standard deviation, percentiles")
    note = extrapolated_note(report)
    if note is not None:
        print_wrapped(note, sys.stdout)
    ranked: dict[str, list[str]] = {}
    for r in report["sensitivity"]:  # an input with its number: on one line on a terminal
        ranked.setdefault(str(r["output"]), []).append(
            f"{r['input']}{KEEP}{format_number(r['rank_corr2'], 3)}"
        )
    if ranked:
        print_wrapped(
            "sensitivity (squared Spearman rank correlation of each input with the output):",
            sys.stdout,
        )
        for out, items in ranked.items():
            print_wrapped(f"  {out}: {', '.join(items)}", sys.stdout)


def _uncertainty_json(report: dict[str, Any]) -> dict[str, Any]:
    """A report's JSON (docs/json-schema.md): per output, ``mean`` with the sample's standard
    deviation as its sigma and each percentile as a quantity; the sensitivities (dimensionless)
    as quantities of unit "1"."""
    summary = []
    for rec in report["summary"]:
        unit = str(rec.get("unit") or "1")
        row: dict[str, Any] = {"output": rec.get("output"), "n": rec.get("n")}
        row["mean"] = quantity_json(rec.get("mean"), unit, rec.get("std"))
        for key, value in rec.items():
            if key not in ("output", "n", "mean", "std", "unit"):
                row[key] = quantity_json(value, unit)
        summary.append(row)
    units = {"rank_corr2": "1", "src2": "1", "r2": "1"}
    return {**to_json(report, units), "summary": summary}
