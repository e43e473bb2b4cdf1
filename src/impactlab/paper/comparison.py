"""The comparison: every published number (and impactlab's own Table 4 for 70 deg) next to
impactlab's, with the relative difference, the tolerance, the verdict of the pass/fail check
(the experimental T: PASS, FAIL or UNDECIDED over the rounding of the printed numbers), whether
it is reproduced and, if not, why, and the caveat of an estimate; and the wide side-by-side
table of one angle.
"""

from __future__ import annotations

import math
from typing import Any

import pandas as pd

from impactlab.paper import data as D
from impactlab.paper.quantities import (
    NOT_SIMULATED,
    QUANTS,
    REPRODUCED_BY_VERDICT,
    TOL_EXPERIMENT_F,
    TOL_EXPERIMENT_T,
    TOL_SIMULATED,
    DurationCheck,
    Simulations,
    caveat,
    duration_checks,
    flag_columns,
    rel_diff,
    sim_value,
)
from impactlab.paper.reasons import Reasons, RowKey
from impactlab.paper.simulations import FRICTIONS

_TABLES = {20: "Table 2", 45: "Table 3", 70: "Table 4 (ours)"}
_TEXT = "Sec. 5.2 text"
#: The ``caveat`` of a published number within tolerance that is a probable copy of another
#: row's (``Reasons.coincidence``; its reason gives the numbers).
CHANCE_CAVEAT = (
    "a probable copy of another law's table value: the agreement is most likely a "
    "coincidence, not a reproduction"
)
#: The flag columns of a row without a simulation (the experiment, or not simulated).
_NO_FLAGS: dict[str, Any] = {"flags": "", "max_delta_ratio": None}
#: The reason of a measured input of the inversion (in ``published``; not compared).
INPUT_NOTE = "measured input (Sec. 5.1.3), not compared"
#: The ``diff`` cell of a measured input in the side-by-side tables.
INPUT_DIFF = "input"
#: The tolerance of each quantity of the experimental rows (the inputs: none, not compared).
EXPERIMENT_TOL: dict[str, float | None] = {
    "delta_p": None,
    "L_s": None,
    "e": None,
    "T": TOL_EXPERIMENT_T,
    "F": TOL_EXPERIMENT_F,
}


def comparison_table(
    sims: Simulations | None,
    experimental: pd.DataFrame,
    consistency: pd.DataFrame,
) -> pd.DataFrame:
    """Long table: every published number (and our Table 4) next to impactlab's, with the
    relative difference, the tolerance, the ``verdict`` of the pass/fail check (the
    experimental T at 20 and 45 deg: PASS, FAIL or UNDECIDED, as the report's Section 1 and
    the reproduce command print it; empty for a number compared, not checked), whether it is
    reproduced (the check: True only for PASS, None for UNDECIDED; a compared number: within
    its tolerance, None for a probable copy of another row's value, whose agreement is most
    likely chance) and, if not, why, and the ``caveat`` of an estimate (the 70 deg T and F)
    or of such a copy."""
    rows: list[dict[str, Any]] = []
    ctx = Reasons(experimental, consistency, sims)
    checks = {c.angle_deg: c for c in duration_checks(experimental)}
    for ang in D.ANGLES_DEG:
        rows += _experiment_rows(ang, experimental, ctx, checks.get(ang))
        for law in D.PAPER_LAWS:
            for fr in FRICTIONS:
                res = sims.get((ang, law, fr)) if sims else None
                rows += _simulated_rows(ang, law, fr, res, ctx)
    return pd.DataFrame(rows)


def _experiment_rows(
    ang: int, experimental: pd.DataFrame, ctx: Reasons, check: DurationCheck | None
) -> list[dict[str, Any]]:
    """The experimental row of one angle: the measured inputs (Sec. 5.1.3) as published values,
    not compared; T and F by the inversion against the published ones, T decided by ``check``
    (its verdict over the rounding of the printed numbers; None: no published T)."""
    key = RowKey(_TABLES[ang], ang, "experiment", "-")
    x = D.EXPERIMENTS[ang]
    exp = experimental.set_index("angle [deg]").loc[ang]
    pub = D.published_row(ang, "experiment")
    inverted = {"T": exp["T [ms]"] * 1e-3, "F": exp["F [N]"]}
    rows = []
    for q, label, scale in QUANTS:
        tol = EXPERIMENT_TOL[q]
        if tol is None:  # an input: the measured value, in the published column only
            values = (getattr(x, q), None)
            rows.append(_row(key, q, label, scale, values, 0.0, INPUT_NOTE, ctx) | _NO_FLAGS)
            continue
        p = getattr(pub, q) if pub is not None else None
        row = _row(key, q, label, scale, (p, inverted[q]), tol, None, ctx) | _NO_FLAGS
        if q == "T" and check is not None and row["rel. diff"] is not None:
            row |= _checked(check, ctx.reason(key, q))
        rows.append(row | {"caveat": caveat(ang, q)})
    return rows


def _checked(check: DurationCheck, why: str) -> dict[str, Any]:
    """The columns of the checked T: its verdict, reproduced only for PASS (None: UNDECIDED)
    and the reason giving the range over the printed digits (``why`` added unless PASS)."""
    reason = check.reason() + ("" if check.ok else f"; {why}")
    return {
        "verdict": check.verdict,
        "reproduced": REPRODUCED_BY_VERDICT[check.verdict],
        "reason": reason,
    }


