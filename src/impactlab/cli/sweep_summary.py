"""The summaries of ``impactlab sweep run``, ``impactlab sweep info`` and ``impactlab sweep
uncertainty``: the table's texts ("0 case(s) not ok; advisory (the result stays ok): law
extrapolated: 63; 63 flagged in all", "1 of 1") and the JSON's integer counts
(docs/json-schema.md: ``"flagged": {"total": 63, "not_ok": 0, "law_extrapolated": 63}``,
``"chunks_done": 1, "chunks_total": 1``), the uncertainty reports in display units."""

from __future__ import annotations

import json
import re
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

from impactlab._display import field_row, format_number
from impactlab._json import quantity as quantity_json
from impactlab._json import to_json
from impactlab.cli._common import print_rows
from impactlab.cli.printing import versioned
from impactlab.flags import invalidating_names

if TYPE_CHECKING:
    from impactlab.sweep import SweepResult

#: ``impactlab.sweep.summary.format_flag_counts``' text: the cases not ok and their flags
#: ("name: count, ..."), then the advisory flags and the cases with any flag.
_NOT_OK_TEXT = re.compile(
    r"(?P<bad>[\d,]+) case\(s\) not ok(?: \((?P<parts>[^()]*)\))?"
    r"(?:; advisory \(the result stays ok\): (?P<advisory>[^;]*); "
    r"(?P<total>[\d,]+) flagged in all)?"
)
#: Its older form (counts without "not ok"): the total, then "name: count, ...".
_FLAGGED_TEXT = re.compile(r"(?P<total>[\d,]+) case\(s\) \((?P<parts>.*)\)")
#: ``impactlab.sweep.summary.store_info``'s progress text: "<done> of <total>".
_CHUNKS_TEXT = re.compile(r"(?P<done>\d+) of (?P<total>\d+)")


def flagged_json(counts: Mapping[str, int]) -> dict[str, int]:
    """``impactlab.sweep.flag_counts``' counts as JSON: ``total`` (cases with any flag, the
    advisory law extrapolated included), ``not_ok`` (cases with a flag that is not advisory:
    not plain success), then each flag that marks a case, by its ``ResultFlag`` name in lower
    case (``law_extrapolated``, ``beyond_tip``)."""
    from impactlab.sweep.summary import FLAG_NAMES, TOTALS

    total = int(counts.get("flagged", 0))
    out = {"total": total}
    if "not ok" in counts or not total:  # counts of an older form have no "not ok"
        out["not_ok"] = int(counts.get("not ok", 0))
    out |= {
        FLAG_NAMES.get(k, k.replace(" ", "_")): int(v)
        for k, v in counts.items()
        if k not in TOTALS and v
    }
    return out


def _number(text: str) -> int:
    return int(text.replace(",", ""))


def flagged_text_json(text: Any) -> Any:
    """The counts of ``format_flag_counts``' text ("none", "2 case(s) not ok (energy gain: 2);
    advisory (the result stays ok): law extrapolated: 7; 7 flagged in all", or the older
    "63 case(s) (law extrapolated (advisory): 63)") as :func:`flagged_json` gives them; a text
    of another shape as it is."""
    if text == "none":
        return flagged_json({"flagged": 0})
    new = _NOT_OK_TEXT.fullmatch(str(text))
    old = None if new is not None else _FLAGGED_TEXT.fullmatch(str(text))
    if new is not None:
        bad = _number(new["bad"])
        counts = {"flagged": _number(new["total"]) if new["total"] else bad, "not ok": bad}
        parts = [p for g in ("parts", "advisory") if new[g] for p in new[g].split(", ")]
    elif old is not None:
        counts, parts = {"flagged": _number(old["total"])}, old["parts"].split(", ")
    else:
        return text
    for part in parts:
        name, _, count = part.rpartition(": ")
        if not name or not count.replace(",", "").isdigit():
            return text
        counts[name.removesuffix(" (advisory)")] = _number(count)
    return flagged_json(counts)


def info_json(info: Mapping[str, Any]) -> dict[str, Any]:
    """``impactlab.sweep.store_info``'s summary with integer counts: ``chunks_done`` and
    ``chunks_total`` instead of "1 of 1", ``flagged`` as :func:`flagged_json`."""
    out: dict[str, Any] = {}
    for key, value in info.items():
        match = _CHUNKS_TEXT.fullmatch(str(value)) if key == "chunks_done" else None
        if match is not None:
            out["chunks_done"] = int(match["done"])
            out["chunks_total"] = int(match["total"])
        elif key == "flagged":
            out[key] = flagged_text_json(value)
        else:
            out[key] = value
    return out


def with_law_ranges(info: Mapping[str, Any], store: Path, *, as_json: bool) -> dict[str, Any]:
    """``info`` with the store's ``law_ranges`` attribute (each law of the study -> its verified
    or stand-in ``range`` and its ``source``): with ``as_json`` as the store records it (null
    for a store that records none); for the table one row per law, ``law range: NAME`` -> its
    range (the sources are long: ``--json`` and the store's attributes hold them), and its
    ``body_yields_first`` pairs one row each (``sweep.summary.flattening_rows``)."""
    from impactlab.sweep.store import SweepStore
    from impactlab.sweep.summary import flattening_rows

    ranges = SweepStore(store).attrs().get("law_ranges")
    if as_json:
        return {**info, "law_ranges": ranges}
    if "body_yields_first" in info:  # the table: one row per pair
        info = {k: v for k, v in info.items() if k != "body_yields_first"} | flattening_rows(
            info["body_yields_first"]
        )
    if not isinstance(ranges, Mapping) or not ranges:
        return {**info, "law ranges": "not recorded in this store"}
    rows = {
        f"law range: {law}": rec.get("range", rec) if isinstance(rec, Mapping) else rec
        for law, rec in ranges.items()
    }
    return {**info, **rows}


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
        print(f"warning: {note}", file=sys.stderr)


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
        print(note)
    ranked: dict[str, list[str]] = {}
    for r in report["sensitivity"]:
        ranked.setdefault(str(r["output"]), []).append(
            f"{r['input']} {format_number(r['rank_corr2'], 3)}"
        )
    if ranked:
        print("sensitivity (squared Spearman rank correlation of each input with the output):")
        for out, items in ranked.items():
            print(f"  {out}: {', '.join(items)}")


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
