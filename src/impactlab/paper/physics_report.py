"""The report section "Can physics explain the experiment?" (blocks of
:mod:`impactlab.paper.report`), from the table of :func:`impactlab.paper.physics.physics_table`.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd

from impactlab.paper.calibration_report import PAPER_SIGMAS
from impactlab.paper.physics import (
    CONFIGURATIONS,
    E_COLUMN,
    E_DEFINITION,
    FE_TABULATED,
    FRICTION,
    LAW,
    MEASURED,
    ROWS,
    SCAR_COLUMN,
)
from impactlab.paper.physics_words import angles as _angles
from impactlab.paper.physics_words import at as _at
from impactlab.paper.physics_words import dent_effect
from impactlab.paper.physics_words import listed as _listed
from impactlab.paper.physics_words import ratio as _ratio
from impactlab.paper.physics_words import series as _series
from impactlab.paper.physics_words import values as _values
from impactlab.paper.quantities import reference_of
from impactlab.paper.report import Block, Bullets, Figure, Heading, Para, Table

#: The compared columns of e and of the mark's extent (``physics.E_COLUMN``, ``SCAR_COLUMN``).
E, SCAR = E_COLUMN, SCAR_COLUMN

__all__ = ["LARGE_EFFECT", "PILE_UP_ANGLE", "TOLERANCES", "physics_section"]


def _shown(table: pd.DataFrame) -> pd.DataFrame:
    """The table for the report: the contact counts as integers, a dash where none."""
    shown = table.copy()
    counts = [None if pd.isna(v) else int(v) for v in table["contacts"]]
    shown["contacts"] = pd.Series(counts, index=table.index, dtype=object)
    return shown


#: Within how much of a measured value a simulated one explains it, by column (tolerance,
#: relative): the standard uncertainties the calibration of the next section assumes
#: (``PAPER_SIGMAS``: e absolute, delta_p and L_s relative) and, for T, which it does not use
#: (the measured T is inferred from the dent), the lengths' relative one. Not tuned to the table.
TOLERANCES: dict[str, tuple[float, bool]] = {
    "delta_p [um]": (PAPER_SIGMAS["delta_p"], True),
    E: (PAPER_SIGMAS["e"], False),
    SCAR: (PAPER_SIGMAS["scar_length"], True),
    "T [ms]": (PAPER_SIGMAS["scar_length"], True),
}
#: Each compared column in the sentences.
NOUNS = {
    "delta_p [um]": "the dent depth",
    E: "e",
    SCAR: "the scar",
    "T [ms]": "the duration",
}
#: The smallest ratio of the rigid rod's dent to the flexible rod's on the rate-dependent flat,
#: or of its inverse, for which the section calls the effect on the dent at an angle large
#: (much shallower or much deeper): five times the dent's assumed relative uncertainty beyond
#: 1. Within that uncertainty (``TOLERANCES``) of 1 it calls it none.
LARGE_EFFECT = 1.0 + 5.0 * PAPER_SIGMAS["delta_p"]
#: The drop the paper explains by a pile-up that no contact law models.
PILE_UP_ANGLE = 70


def _closeness(table: pd.DataFrame, column: str) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Per angle the measured ``column``, the nearest value of the flexible rod on the plain
    or the rate-dependent flat (``CONFIGURATIONS``) and whether it lies within its tolerance."""
    tol, relative = TOLERANCES[column]
    measured = _series(table, MEASURED, column)
    values = np.stack([_series(table, c.name, column) for c in CONFIGURATIONS if c.flexible])
    off = np.abs(values / measured - 1.0) if relative else np.abs(values - measured)
    pick = (np.argmin(np.where(np.isnan(off), np.inf, off), axis=0), np.arange(values.shape[1]))
    return measured, values[pick], off[pick] <= tol * (1.0 + 1e-9)


def _off(column: str, measured: np.ndarray, near: np.ndarray) -> str:
    """How far ``near`` lies from ``measured``: "1.55 times the measured one" (a relative
    tolerance) or "0.724 / 0.602 against 0.5 / 0.49"."""
    if TOLERANCES[column][1]:
        return f"{' / '.join(f'{r:.3g}' for r in near / measured)} times the measured one"
    ours, theirs = (" / ".join(f"{v:.3g}" for v in x) for x in (near, measured))
    return f"{ours} against the measured {theirs}"


