"""Wording helpers of the section "Can physics explain the experiment?"
(:mod:`impactlab.paper.physics_report`): a configuration's numbers by angle, lists of angles,
the size and direction of the change in the dent depth, the verdicts (what the flexible rod
explains, within which tolerance and under which rate law), the bullet of the contacts, the
paragraph on friction (each row's Eq. 28 mu) and the figure's mark of an extrapolated drop."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from impactlab.paper.calibration_run import PAPER_SIGMAS
from impactlab.paper.physics import (
    CONFIGURATIONS,
    E_COLUMN,
    FE_TABULATED,
    LAW,
    MEASURED,
    MU_COLUMN,
    RATE_LOWER,
    SCAR_COLUMN,
    SEQUENCE_COLUMN,
    T_COLUMN,
)
from impactlab.paper.quantities import reference_of

#: The compared columns of e, the mark's extent and Eq. 12's T (``physics.E_COLUMN``, ...).
E, SCAR, T = E_COLUMN, SCAR_COLUMN, T_COLUMN
#: The rigid rod, the flexible rod and the flexible rod on the Cowper-Symonds flat (upper
#: estimate of the rate effect), and on the Johnson-Cook flat (lower estimate).
RIGID, FLEX, RATE = (c.name for c in CONFIGURATIONS)
LOWER = RATE_LOWER.name
#: The rows whose verdicts the section draws, and how a verdict names each.
WITH = {
    FLEX: "without rate dependence",
    RATE: "with the upper estimate of the rate constants (Cowper-Symonds)",
    LOWER: "with the lower estimate of the rate constants (Johnson-Cook)",
}


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


#: Within how much of a measured value a simulated one explains it, by column (tolerance,
#: relative): the standard uncertainties the calibration of the next section assumes
#: (``PAPER_SIGMAS``: e absolute, delta_p and L_s relative) and, for T, which it does not use
#: (Eq. 12's, from the dent and scar), the lengths' relative one. Not tuned to the table.
TOLERANCES: dict[str, tuple[float, bool]] = {
    "delta_p [um]": (PAPER_SIGMAS["delta_p"], True),
    E: (PAPER_SIGMAS["e"], False),
    SCAR: (PAPER_SIGMAS["scar_length"], True),
    T: (PAPER_SIGMAS["scar_length"], True),
}
#: Each compared column in the sentences.
NOUNS = {
    "delta_p [um]": "the dent depth",
    E: "e",
    SCAR: "the scar",
    T: "the duration",
}


def present(table: pd.DataFrame) -> tuple[str, ...]:
    """The rows of :data:`WITH` that ``table`` holds, in that order."""
    return tuple(n for n in WITH if (table["configuration"] == n).any())


def distances(table: pd.DataFrame, column: str) -> tuple[np.ndarray, dict[str, np.ndarray]]:
    """Per angle the measured ``column`` and, by row of :func:`present`, its distance from it
    (relative or absolute, as its tolerance; NaN where the row has no number)."""
    relative = TOLERANCES[column][1]
    measured = series(table, MEASURED, column)
    out: dict[str, np.ndarray] = {}
    for name in present(table):
        v = series(table, name, column)
        out[name] = np.abs(v / measured - 1.0) if relative else np.abs(v - measured)
    return measured, out


def inside(off: np.ndarray, column: str) -> np.ndarray:
    """Where a distance ``off`` lies within ``column``'s tolerance (NaN: not)."""
    return np.asarray(off <= TOLERANCES[column][0] * (1.0 + 1e-9))


