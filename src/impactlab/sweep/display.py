"""How a study and a finished sweep show themselves: a one-line ``repr`` and a notebook table
that summarise each dimension as name, size, range and unit (never every value), and the
run's throughput; the units of the plots' axes and the words for the slice of a study a figure
shows.

The throughput of a run (``run_throughput``: the notebook table, ``impactlab sweep run`` and its
``--json``) is the cases this run computed over this run's wall time, the engine's load (its
first task, reported beside it) included. The first task of each worker includes loading (or
compiling) the engine's compiled functions once; ``steady_throughput`` leaves those tasks out.
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from impactlab._display import display_unit, format_number, format_value
from impactlab._html import axis_row, grid_html, value_range
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages
from impactlab.sweep.dimensions import SAMPLE_DIM
from impactlab.sweep.inputs import MATERIAL_OVERRIDES, get_input

__all__ = [
    "dimension_rows",
    "no_result",
    "plot_unit",
    "results_text",
    "run_throughput",
    "slice_note",
    "steady_throughput",
    "study_html",
    "study_repr",
    "sweep_result_html",
    "throughput_text",
    "value_text",
    "warm_up_s",
]


def dimension_rows(study: Any) -> list[tuple[str, str, str, str]]:
    """``(name, size, range, unit)`` of each dimension: grid axes, then each sampled input (its
    distribution as the range)."""
    rows = [axis_row(a.name, a.values, get_input(a.name).unit) for a in study.axes]
    if study.sample is not None:
        for name, dist in study.sample.inputs.items():
            d = display_unit(name, get_input(name).unit)
            unit = "" if d.unit == "-" else d.unit
            text = ", ".join(_param_text(k, v, d.scale, unit) for k, v in dist.to_dict().items())
            rows.append((f"{SAMPLE_DIM}: {name}", str(study.sample.size), text, unit))
    return rows


def _param_text(key: str, value: Any, scale: float, unit: str) -> str:
    """One parameter of a distribution in the display unit of its input (``"median 305
    MPa"``); a lognormal's ``sigma`` is the dimensionless spread of the log: ``"sigma 0.08
    (log)"``."""
    if key == "dist":
        return f"dist {value}"
    if key == "sigma":
        return f"sigma {format_value(value)} (log)"
    return f"{key} {format_value(value * scale)}{' ' + unit if unit else ''}"


def _fixed_text(study: Any) -> list[str]:
    out = []
    for name, v in study.fixed.items():
        text, unit = value_range(name, [v], get_input(name).unit)
        out.append(f"{name} = {text}{' ' + unit if unit else ''}")
    return out


def _counts(layout: Any) -> str:
    """``"1089 cases in 5 chunks"``, ``"1 case in 1 chunk"``."""
    n, k = int(layout.n_cases), int(layout.n_chunks)
    return f"{n} case{'s' * (n != 1)} in {k} chunk{'s' * (k != 1)}"


def study_repr(study: Any) -> str:
    """``Study('map', grid, 1089 cases in 5 chunks; angle[33] 5 .. 85 deg, ...; fixed: ...)``."""
    dims = "; ".join(
        f"{n}[{s}] {r}" + ("" if n.startswith(f"{SAMPLE_DIM}:") else f" {u}").rstrip()
        for n, s, r, u in dimension_rows(study)
    )
    fixed = ", ".join(_fixed_text(study))
    lay = study.layout
    return (
        f"Study({study.name!r}, {study.mode}, {_counts(lay)}; "
        f"{dims}{'; fixed: ' + fixed if fixed else ''})"
    )


def study_html(study: Any) -> str:
    """A study as a notebook table: one row per dimension, then the fixed inputs and outputs."""
    lay = study.layout
    outputs = ", ".join(study.outputs) if study.outputs is not None else "all"
    caption = (
        f"{study.mode}: {_counts(lay)}; fixed: "
        f"{', '.join(_fixed_text(study)) or 'none'}; outputs: {outputs}"
    )
    header = ("dimension", "size", "range", "unit")
    return grid_html(f"Study {study.name!r}", header, dimension_rows(study), caption)


def warm_up_s(stats: Any) -> float:
    """The longest first task of a worker [s]: it includes loading (or compiling) the engine."""
    return max(stats.first_task_s.values(), default=0.0)


def steady_throughput(stats: Any) -> float | None:
    """Cases per second of wall time after each worker's first task (which loads or compiles the
    engine once); None when every computed chunk was a first task."""
    first_cases = sum(stats.first_task_cases.values())
    cases = stats.cases_computed - first_cases
    wall = stats.wall_s - warm_up_s(stats)
    if cases <= 0 or wall <= 0.0:
        return None
    return float(cases / wall)


def run_throughput(stats: Any) -> float | None:
    """The cases this run computed per second of this run's wall time (the engine's load
    included; chunks stored before the run are not counted); None when it computed nothing."""
    if stats.cases_computed <= 0 or stats.wall_s <= 0.0:
        return None
    return float(stats.cases_computed / stats.wall_s)


#: The keys of ``summary.flag_counts`` that count cases, not one flag: "flagged" (any flag) and
#: "not ok" (a flag that is not advisory: not plain success).
TOTALS = ("flagged", "not ok")


#: The names of the advisory flags (``ADVISORY_FLAGS``: the result stays ``ok``), as counted.
ADVISORY_NAMES = {messages(f)[0].split(":")[0] for f in ResultFlag if f & ADVISORY_FLAGS}


def not_ok_text(counts: Mapping[str, int]) -> str:
    """``"58 case(s) not ok (energy gain: 15, gravity-dominated: 48)"``: the cases of
    :func:`summary.flag_counts`' ``counts`` with a flag that is not advisory, and those flags."""
    bad = ", ".join(
        f"{k}: {v:,}"
        for k, v in counts.items()
        if k not in TOTALS and v and k not in ADVISORY_NAMES
    )
    return f"{counts.get('not ok', 0):,} case(s) not ok" + (f" ({bad})" if bad else "")


def throughput_text(stats: Any) -> str:
    """``"59813 impacts/s (cases computed / wall time)"``: :func:`run_throughput`
    and what it is; ``"- (nothing computed)"``."""
    rate = run_throughput(stats)
    if rate is None:
        return "- (nothing computed)"
    return f"{format_number(rate)} impacts/s (cases computed / wall time)"


def _rows(result: Any) -> Sequence[tuple[str, str]]:
    s = result.stats
    return (
        ("store", str(result.path)),
        ("chunks", f"{s.chunks_computed} computed, {s.chunks_before} already stored"),
        ("cases computed", str(s.cases_computed)),
        ("wall time", f"{format_number(s.wall_s)} s ({s.backend}, {s.workers} workers)"),
        (
            "first task (compile/load)",
            f"{format_number(warm_up_s(s))} s" if s.chunks_computed else "- (nothing computed)",
        ),
        ("throughput", throughput_text(s)),
        ("not ok (flags)", not_ok_text(s.flagged) if s.flagged else "- (no flags stored)"),
        ("without a result", f"{no_result(s):,} case(s) (status > 0)"),
    )


def sweep_result_html(result: Any) -> str:
    """A finished sweep as a notebook table: its run numbers, then its study."""
    run = grid_html("SweepResult", ("", ""), _rows(result))
    return run + study_html(result.study)


def results_text(stats: Any) -> str:
    """``"; 183 case(s) not ok (beyond the tip: 183)"``, then ``"; 3 case(s) without a result
    (status > 0)"`` where there are such cases; "" otherwise."""
    parts = [not_ok_text(stats.flagged)] if stats.not_ok else []
    if no_result(stats):
        parts.append(f"{no_result(stats):,} case(s) without a result (status > 0)")
    return "".join(f"; {p}" for p in parts)


def no_result(stats: Any) -> int:
    """Cases of a run's store computed without a result (``stats.status``: a code > 0)."""
    return sum(n for k, n in stats.status.items() if int(k.partition(":")[0]) > 0)


# -- plots: units and the slice a figure shows -----------------------------------------------


def plot_unit(name: str, units: str) -> tuple[float, str]:
    """(scale, unit) of a variable in the display layer's units (``impactlab._display``; a
    material override such as ``flat_E`` as its field ``E``); "1" for dimensionless."""
    if name == "angle":
        return 180.0 / math.pi, "deg"
    field = next((side[name] for side in MATERIAL_OVERRIDES.values() if name in side), name)
    d = display_unit(field, units)
    return d.scale, "1" if d.unit == "-" else d.unit


def value_text(ds: Any, dim: str, value: Any, digits: int = 5) -> str:
    """``"vy = -1.41 m/s"``: a value of dimension ``dim`` in its display unit (``digits``
    significant digits)."""
    if isinstance(value, str):
        return f"{dim} = {value}"
    scale, unit = plot_unit(dim, str(ds[dim].attrs.get("units", "")))
    unit = "" if unit in ("1", "-") else unit
    return f"{dim} = {format_number(float(value) * scale, digits)} {unit}".rstrip()


def slice_note(ds: Any, hidden: Sequence[str]) -> str:
    """What a plot leaves out of the dimensions ``hidden`` (each at its first value), and how
    to choose another slice: ``"shows only law = brake (first of 3 values); ..."``."""
    shown = ", ".join(
        f"{value_text(ds, d, ds[d].values[0])} (first of {ds.sizes[d]} values)" for d in hidden
    )
    d, last = hidden[0], ds[hidden[0]].values[-1]
    example = last.item() if isinstance(last, np.generic) else last
    return (
        f"more dimensions than a figure shows: the plots show only {shown}; choose "
        f"another slice with sel (SI values), e.g. impactlab.sweep.plot_sweep(ds, outdir, "
        f"sel={{{d!r}: {example!r}}})"
    )
