"""Section 5 of the reproduction report: every published number impactlab does not reproduce,
as one table, with each explanation (from :mod:`impactlab.paper.reasons`) written once."""

from __future__ import annotations

import re
from typing import Any

import pandas as pd

from impactlab.paper.quantities import (
    COINCIDENCE,
    EXTRAPOLATED_MARK,
    NOT_SIMULATED,
    PUBLISHED_KEY,
    UNDECIDED,
    comparison_counts,
)
from impactlab.paper.report import Block, Bullets, Heading, Para, Table, fmt, fmt_pct

__all__ = ["not_reproduced"]

_NUMBER = re.compile(r"[-+]?\d+(?:\.\d+)?(?:e[-+]?\d+)?")


def _letter(i: int) -> str:
    """A, B, ..., Z, AA, AB, ... for the explanations of Section 5."""
    return _letter(i // 26 - 1) + chr(65 + i % 26) if i >= 26 else chr(65 + i)


def _model(r: pd.Series) -> str:
    """The row's model, with ``EXTRAPOLATED_MARK`` when its simulation is LAW_EXTRAPOLATED."""
    flagged = "LAW_EXTRAPOLATED" in str(r.get("flags", ""))
    return f"{r['model']} {EXTRAPOLATED_MARK}" if flagged else str(r["model"])


def _explained(bad: pd.DataFrame) -> tuple[pd.DataFrame, list[str]]:
    """One row per published number not reproduced (identical numbers of the two friction
    models once), with the letter of its explanation; and the explanations, each once: reasons
    that differ only in their numbers share one (shown with the numbers of its first row)."""
    rows: list[dict[str, Any]] = []
    kinds: dict[str, tuple[str, list[str]]] = {}  # reason without numbers -> letter, row labels
    texts: dict[str, str] = {}
    keys = ["source", "angle [deg]", "model", "quantity", "published", "impactlab", "reason"]
    for _, g in bad.groupby(keys, sort=False, dropna=False):
        r = g.iloc[0]
        frs = ", ".join(f for f in g["friction"] if f != "-") or "-"
        kind = _NUMBER.sub("#", str(r["reason"]))
        if kind not in kinds:
            kinds[kind] = (_letter(len(kinds)), [])
            texts[kind] = str(r["reason"])
        letter, labels = kinds[kind]
        labels.append(f"{r['source']}, {r['angle [deg]']} deg, {r['model']}, {r['quantity']}")
        rows.append(
            {
                "source": r["source"],
                "angle [deg]": r["angle [deg]"],
                "model": _model(r),
                "friction": frs,
                "quantity": r["quantity"],
                "published": r["published"],
                "impactlab": r["impactlab"],
                "rel. diff": fmt_pct(r["rel. diff"]),
                "why": letter,
            }
        )
    notes = [
        f"{letter} ({_covers(labels)}): {texts[kind]}." for kind, (letter, labels) in kinds.items()
    ]
    return pd.DataFrame(rows), notes


def _covers(labels: list[str]) -> str:
    """What one explanation covers: ``1 row`` for one; for several, every row it covers and
    whose numbers its text quotes (the first's; each row's own are in comparison.csv)."""
    if len(labels) == 1:
        return "1 row"
    return (
        f"{len(labels)} rows: {'; '.join(labels)}; the numbers quoted are those of the first, "
        "each row's own are in comparison.csv"
    )


def not_reproduced(comp: pd.DataFrame) -> list[Block]:
    """Section 5: the table of the published numbers not reproduced, each explanation once,
    the published numbers not compared (the simulations skipped), the experimental forces
    within tolerance that still need a note, and the checks the printed digits leave
    UNDECIDED (neither reproduced nor not)."""
    B: list[Block] = [Heading("5. Every published number not reproduced, and why")]
    bad = comp[comp["reproduced"] == False]  # noqa: E712
    skipped = _not_compared(comp)
    if bad.empty:
        B.append(Para("None not reproduced." if skipped else "None."))
    else:
        table, notes = _explained(bad)
        B += [
            Para(
                "Tolerances: 15 % for the simulated rows (required for e and delta_p; "
                "applied to L_s, T and F as well), 5 % for the experimental T (a check, "
                "decided over the rounding of the printed numbers: Section 1), 15 % for "
                "the experimental F. Identical numbers of the two friction models are "
                "listed once. The column 'why' names the explanation below the table; "
                "each row's own numbers are in the column 'reason' of comparison.csv."
            ),
            Table(table, "Published numbers not reproduced", digits=4),
            Bullets(tuple(notes)),
        ]
    if skipped:
        B.append(Para(skipped))
    ok_f = comp[
        (comp["model"] == "experiment")
        & (comp["quantity"] == "F [N]")
        & comp["reproduced"].eq(True)
    ]
    for _, r in ok_f.iterrows():
        B.append(
            Para(
                f"Within tolerance but worth a note: {r['angle [deg]']} deg experimental F, "
                f"published {fmt(r['published'])} N, impactlab {fmt(r['impactlab'])} N "
                f"({fmt_pct(r['rel. diff'])}): {r['reason']}."
            )
        )
    chance = comp[comp["reason"].fillna("").astype(str).str.startswith(COINCIDENCE)]
    for _, r in chance.drop_duplicates(PUBLISHED_KEY).iterrows():
        B.append(
            Para(
                f"Within tolerance but not counted as reproduced: {r['source']}, "
                f"{r['angle [deg]']} deg, {_model(r)}, {r['quantity']}, published "
                f"{fmt(r['published'])}, impactlab {fmt(r['impactlab'])}: {r['reason']}."
            )
        )
    undecided = comp[comp["verdict"] == UNDECIDED] if "verdict" in comp else comp.iloc[:0]
    for _, r in undecided.iterrows():
        B.append(
            Para(
                f"Neither reproduced nor not ({UNDECIDED}, Section 1): {r['angle [deg]']} deg "
                f"experimental {r['quantity']}, published {fmt(r['published'])}, impactlab "
                f"{fmt(r['impactlab'])} ({fmt_pct(r['rel. diff'])}): {r['reason']}."
            )
        )
    return B


def _short(quantity: str) -> str:
    """A quantity's column label without its unit and sign note: ``delta_p``, ``T``."""
    return quantity.split(" [")[0].split(",")[0]


def _not_compared(comp: pd.DataFrame) -> str:
    """The paragraph on the published numbers not compared because the simulations were
    skipped, by source with their quantities; ``""`` when every one was compared."""
    _n_bad, n = comparison_counts(comp)
    if not n:
        return ""
    rows = comp[(comp["reason"] == NOT_SIMULATED) & comp["published"].notna()]
    by_source = [
        f"{source}: {len(g)} ({', '.join(dict.fromkeys(_short(str(q)) for q in g['quantity']))})"
        for source, g in rows.drop_duplicates(PUBLISHED_KEY).groupby("source", sort=False)
    ]
    return (
        f"Not compared: {n} published number{'' if n == 1 else 's'} of the paper's simulations "
        f"({'; '.join(by_source)}), because the simulations were skipped (`--no-simulate`): "
        f"neither reproduced nor not, and not counted above (comparison.csv: reason "
        f"'{NOT_SIMULATED}'). A run with the simulations compares them."
    )
