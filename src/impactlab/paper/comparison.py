"""The comparison: every published number (and impactlab's own Table 4 for 70 deg) next to
impactlab's, with the relative difference, the tolerance, whether it is reproduced and, if not,
why; and the wide side-by-side table of one angle.
"""

from __future__ import annotations

import math
from typing import Any

import pandas as pd

from impactlab.paper import data as D
from impactlab.paper.quantities import (
    QUANTS,
    TOL_EXPERIMENT_T,
    TOL_SIMULATED,
    Simulations,
    rel_diff,
    sim_value,
)
from impactlab.paper.reasons import Reasons
from impactlab.paper.simulations import FRICTIONS

_TABLES = {20: "Table 2", 45: "Table 3", 70: "Table 4 (ours)"}
_TEXT = "Sec. 5.2 text"


def comparison_table(
    sims: Simulations | None,
    experimental: pd.DataFrame,
    consistency: pd.DataFrame,
) -> pd.DataFrame:
    """Long table: every published number (and our Table 4) next to impactlab's, with the
    relative difference, the tolerance, whether it is reproduced and, if not, why."""
    rows: list[dict[str, Any]] = []
    ctx = Reasons(experimental, consistency, sims)
    for ang in D.ANGLES_DEG:
        rows += _experiment_rows(ang, experimental, ctx)
        for law in D.PAPER_LAWS:
            for fr in FRICTIONS:
                res = sims.get((ang, law, fr)) if sims else None
                rows += _simulated_rows(ang, law, fr, res, ctx)
    return pd.DataFrame(rows)


def _experiment_rows(ang: int, experimental: pd.DataFrame, ctx: Reasons) -> list[dict[str, Any]]:
    """The experimental row of one angle: measured inputs, T and F by the inversion."""
    table = _TABLES[ang]
    x = D.EXPERIMENTS[ang]
    exp = experimental.set_index("angle [deg]").loc[ang]
    pub = D.published_row(ang, "experiment")
    ours = {
        "delta_p": x.delta_p,
        "L_s": x.L_s,
        "e": x.e,
        "T": exp["T [ms]"] * 1e-3,
        "F": exp["F [N]"],
    }
    rows = []
    for q, label, scale in QUANTS:
        p = getattr(pub, q) if pub is not None else None
        measured = q in ("delta_p", "L_s", "e")
        tol = TOL_EXPERIMENT_T if q == "T" else (0.15 if q == "F" else 0.0)
        rows.append(
            _row(
                table,
                ang,
                "experiment",
                "-",
                label,
                p,
                ours[q],
                scale,
                tol,
                "measured input" if measured else None,
                ctx,
                q,
            )
        )
    return rows


def _simulated_rows(ang: int, law: str, fr: str, res: Any, ctx: Reasons) -> list[dict[str, Any]]:
    """The rows of one simulation against every published row of its angle and law (the
    Sec. 5.2 text only where it differs from the table)."""
    table = _TABLES[ang]
    pubs = [r for r in (*D.TABLE_ROWS, *D.TEXT_ROWS) if r.angle_deg == ang and r.model == law]
    rows = []
    if not pubs:
        for q, label, scale in QUANTS:
            rows.append(
                _row(
                    table,
                    ang,
                    law,
                    fr,
                    label,
                    None,
                    None if res is None else sim_value(res, q),
                    scale,
                    TOL_SIMULATED,
                    None,
                    ctx,
                    q,
                )
            )
        return rows
    for pr in pubs:
        src = table if pr.table != _TEXT else _TEXT
        if src == _TEXT and not _text_differs(pr):
            continue
        for q, label, scale in QUANTS:
            if src == _TEXT and getattr(pr, q) == getattr(D.published_row(ang, law), q):
                continue
            rows.append(
                _row(
                    src,
                    ang,
                    law,
                    fr,
                    label,
                    getattr(pr, q),
                    None if res is None else sim_value(res, q),
                    scale,
                    TOL_SIMULATED,
                    None,
                    ctx,
                    q,
                )
            )
    return rows


def _text_differs(pr: D.PublishedRow) -> bool:
    tab = D.published_row(pr.angle_deg, pr.model)
    return tab is not None and any(getattr(pr, q) != getattr(tab, q) for q, _, _ in QUANTS)


def _row(
    source: str,
    ang: int,
    model: str,
    fr: str,
    label: str,
    pub: float | None,
    ours: float | None,
    scale: float,
    tol: float,
    fixed_note: str | None,
    ctx: Reasons,
    q: str,
) -> dict[str, Any]:
    p = None if pub is None else round(pub * scale, 9)  # printed values: no float noise
    o = None if ours is None else ours * scale
    rd = rel_diff(o, p)
    if fixed_note is not None:
        ok: bool | None = None
        reason = fixed_note
    elif rd is None:
        ok = None
        reason = "no published value (impactlab's own number)" if p is None else "not simulated"
    else:
        ok = abs(rd) <= tol
        reason = "" if ok else ctx.reason(source, ang, model, fr, q, p, o)
        if ok and model == "experiment" and q == "F":  # context even when within tolerance
            reason = ctx.reason(source, ang, model, fr, q, p, o)
    return {
        "source": source,
        "angle [deg]": ang,
        "model": model,
        "friction": fr,
        "quantity": label,
        "published": p,
        "impactlab": o,
        "rel. diff": rd,
        "tolerance": tol if fixed_note is None else None,
        "reproduced": ok,
        "reason": reason,
    }


def side_by_side(comparison: pd.DataFrame, angle: int) -> pd.DataFrame:
    """Wide table for one angle: per model/friction the published value, impactlab's and the
    relative difference for each quantity."""
    sub = comparison[comparison["angle [deg]"] == angle]
    out = []
    for (src, model, fr), g in sub.groupby(["source", "model", "friction"], sort=False):
        row: dict[str, Any] = {"source": src, "model": model, "friction": fr}
        for _, label, _ in QUANTS:
            h = g[g["quantity"] == label]
            if h.empty:
                row[f"{label} pub."] = row[f"{label} ours"] = row[f"{label} diff"] = None
                continue
            r = h.iloc[0]
            row[f"{label} pub."] = r["published"]
            row[f"{label} ours"] = r["impactlab"]
            row[f"{label} diff"] = (
                None
                if r["rel. diff"] is None
                or (isinstance(r["rel. diff"], float) and math.isnan(r["rel. diff"]))
                else f"{r['rel. diff']:+.0%}"
            )
        out.append(row)
    return pd.DataFrame(out)