def _verdict(table: pd.DataFrame, column: str) -> tuple[list[int], list[int], str]:
    """The angles at which flexibility and rate dependence explain ``column`` (within its
    tolerance), those at which they do not, and how far the nearest value lies at the latter."""
    measured, near, close = _closeness(table, column)
    angles = _angles(table)
    ok = [a for a, c in zip(angles, close, strict=True) if c]
    bad = [a for a, c in zip(angles, close, strict=True) if not c]
    return ok, bad, _off(column, measured[~close], near[~close])


def _sentence(table: pd.DataFrame, column: str) -> tuple[str, bool]:
    """Whether flexibility and rate dependence explain ``column``, in one sentence, and True
    when they do at one angle at least."""
    ok, bad, miss = _verdict(table, column)
    every, what = len(ok) + len(bad), NOUNS[column]
    within = f"within {_tol(column)}"
    who = "Flexibility and rate dependence"
    if not bad:
        return f"{who} explain {what} {_at(ok, every)} ({within}).", True
    if not ok:
        return f"{who} do not explain {what} at any angle (none {within}; nearest: {miss}).", False
    return (
        f"{who} explain {what} {_at(ok, every)} ({within}), not {_at(bad, every)} ({miss}).",
        True,
    )


def _direction(table: pd.DataFrame, column: str) -> str:
    """Which way the flexible rod moves ``column`` from the rigid rod's, by angle: "raises e at
    20 and 45 deg and lowers it at 70 deg"."""
    rigid, flex = (c.name for c in CONFIGURATIONS[:2])
    up = _series(table, flex, column) > _series(table, rigid, column)
    angles = _angles(table)
    parts: list[str] = []
    for word, way in (("raises", True), ("lowers", False)):
        at = [a for a, u in zip(angles, up, strict=True) if u == way]
        if at:
            parts.append(f"{word} {'it' if parts else NOUNS[column]} {_at(at, len(angles))}")
    return " and ".join(parts)


def _findings(table: pd.DataFrame) -> list[Block]:
    rigid, flex, rate = (c.name for c in CONFIGURATIONS)

    def v(config: str, column: str) -> str:
        return _values(table, config, column)

    scar_growth = _series(table, flex, SCAR) / _series(table, rigid, SCAR)
    bullets = [
        _rings(table),
        _with(
            f"Dent depths: on the rate-dependent flat (self-consistent factor "
            f"{v(rate, 'rate factor')}) the flexible rod leaves {v(rate, 'delta_p [um]')} um "
            f"against the measured {v(MEASURED, 'delta_p [um]')} um (rigid rod "
            f"{v(rigid, 'delta_p [um]')} um): {_ratio(table, rate, 'delta_p [um]')} times the "
            "measured depth.",
            _sentence(table, "delta_p [um]"),
        ),
        _with(
            f"e: measured {v(MEASURED, E)}; rigid {v(rigid, E)}, flexible {v(flex, E)}, "
            f"flexible + rate {v(rate, E)}. The flexible rod {_direction(table, E)}.",
            _sentence(table, E),
        ),
        _with(
            f"Scar: L_s {v(MEASURED, SCAR)} um measured against {v(flex, SCAR)} um "
            f"(flexible; {' / '.join(f'{r:.3g}' for r in scar_growth)} times the rigid rod's "
            "scar).",
            _sentence(table, SCAR),
        ),
        _with(
            f"Duration: T {v(MEASURED, 'T [ms]')} ms (from the dent) against {v(flex, 'T [ms]')} "
            "ms (flexible).",
            _sentence(table, "T [ms]"),
        ),
        *_pile_up(table),
    ]
    explained = tuple(text for text, ok in bullets if ok)
    not_explained = tuple(text for text, ok in bullets if not ok)
    intro = (
        "What flexibility and rate dependence explain (at an angle where the flexible rod, "
        "on the plain or the rate-dependent flat, comes within the uncertainty the next "
        f"section's calibration assumes: e +- {_tol(E)}, delta_p and L_s +- "
        f"{_tol('delta_p [um]')}; T, which it does not use, +- {_tol('T [ms]')}; the contacts: "
        "where it touches the flat again):"
    )
    blocks: list[Block] = [Para(f"{intro} nothing at any angle.")]
    if explained:
        blocks = [Para(intro), Bullets(explained)]
    if not_explained:
        blocks += [Para("What they do not explain:"), Bullets(not_explained)]
    return [*blocks, *_fe_row(table)]


def _tol(column: str) -> str:
    """The tolerance of ``column`` in words: "10 %" or "0.03"."""
    tol, relative = TOLERANCES[column]
    return f"{tol * 100:g} %" if relative else f"{tol:g}"


def _with(text: str, verdict: tuple[str, bool]) -> tuple[str, bool]:
    """A bullet's ``text`` followed by its verdict's sentence, and whether it explains."""
    return f"{text} {verdict[0]}", verdict[1]


