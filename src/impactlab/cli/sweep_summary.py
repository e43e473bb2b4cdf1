"""The summaries of ``impactlab sweep run`` and ``impactlab sweep info``: the table's texts
("63 case(s) (law extrapolated: 63)", "1 of 1") and the JSON's integer counts
(docs/json-schema.md: ``"flagged": {"total": 63, "law_extrapolated": 63}``,
``"chunks_done": 1, "chunks_total": 1``)."""

from __future__ import annotations

import re
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:
    from impactlab.sweep import SweepResult

#: ``impactlab.sweep.summary.format_flag_counts``' text: the total, then "name: count, ...".
_FLAGGED_TEXT = re.compile(r"(?P<total>[\d,]+) case\(s\) \((?P<parts>.*)\)")
#: ``impactlab.sweep.summary.store_info``'s progress text: "<done> of <total>".
_CHUNKS_TEXT = re.compile(r"(?P<done>\d+) of (?P<total>\d+)")


def flagged_json(counts: Mapping[str, int]) -> dict[str, int]:
    """``impactlab.sweep.flag_counts``' counts as JSON: ``total`` (cases with any flag), then
    each flag that marks a case, by its ``ResultFlag`` name in lower case (``law_extrapolated``,
    ``beyond_tip``)."""
    from impactlab.sweep.summary import FLAG_NAMES

    out = {"total": int(counts.get("flagged", 0))}
    out |= {
        FLAG_NAMES.get(k, k.replace(" ", "_")): int(v)
        for k, v in counts.items()
        if k != "flagged" and v
    }
    return out


def flagged_text_json(text: Any) -> Any:
    """The counts of ``format_flag_counts``' text ("none", "63 case(s) (law extrapolated:
    63)") as :func:`flagged_json` gives them; a text of another shape as it is."""
    if text == "none":
        return {"total": 0}
    match = _FLAGGED_TEXT.fullmatch(str(text))
    if match is None:
        return text
    counts = {"flagged": int(match["total"].replace(",", ""))}
    for part in match["parts"].split(", "):
        name, _, count = part.rpartition(": ")
        if not name or not count.replace(",", "").isdigit():
            return text
        counts[name.removesuffix(" (advisory)")] = int(count.replace(",", ""))
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


def run_summary(
    res: SweepResult, ds: Any, netcdf: Path | None, files: list[str], *, as_json: bool
) -> dict[str, Any]:
    """The summary of a finished ``sweep run``: the store, the counts of cases and chunks, the
    wall time [s], the throughput [1/s] after each worker's first task (None when every chunk
    computed was a first task: a single-chunk run has no case after the engine's load to time),
    the first task [s] (None when the run computed nothing: every chunk was stored), the status
    counts and the flagged cases (text for the table, integer
    counts with ``as_json``)."""
    from impactlab.sweep import flag_counts, status_counts
    from impactlab.sweep.display import steady_throughput, warm_up_s
    from impactlab.sweep.summary import format_flag_counts

    s = res.stats
    summary: dict[str, Any] = {
        "store": str(res.path),
        "cases": s.n_cases,
        "chunks": s.n_chunks,
        "chunks_resumed": s.chunks_before,
        "chunks_computed": s.chunks_computed,
        "wall_time": s.wall_s,
        "throughput": steady_throughput(s),  # after each worker's first task (the compile)
        "first_task": warm_up_s(s) if s.chunks_computed else None,  # None: nothing computed
        "backend": s.backend,
        "status": status_counts(ds),
    }
    if "flags" in ds.data_vars:
        counts = flag_counts(ds["flags"].values, ds["flags"].attrs)
        summary["flagged"] = flagged_json(counts) if as_json else format_flag_counts(counts)
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