def closeness(table: pd.DataFrame, column: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per angle the measured ``column``, the nearest value of the flexible rod on the plain
    flat or a rate-dependent one (either estimate; :data:`WITH`) and whether it lies within
    its tolerance."""
    measured, offs = distances(table, column)
    values = np.stack([series(table, n, column) for n in offs])
    off = np.stack(list(offs.values()))
    pick = (np.argmin(np.where(np.isnan(off), np.inf, off), axis=0), np.arange(values.shape[1]))
    return measured, values[pick], inside(off[pick], column)


def only_with(rows: tuple[str, ...], shown: tuple[str, ...]) -> str:
    """Which of the ``shown`` rows (of :data:`WITH`) explain, when not all: " only with the
    upper estimate of the rate constants (Cowper-Symonds)"; ``""`` when each does."""
    if set(rows) == set(shown):
        return ""
    if set(rows) == {RATE, LOWER}:
        return " only with rate dependence (either estimate of its constants)"
    return " only " + listed([WITH[r] for r in rows], "or")


def which(table: pd.DataFrame, column: str, ok: list[int]) -> str:
    """Under which rate law the flexible rod explains ``column`` at the angles ``ok``: ``""``
    where each row of :data:`WITH` does, " only with ..." where some do, and angle by angle,
    " (at 20 deg only ...; at 70 deg ...)", where that differs between them."""
    _m, offs = distances(table, column)
    every = angles(table)
    groups: dict[tuple[str, ...], list[int]] = {}
    for i, a in enumerate(every):
        if a in ok:
            rows = tuple(n for n, off in offs.items() if inside(off[i], column))
            groups.setdefault(rows, []).append(a)
    if len(groups) == 1:
        return only_with(next(iter(groups)), tuple(offs))
    parts = [
        f"{at(a, len(every))}{only_with(r, tuple(offs)) or ' with each'}" for r, a in groups.items()
    ]
    return f" ({'; '.join(parts)})"


def nowhere(table: pd.DataFrame, column: str) -> str:
    """The sentences of the rate laws under which the flexible rod explains ``column`` at no
    angle: " With the lower estimate of the rate constants (Johnson-Cook) they explain it at
    no angle (1.43 / 2.11 / 1.48 times the measured one)."."""
    measured, offs = distances(table, column)
    out = ""
    for name in (RATE, LOWER):
        if name in offs and not inside(offs[name], column).any():
            how = off_text(column, measured, series(table, name, column))
            said = WITH[name][0].upper() + WITH[name][1:]
            out += f" {said} they explain it at no angle ({how})."
    return out


def off_text(column: str, measured: np.ndarray, near: np.ndarray) -> str:
    """How far ``near`` lies from ``measured``: "1.55 times the measured one" (a relative
    tolerance) or "0.724 / 0.602 against 0.5 / 0.49"."""
    if TOLERANCES[column][1]:
        return f"{' / '.join(f'{r:.3g}' for r in near / measured)} times the measured one"
    ours, theirs = (" / ".join(f"{v:.3g}" for v in x) for x in (near, measured))
    return f"{ours} against the measured {theirs}"


def verdict(table: pd.DataFrame, column: str) -> tuple[list[int], list[int], str]:
    """The angles at which flexibility and rate dependence explain ``column`` (within its
    tolerance), those at which they do not, and how far the nearest value lies at the latter."""
    measured, near, close = closeness(table, column)
    every = angles(table)
    ok = [a for a, c in zip(every, close, strict=True) if c]
    bad = [a for a, c in zip(every, close, strict=True) if not c]
    return ok, bad, off_text(column, measured[~close], near[~close])


def sentence(table: pd.DataFrame, column: str) -> tuple[str, bool]:
    """Whether flexibility and rate dependence explain ``column`` and under which rate law, in
    words, and True when they do at one angle at least."""
    ok, bad, miss = verdict(table, column)
    every, what = len(ok) + len(bad), NOUNS[column]
    within = f"within {tol(column)}"
    who = "Flexibility and rate dependence"
    if not ok:
        return f"{who} do not explain {what} at any angle (none {within}; nearest: {miss}).", False
    head = f"{who} explain {what} {at(ok, every)} ({within}){which(table, column, ok)}"
    if bad:
        head += f", not {at(bad, every)} ({miss})"
    return f"{head}.{nowhere(table, column)}", True


def tol(column: str) -> str:
    """The tolerance of ``column`` in words: "10 %" or "0.03"."""
    tol, relative = TOLERANCES[column]
    return f"{tol * 100:g} %" if relative else f"{tol:g}"


def rings(table: pd.DataFrame) -> tuple[str, bool]:
    """The bullet of the flexible rod's contacts against the rigid rod's (over the sequence's
    duration, first touch to last separation), and whether it is explained: the flexible rod
    touches the flat again (rings) at one angle at least."""
    rigid, flex = (c.name for c in CONFIGURATIONS[:2])
    seq = SEQUENCE_COLUMN

    def v(config: str, column: str) -> str:
        return values(table, config, column)

    every, n = angles(table), series(table, flex, "contacts")
    again = [a for a, k in zip(every, n > 1, strict=True) if k]
    once = [a for a, k in zip(every, n == 1, strict=True) if k]
    theirs = f"{v(rigid, 'contacts')} contacts over {v(rigid, seq)} ms"
    if (series(table, rigid, "contacts") == 1).all():
        theirs = f"one contact of {v(rigid, seq)} ms"
    ours = f"{v(flex, 'contacts')} contacts over {v(flex, seq)} ms"
    if not again:
        head = f"The flexible rod does not touch the flat again: {ours} against the rigid rod's"
    elif once:
        head = (
            f"The flexible rod rings and touches the flat again {at(again, len(every))} (once "
            f"{at(once, len(every))}): {ours} instead of the rigid rod's"
        )
    else:  # the rigid rod's single contact: "instead of one contact of ..."
        head = f"The flexible rod rings and touches the flat again: {ours} instead of"
        head += "" if theirs.startswith("one") else " the rigid rod's"
    f_flex, f_rigid = (series(table, c, "F_max [N]") for c in (flex, rigid))
    way = "falls" if (f_flex < f_rigid).all() else "rises" if (f_flex > f_rigid).all() else "goes"
    return (
        f"{head} {theirs}; the largest force {way} from {v(rigid, 'F_max [N]')} N to "
        f"{v(flex, 'F_max [N]')} N.",
        bool(again),
    )


#: How the paragraph on friction names each flexible row.
FLEXIBLE_ROWS = {
    FLEX: "flexible rod",
    RATE: "on the Cowper-Symonds flat",
    LOWER: "on the Johnson-Cook flat",
    FE_TABULATED.name: "with the FE-tabulated law",
}


def friction(table: pd.DataFrame) -> str:
    """The paragraph on mu: the measured one (the paper's Eq. 28), every simulated row's local
    Coulomb coefficient, beside each row's own Eq. 28 mu (``MU_COLUMN``), and what the flexible
    rows' lower one means."""
    mu, shown = MU_COLUMN, [n for n in FLEXIBLE_ROWS if (table["configuration"] == n).any()]
    own = "; ".join(f"{FLEXIBLE_ROWS[n]} {values(table, n, mu)}" for n in shown)
    return (
        f"Friction: the measured mu, {values(table, MEASURED, mu)}, is the paper's Eq. 28 on the "
        "measured velocities, and every simulated row takes it as the local Coulomb "
        f"coefficient at the tip. {mu} is the same Eq. 28 on each simulated drop's rigid-body "
        "velocities, gravity removed: the tangential over the normal impulse. Coulomb friction, "
        "never above mu times the normal force, gives mu back only where the tip slides one "
        f"way throughout, as the rigid rod's tip does ({values(table, RIGID, mu)}), and less where "
        f"it sticks or its slip turns, as in the flexible rod's re-contacts: {own} "
        f"({ratio(table, FLEX, mu)} times the measured mu for the flexible rod). So the "
        "flexible rows do not reproduce the measured mu they take as input. Nothing is tuned "
        "to it: docs/flexible.md gives these rows with the local coefficient raised until Eq. "
        "28 returns the measured mu, and no verdict of this section changes."
    )


def drop_flag(table: pd.DataFrame) -> str:
    """The caption's mark when the figure's drop (flexible rod, 20 deg) left its law's verified
    range: ``; extrapolated: 43 delta_c (LAW_EXTRAPOLATED)``; ``""`` otherwise."""
    rows = table[(table["configuration"] == CONFIGURATIONS[1].name) & (table["angle [deg]"] == 20)]
    if rows.empty or "LAW_EXTRAPOLATED" not in str(rows.iloc[0]["flags"]):
        return ""
    ratio = float(rows.iloc[0]["max_delta_ratio"])
    return f"; extrapolated: {ratio:.0f} {reference_of(LAW)} (LAW_EXTRAPOLATED)"


#: Each compared column's quantity in the calibration's predictive check (its ``checks``).
CALIBRATED = {"delta_p [um]": "delta_p [um]", E: "e", SCAR: "scar_length [um]"}


def damped(calibration: Mapping[str, Any], columns: list[str], every: int) -> str:
    """What the next section's calibration (``calibration``: its shipped summary) says of the
    ``columns`` that the undamped rows explain at no angle: where a configuration with a
    fitted damping ratio comes, at its best fit (highest-posterior zeta), within the same
    tolerance (``TOLERANCES``); ``every``: how many angles the section compares."""
    fitted = {
        str(r["configuration"])
        for r in calibration.get("ranking", ())
        if r.get("zeta median") is not None
    }
    parts = []
    for column in columns:
        if column not in CALIBRATED:
            parts.append(f"{NOUNS[column]} is not among its measurements")
            continue
        tol_, relative = TOLERANCES[column]
        near: dict[int, tuple[float, str, float]] = {}  # angle -> (off, configuration, best)
        measured: dict[int, float] = {}
        for r in calibration.get("checks", ()):
            if r["quantity"] != CALIBRATED[column] or r["configuration"] not in fitted:
                continue
            ang, m, best = int(str(r["drop"]).split()[0]), float(r["measured"]), r["best fit"]
            if best is None or not math.isfinite(float(best)):
                continue
            off = abs(float(best) / m - 1.0) if relative else abs(float(best) - m)
            measured[ang] = m
            if ang not in near or off < near[ang][0]:
                near[ang] = (off, str(r["configuration"]), float(best))
        ok = sorted(a for a, (off, _c, _b) in near.items() if off <= tol_ * (1.0 + 1e-9))
        if not ok:
            parts.append(f"{NOUNS[column]} comes within {tol(column)} at no angle")
            continue
        best = "; ".join(
            f"{near[a][1]}: {_shown(near[a][2])} against the measured {_shown(measured[a])}"
            for a in ok
        )
        bad = sorted(set(near) - set(ok))
        parts.append(
            f"{NOUNS[column]} comes within {tol(column)} {at(ok, every)} ({best})"
            + (f", not {at(bad, every)}" if bad else "")
        )
    return (
        "With the damping ratio the next section fits (its best fits, column 'best fit'): "
        + "; ".join(parts)
        + "."
    )


def _shown(v: float) -> str:
    """A value as the section prints it: 3 significant digits, whole numbers from 1000 on."""
    return f"{v:.3g}" if abs(v) < 1000 else f"{v:.0f}"