def _pile_up(table: pd.DataFrame) -> list[tuple[str, bool]]:
    """The bullet of the drop the paper explains by a pile-up (none without that drop): the
    flexible rod's scar and e there, against the measured ones, and whether flexibility and
    rate dependence explain both (then no pile-up is needed), one or neither there."""
    at = table[table["angle [deg]"] == PILE_UP_ANGLE]
    if at.empty:
        return []
    rigid, flex = (c.name for c in CONFIGURATIONS[:2])

    def x(config: str, column: str) -> float:
        return float(at.loc[at["configuration"] == config, column].iloc[0])

    scar, e = x(MEASURED, SCAR), x(MEASURED, E)
    i = _angles(table).index(PILE_UP_ANGLE)
    near: dict[str, str] = {}  # the explained columns: the nearest value there, in words
    for column in (E, SCAR):
        measured, nearest, close = _closeness(table, column)
        if close[i]:
            m, n = measured[i], nearest[i]
            how = f"{n / m:.3g} times the measured one" if TOLERANCES[column][1] else f"{n:.3g}"
            near[column] = f"{how}, within {_tol(column)}"
    pile_up = "a pile-up that no contact law models"
    if len(near) == 2:
        both = "; ".join(f"{NOUNS[c]} {how}" for c, how in near.items())
        verdict = f"flexibility and rate dependence explain both ({both}) with no pile-up"
    elif near:
        [(column, how)] = near.items()
        other = SCAR if column == E else E
        verdict = (
            f"flexibility and rate dependence explain {NOUNS[column]} there ({how}) but not "
            f"{NOUNS[other]}, for which the paper points at {pile_up}"
        )
    else:
        verdict = f"the paper points at {pile_up}"
    return [
        (
            f"The {PILE_UP_ANGLE} deg case: the flexible rod's scar is "
            f"{x(flex, SCAR) / scar:.3g} times the measured {scar:.3g} um (the rigid "
            f"rod's {x(rigid, SCAR) / scar:.3g} times) and its e {x(flex, E):.3g} "
            f"against the measured {e:.3g}; {verdict}.",
            len(near) == 2,
        )
    ]


def _rings(table: pd.DataFrame) -> tuple[str, bool]:
    """The bullet of the flexible rod's contacts against the rigid rod's, and whether it is
    explained: the flexible rod touches the flat again (rings) at one angle at least."""
    rigid, flex = (c.name for c in CONFIGURATIONS[:2])

    def v(config: str, column: str) -> str:
        return _values(table, config, column)

    every, n = _angles(table), _series(table, flex, "contacts")
    again = [a for a, k in zip(every, n > 1, strict=True) if k]
    once = [a for a, k in zip(every, n == 1, strict=True) if k]
    theirs = f"{v(rigid, 'contacts')} contacts over {v(rigid, 'T [ms]')} ms"
    if (_series(table, rigid, "contacts") == 1).all():
        theirs = f"one contact of {v(rigid, 'T [ms]')} ms"
    ours = f"{v(flex, 'contacts')} contacts over {v(flex, 'T [ms]')} ms"
    if not again:
        head = f"The flexible rod does not touch the flat again: {ours} against the rigid rod's"
    elif once:
        head = (
            f"The flexible rod rings and touches the flat again {_at(again, len(every))} (once "
            f"{_at(once, len(every))}): {ours} instead of the rigid rod's"
        )
    else:  # the rigid rod's single contact: "instead of one contact of ..."
        head = f"The flexible rod rings and touches the flat again: {ours} instead of"
        head += "" if theirs.startswith("one") else " the rigid rod's"
    f_flex, f_rigid = (_series(table, c, "F_max [N]") for c in (flex, rigid))
    way = "falls" if (f_flex < f_rigid).all() else "rises" if (f_flex > f_rigid).all() else "goes"
    return (
        f"{head} {theirs}; the largest force {way} from {v(rigid, 'F_max [N]')} N to "
        f"{v(flex, 'F_max [N]')} N.",
        bool(again),
    )