def _simulated_rows(ang: int, law: str, fr: str, res: Any, ctx: Reasons) -> list[dict[str, Any]]:
    """The rows of one simulation against every published row of its angle and law (the
    Sec. 5.2 text only where it differs from the table; no published value: impactlab's own)."""
    table = _TABLES[ang]
    pubs = [r for r in (*D.TABLE_ROWS, *D.TEXT_ROWS) if r.angle_deg == ang and r.model == law]
    sources: list[tuple[str, D.PublishedRow | None]] = [(table, None)] if not pubs else []
    for published in pubs:
        src = table if published.table != _TEXT else _TEXT
        if src != _TEXT or _text_differs(published):
            sources.append((src, published))
    rows = []
    for src, pr in sources:
        for q, label, scale in QUANTS:
            pub = None if pr is None else getattr(pr, q)
            if src == _TEXT and pub == getattr(D.published_row(ang, law), q):
                continue
            ours = None if res is None else sim_value(res, q)
            key = RowKey(src, ang, law, fr)
            row = _row(key, q, label, scale, (pub, ours), TOL_SIMULATED, None, ctx)
            chance = ctx.coincidence(key, q, row["rel. diff"]) if row["reproduced"] else None
            if chance is not None:  # within tolerance, but a probable copy: not counted
                row |= {"reproduced": None, "reason": chance, "caveat": CHANCE_CAVEAT}
            rows.append(row | (flag_columns(res) if res is not None else _NO_FLAGS))
    return rows


def _text_differs(pr: D.PublishedRow) -> bool:
    tab = D.published_row(pr.angle_deg, pr.model)
    return tab is not None and any(getattr(pr, q) != getattr(tab, q) for q, _, _ in QUANTS)


def _row(
    key: RowKey,
    q: str,
    label: str,
    scale: float,
    values: tuple[float | None, float | None],
    tol: float,
    fixed_note: str | None,
    ctx: Reasons,
) -> dict[str, Any]:
    """One row: quantity ``q`` (``label``, display ``scale``) of the row ``key``, its
    (published, impactlab) ``values`` [SI], the tolerance and the reason."""
    pub, ours = values
    p = None if pub is None else round(pub * scale, 9)  # printed values: no float noise
    o = None if ours is None else ours * scale
    rd = rel_diff(o, p)
    if fixed_note is not None:
        ok: bool | None = None
        reason = fixed_note
    elif rd is None:
        ok = None
        reason = "no published value (impactlab's own number)" if p is None else NOT_SIMULATED
    else:
        ok = abs(rd) <= tol
        # the experiment's F: context even when within tolerance
        explain = not ok or (key.model == "experiment" and q == "F")
        reason = ctx.reason(key, q) if explain else ""
    return {
        "source": key.source,
        "angle [deg]": key.angle,
        "model": key.model,
        "friction": key.friction,
        "quantity": label,
        "published": p,
        "impactlab": o,
        "rel. diff": rd,
        "tolerance": tol if fixed_note is None else None,
        "verdict": "",
        "reproduced": ok,
        "reason": reason,
        "caveat": "",
    }


def side_by_side(comparison: pd.DataFrame, angle: int) -> pd.DataFrame:
    """Wide table for one angle: per model/friction the simulation's flags, then the published
    value, impactlab's and the relative difference for each quantity (one decimal of a percent;
    ``input`` for a measured input of the experiment, not compared), and the ``caveat`` of
    the row's estimates (``T [ms], F [N]: an estimate ...``; ``""``: none)."""
    sub = comparison[comparison["angle [deg]"] == angle]
    out = []
    for (src, model, fr), g in sub.groupby(["source", "model", "friction"], sort=False):
        row: dict[str, Any] = {"source": src, "model": model, "friction": fr}
        for col in ("flags", "max_delta_ratio"):
            if col in g:
                row[col] = g[col].iloc[0]
        for _, label, _ in QUANTS:
            h = g[g["quantity"] == label]
            if h.empty:
                row[f"{label} pub."] = row[f"{label} ours"] = row[f"{label} diff"] = None
                continue
            r = h.iloc[0]
            row[f"{label} pub."] = r["published"]
            row[f"{label} ours"] = r["impactlab"]
            row[f"{label} diff"] = (
                INPUT_DIFF
                if r["reason"] == INPUT_NOTE
                else None
                if r["rel. diff"] is None
                or (isinstance(r["rel. diff"], float) and math.isnan(r["rel. diff"]))
                else f"{r['rel. diff']:+.1%}"  # one decimal: read against a 5 % tolerance
            )
        row["caveat"] = _caveats(g)
        out.append(row)
    return pd.DataFrame(out)


def _caveats(g: pd.DataFrame) -> str:
    """The caveats of one row of the wide table, each once, after the quantities it concerns."""
    if "caveat" not in g:
        return ""
    words: dict[str, list[str]] = {}
    for label, text in zip(g["quantity"], g["caveat"].fillna(""), strict=True):
        if text:
            words.setdefault(str(text), []).append(str(label))
    return "; ".join(f"{', '.join(labels)}: {text}" for text, labels in words.items())
