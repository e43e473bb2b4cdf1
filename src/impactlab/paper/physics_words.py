"""Wording helpers of the section "Can physics explain the experiment?"
(:mod:`impactlab.paper.physics_report`): a configuration's numbers by angle, lists of angles,
and the size and direction of the change in the dent depth."""

from __future__ import annotations

import math

import numpy as np
import pandas as pd

from impactlab.paper.physics import MEASURED


def series(table: pd.DataFrame, config: str, column: str) -> np.ndarray:
    """``column`` of ``config`` at the table's angles, in increasing angle."""
    rows = table[table["configuration"] == config].sort_values("angle [deg]")
    return rows[column].to_numpy(dtype=np.float64)


def angles(table: pd.DataFrame) -> list[int]:
    """The table's angles [deg], increasing."""
    return sorted(int(a) for a in table["angle [deg]"].unique())


def values(table: pd.DataFrame, config: str, column: str) -> str:
    """``column`` of ``config`` at the three angles, "a / b / c"."""
    rows = table[table["configuration"] == config].sort_values("angle [deg]")
    return " / ".join(f"{v:.3g}" if abs(v) < 1000 else f"{v:.0f}" for v in rows[column])


def ratio(table: pd.DataFrame, config: str, column: str) -> str:
    """``column`` of ``config`` over the measured one at the three angles, "a / b / c"."""
    a, m = series(table, config, column), series(table, MEASURED, column)
    return " / ".join(f"{x:.2f}" for x in a / m)


def listed(items: list[str], last: str = "and") -> str:
    """ "a", "a and b", "a, b and c" (``last``: the last joint)."""
    return items[0] if len(items) == 1 else f"{', '.join(items[:-1])} {last} {items[-1]}"


def at(chosen: list[int], every: int) -> str:
    """ "at every angle" when ``chosen`` holds all ``every`` angles, else "at 20 and 70 deg"."""
    if len(chosen) == every:
        return "at every angle"
    return f"at {listed([str(a) for a in chosen])} deg"


def _kind(factor: float, none: float, large: float) -> str:
    """One angle's change of the dent: "none", "shallower", "much deeper", ... or "unknown"
    (no number); ``factor`` the dent without the effect over the dent with it."""
    if not math.isfinite(factor) or factor <= 0.0:
        return "unknown"
    if abs(factor - 1.0) <= none * (1.0 + 1e-9):
        return "none"
    way = "shallower" if factor > 1.0 else "deeper"
    return f"much {way}" if abs(math.log(factor)) >= math.log(large) * (1.0 - 1e-9) else way


def dent_effect(factor: np.ndarray, chosen: list[int], none: float, large: float) -> str:
    """What the effects do to the dent, after "Rod flexibility and rate sensitivity": "are real
    and large effects that make the dent shallower at every angle", "leave the dent depth
    within 10 % of the rigid rod's at every angle" or, angle by angle, "make the dent much
    shallower at 20 and 45 deg, and leave it within 10 % of the rigid rod's at 70 deg".
    ``factor``: the dent without the effects over the dent with them, at the angles ``chosen``
    [deg]; ``none``: the relative change within which there is no effect; ``large``: the
    smallest factor (or its inverse) of a large effect."""
    kinds = [_kind(float(f), none, large) for f in factor]
    every, within = len(chosen), f"within {none * 100:g} % of the rigid rod's"
    if len(set(kinds)) == 1 and kinds[0] not in ("none", "unknown"):
        size = "real and large effects" if kinds[0].startswith("much") else "real effects"
        return f"are {size} that make the dent {kinds[0].split()[-1]} at every angle"
    groups = {k: [a for a, j in zip(chosen, kinds, strict=True) if j == k] for k in kinds}
    changes = [f"{k} {at(a, every)}" for k, a in groups.items() if k not in ("none", "unknown")]
    clauses = [f"make the dent {listed(changes)}"] if changes else []
    if "none" in groups:
        it = "it" if changes else "the dent depth"
        clauses.append(f"leave {it} {within} {at(groups['none'], every)}")
    if "unknown" in groups:
        clauses.append(f"have no dent to compare {at(groups['unknown'], every)}")
    return clauses[0] if len(clauses) == 1 else f"{', '.join(clauses[:-1])}, and {clauses[-1]}"