def _closing(table: pd.DataFrame) -> Para:
    """The section's conclusion: how large the effects are, what they explain and where."""
    rigid, rate = CONFIGURATIONS[0].name, CONFIGURATIONS[2].name
    factor = _series(table, rigid, "delta_p [um]") / _series(table, rate, "delta_p [um]")
    none = TOLERANCES["delta_p [um]"][0]
    effect = dent_effect(factor, _angles(table), none, LARGE_EFFECT)
    explained: list[str] = []
    missed: list[str] = []
    for column in TOLERANCES:
        ok, bad, miss = _verdict(table, column)
        every = len(ok) + len(bad)
        if not ok:
            missed.append(NOUNS[column])
        else:
            where = f" (not {_at(bad, every)}: {miss})" if bad else ""
            explained.append(f"{NOUNS[column]} {_at(ok, every)}{where}")
    said = [f"they explain {_listed(explained)}"] if explained else []
    if missed:
        said.append(f"they do not explain {_listed(missed, 'or')} at any angle")
    return Para(
        f"Rod flexibility and rate sensitivity {effect} (the rigid rod's dent is "
        f"{' / '.join(f'{r:.3g}' for r in factor)} times the flexible rod's on the "
        f"rate-dependent flat): {', but '.join(said)}."
    )


def _fe_row(table: pd.DataFrame) -> list[Block]:
    """What the FE-tabulated row (hardening flat) gives, in numbers (none if it was not run)."""
    fe, flex = FE_TABULATED.name, CONFIGURATIONS[1].name
    if not (table["configuration"] == fe).any():
        return []

    def v(config: str, column: str) -> str:
        return _values(table, config, column)

    return [
        Para(
            "The flexible rod with the FE-tabulated law of a strain-hardening flat (AISI 1010's "
            "own hardening, a Swift law derived from SAE J1397's cold-drawn yield and tensile "
            f"strength; nothing tuned, rate-independent): delta_p {v(fe, 'delta_p [um]')} um, "
            f"{_ratio(table, fe, 'delta_p [um]')} times the measured depth (flexible rod with "
            f"the {LAW!r} law: {v(flex, 'delta_p [um]')} um); e {v(fe, E)} against the "
            f"measured {v(MEASURED, E)}; L_s {v(fe, SCAR)} um; {v(fe, 'contacts')} "
            f"contacts; F_max {v(fe, 'F_max [N]')} N (20 / 45 / 70 deg)."
        )
    ]


def physics_section(
    table: pd.DataFrame | None, figures: Mapping[str, str], number: int
) -> list[Block]:
    """The section's blocks, headed ``number``; none when the simulations were not run
    (``table`` None)."""
    if table is None:
        return []
    configs = tuple(f"{c.name}: {c.description}" for c in ROWS)
    B: list[Block] = [
        Heading(f"{number}. Can physics explain the experiment?"),
        Para(
            "Nothing tuned: every configuration uses the paper's rod, flat (AISI 1010), drop "
            f"velocity and measured mu (as the local coefficient of the {FRICTION!r} model), the "
            f"{LAW!r} law with "
            "impactlab's defaults (the last row: the FE-tabulated law instead), gravity on and "
            "no structural damping (the next section "
            "calibrates the damping). The measured row's T is not measured: it is the "
            "inversion of the measured drop (Eq. 12 from the dent, Section 3). "
            f"{SCAR} is the extent of the mark the "
            "tip left, as a scan measures it (the measured L_s): |contact_travel| for "
            "the rigid rod, not the signed slip (sliding_length, Section 4's L_s [um]), and "
            "scar_length (x-extent of the tip's contact path over all contacts) for the "
            "flexible rod; T is first touch to last separation; "
            f"{E}: {E_DEFINITION} (not the impact's e of Section 4). The model and its "
            "verification: docs/flexible.md."
        ),
        Bullets(configs),
        Table(
            _shown(table),
            "Measured vs rigid, flexible, flexible + rate-dependent and flexible + FE-tabulated "
            "(hardening flat)",
            digits=4,
        ),
        *_findings(table),
        _closing(table),
    ]
    if "physics_drop_20" in figures:
        B.append(
            Figure(
                figures["physics_drop_20"],
                "Flexible rod, 20 deg: contact forces on the tip, tip height and tip trajectory "
                "over the whole contact sequence (grey: contacts)" + _drop_flag(table),
            )
        )
    return B


def _drop_flag(table: pd.DataFrame) -> str:
    """The caption's mark when the figure's drop (flexible rod, 20 deg) left its law's verified
    range: ``; extrapolated: 43 delta_c (LAW_EXTRAPOLATED)``; ``""`` otherwise."""
    rows = table[(table["configuration"] == CONFIGURATIONS[1].name) & (table["angle [deg]"] == 20)]
    if rows.empty or "LAW_EXTRAPOLATED" not in str(rows.iloc[0]["flags"]):
        return ""
    ratio = float(rows.iloc[0]["max_delta_ratio"])
    return f"; extrapolated: {ratio:.0f} {reference_of(LAW)} (LAW_EXTRAPOLATED)"
