"""Notebook and console display of the laws' measured accuracy (``impactlab.fe.accuracy``):
the short reprs of :class:`~impactlab.fe.accuracy.LawAccuracy` and
:class:`~impactlab.fe.accuracy.CaseAccuracy`, and a case's HTML table: the rows
``impactlab laws --accuracy`` prints (:func:`table_rows`, the same as
``accuracy_views.table_rows``; kept here because ``accuracy_views`` imports ``accuracy``).
Imports nothing of ``impactlab.fe``: the objects are read by their attributes."""

from __future__ import annotations

import html
import math
from typing import Any

from impactlab._display import display_unit, format_number
from impactlab._html import grid_html

__all__ = ["case_html", "case_repr", "law_repr", "table_rows"]


def _pct_cell(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{100 * x:+.0f} %"


def _abs_cell(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{x:+.3f}"


def _ratio_cell(x: float) -> str:
    return "n/a" if not math.isfinite(x) else f"{x:.3f}"


def table_rows(result: Any, only: str | None = None) -> tuple[list[str], list[list[str]]]:
    """(header, rows) of one case (a ``CaseAccuracy``): per law (``only``: that one) the force
    error and the delta_r / delta_max error at the FE maxima, and the verified range; the last
    row: FE's delta_r / delta_max."""
    ratios = [float(r) for r in result.laws[0].maxima_ratio] if result.laws else []
    header = ["law", *(f"{r:g}" for r in ratios), "verified range"]
    rows = []
    for a in (a for a in result.laws if only in (None, a.law)):
        if not a.built:  # e.g. Brake's law for a material without a Brinell hardness
            why = a.message.split("; ")[0]
            rows.append([a.law, *("n/a" for _ in ratios), f"not built for this pair: {why}"])
            continue
        cells = [
            f"{_pct_cell(a.force_error_at(r))} / {_abs_cell(a.residual_error_at(r))}"
            for r in ratios
        ]
        rows.append([a.law, *cells, a.verified.text])
    fe = ["FE: delta_r/delta_max", *(_ratio_cell(x) for x in result.laws[0].residual_fe)]
    rows.append([*fe, ""] if result.laws else fe)
    return header, rows


def _pct(x: float) -> str:
    return f"{format_number(100 * x, 3)} %" if math.isfinite(x) else "n/a"


def _ratio(x: float) -> str:
    return format_number(x, 3) if math.isfinite(x) else "n/a"


def _um(x: float) -> str:
    d = display_unit("delta_c", "m")
    return f"{format_number(x * d.scale, 4)} {d.unit}"


def law_repr(a: Any) -> str:
    """``LawAccuracy(ghaednia on <case>, E*/S_y = 1731: verified <= 30 delta_c (...); RMS
    force error 12 %, RMS delta_r/delta_max error 0.034; 40 force points, 6 maxima)``."""
    head = f"LawAccuracy({a.law} on {a.case}, E*/S_y = {format_number(a.e_star_over_sy, 4)}"
    if not a.built:
        why = a.message.split("; ")[0]
        return f"{head}: not built for this pair: {why[:120]})"
    return (
        f"{head}: verified {a.verified.text}; RMS force error {_pct(a.rms_force_error())}, "
        f"RMS delta_r/delta_max error {_ratio(a.rms_residual_error())}; "
        f"{a.force_ratio.size} force points, {a.maxima_ratio.size} maxima)"
    )


def _summary(res: Any, plastic_from: float) -> str:
    """``6 laws (5 built); closest: ... (from 100 delta_c on: ...); largest verified range
    ...`` of a case (``plastic_from``: where its fully plastic regime starts [delta_c])."""
    laws, built = res.laws, res.built
    text = f"{len(laws)} law{'s' * (len(laws) != 1)}"
    if len(built) != len(laws):
        text += f" ({len(built)} built)"
    if not built:
        return text
    most = max(a.verified.upper for a in built)
    who = ", ".join(a.law for a in built if a.verified.upper == most)
    plastic = res.closest_fully_plastic()
    beyond = "" if plastic is None else f" (from {plastic_from:g} delta_c on: {plastic.law})"
    return (
        f"{text}; closest: {res.closest().law}{beyond}; largest verified range "
        f"{format_number(most, 3)} delta_c ({who})"
    )


def case_repr(res: Any, plastic_from: float) -> str:
    """``CaseAccuracy('<case>', E*/S_y = 1731, delta_c = 1.234 um, 6 laws; closest: ...)``."""
    c = res.case
    return (
        f"CaseAccuracy({c.name!r}, E*/S_y = {format_number(c.e_star_over_sy, 4)}, "
        f"delta_c = {_um(c.delta_c)}, {_summary(res, plastic_from)})"
    )


def case_html(res: Any) -> str:
    """The case's table as ``impactlab laws --accuracy`` prints it (per law the force error /
    delta_r/delta_max error at each FE maximum and the verified range), with the
    recommendation under it."""
    c = res.case
    title = (
        f"{c.description}: E*/S_y = {format_number(c.e_star_over_sy, 4)}, "
        f"delta_c = {_um(c.delta_c)}"
    )
    if not res.laws:
        return f"<div><strong>{html.escape(title)}</strong><p>no law measured</p></div>"
    header, rows = table_rows(res)
    table = grid_html(
        title,
        header,
        rows,
        caption="force error / delta_r/delta_max error, at delta_max/delta_c =",
    )
    if not res.built:
        return table
    return f"{table}<p>recommendation: {html.escape(res.recommendation())}</p>"
