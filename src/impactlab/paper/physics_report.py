"""The report section "Can physics explain the experiment?" (blocks of
:mod:`impactlab.paper.report`), from the table of :func:`impactlab.paper.physics.physics_table`.
Each verdict says under which rate law it holds: without rate dependence, with the upper
estimate of the rate constants (Cowper-Symonds) or with the lower (Johnson-Cook).
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import pandas as pd

from impactlab.paper.calibration_run import PAPER_SIGMAS
from impactlab.paper.physics import (
    CONTACT_TIME_COLUMN,
    DELTA_C_COLUMN,
    E_DEFINITION,
    FE_TABULATED,
    FRICTION,
    LAW,
    LIMIT_COLUMN,
    MEASURED,
    MU_COLUMN,
    SEQUENCE_COLUMN,
    TABLE_ROWS,
)
from impactlab.paper.physics_words import (
    FLEX,
    LOWER,
    NOUNS,
    RATE,
    RIGID,
    SCAR,
    TOLERANCES,
    E,
    T,
    closeness,
    damped,
    dent_effect,
    drop_flag,
    friction,
    present,
    rings,
    sentence,
    tol,
    verdict,
    which,
)
from impactlab.paper.physics_words import angles as _angles
from impactlab.paper.physics_words import at as _at
from impactlab.paper.physics_words import listed as _listed
from impactlab.paper.physics_words import ratio as _ratio
from impactlab.paper.physics_words import series as _series
from impactlab.paper.physics_words import values as _values
from impactlab.paper.report import Block, Bullets, Figure, Heading, Para, Table

__all__ = ["LARGE_EFFECT", "PILE_UP_ANGLE", "STICKING_ANGLE", "TOLERANCES", "physics_section"]


def _shown(table: pd.DataFrame) -> pd.DataFrame:
    """The table for the report: the contact counts as integers, a dash where none."""
    shown = table.copy()
    counts = [None if pd.isna(v) else int(v) for v in table["contacts"]]
    shown["contacts"] = pd.Series(counts, index=table.index, dtype=object)
    return shown


#: The smallest ratio of the rigid rod's dent to the flexible rod's on the rate-dependent flat,
#: or of its inverse, for which the section calls the effect on the dent at an angle large
#: (much shallower or much deeper): five times the dent's assumed relative uncertainty beyond
#: 1. Within that uncertainty (``TOLERANCES``) of 1 it calls it none.
LARGE_EFFECT = 1.0 + 5.0 * PAPER_SIGMAS["delta_p"]
#: The drop the paper explains by a pile-up that no contact law models.
PILE_UP_ANGLE = 70
#: The drop the paper describes as sliding at first and sticking, rolling, at its end (Sec.
#: 5.1.3): outside Eq. 12's sliding throughout, so its measured row's T is an estimate only.
STICKING_ANGLE = 70


def _direction(table: pd.DataFrame, column: str) -> str:
    """Which way the flexible rod moves ``column`` from the rigid rod's, by angle: "raises e at
    20 and 45 deg and lowers it at 70 deg"."""
    up = _series(table, FLEX, column) > _series(table, RIGID, column)
    angles = _angles(table)
    parts: list[str] = []
    for word, way in (("raises", True), ("lowers", False)):
        at = [a for a, u in zip(angles, up, strict=True) if u == way]
        if at:
            parts.append(f"{word} {'it' if parts else NOUNS[column]} {_at(at, len(angles))}")
    return " and ".join(parts)


def _findings(table: pd.DataFrame) -> list[Block]:
    def v(config: str, column: str) -> str:
        return _values(table, config, column)

    lower = LOWER in present(table)
    dp, seq = "delta_p [um]", SEQUENCE_COLUMN
    lower_dent = lower_e = lower_ratio = ""
    if lower:
        lower_dent = (
            f" and {v(LOWER, dp)} um with the lower (Johnson-Cook, factor "
            f"{v(LOWER, 'rate factor')})"
        )
        lower_e, lower_ratio = f", {v(LOWER, E)} (lower)", f" and {_ratio(table, LOWER, dp)}"
    scar_growth = _series(table, FLEX, SCAR) / _series(table, RIGID, SCAR)
    bullets = [
        rings(table),
        _with(
            f"Dent depths: on a rate-dependent flat the flexible rod leaves {v(RATE, dp)} um "
            "with the upper estimate of the rate constants (Cowper-Symonds, self-consistent "
            f"factor {v(RATE, 'rate factor')}){lower_dent}, against the measured "
            f"{v(MEASURED, dp)} um (rigid rod {v(RIGID, dp)} um; flexible rod on the "
            f"rate-independent flat {v(FLEX, dp)} um): {_ratio(table, RATE, dp)}{lower_ratio} "
            "times the measured depth.",
            sentence(table, dp),
        ),
        _with(
            f"e: measured {v(MEASURED, E)}; rigid {v(RIGID, E)}, flexible {v(FLEX, E)}, "
            f"flexible + rate {v(RATE, E)} (upper estimate){lower_e}. The flexible rod "
            f"{_direction(table, E)}.",
            sentence(table, E),
        ),
        _with(
            f"Scar: L_s {v(MEASURED, SCAR)} um measured against {v(FLEX, SCAR)} um "
            f"(flexible; {' / '.join(f'{r:.3g}' for r in scar_growth)} times the rigid rod's "
            "scar).",
            sentence(table, SCAR),
        ),
        _with(
            f"Duration: T by Eq. 12 from each row's own dent and scar (like for like), "
            f"{v(MEASURED, T)} ms measured against {v(FLEX, T)} ms for the flexible rod, whose "
            f"sequence lasts {v(FLEX, seq)} ms from first touch to last separation "
            f"({v(FLEX, CONTACT_TIME_COLUMN)} ms of it in contact).{_sticking(table)}",
            sentence(table, T),
        ),
        *_pile_up(table),
    ]
    explained = tuple(text for text, ok in bullets if ok)
    not_explained = tuple(text for text, ok in bullets if not ok)
    intro = (
        "What flexibility and rate dependence explain (at an angle where the undamped "
        "flexible rod, zeta = 0, "
        "on the plain flat or a rate-dependent one, with either estimate of the rate constants, "
        "comes within the uncertainty the next section's calibration assumes: e +- "
        f"{tol(E)}, delta_p and L_s +- {tol('delta_p [um]')}; T, which it does not use, +- "
        f"{tol(T)}; the contacts: where it touches the flat again):"
    )
    blocks: list[Block] = [Para(f"{intro} nothing at any angle.")]
    if explained:
        blocks = [Para(intro), Bullets(explained)]
    if not_explained:
        blocks += [Para("What they do not explain:"), Bullets(not_explained)]
    return [*blocks, *_fe_row(table), Para(friction(table))]


def _sticking(table: pd.DataFrame) -> str:
    """The caveat of the measured T of the drop that slides, then sticks (none without it)."""
    if STICKING_ANGLE not in _angles(table):
        return ""
    T_70 = _series(table, MEASURED, T)[_angles(table).index(STICKING_ANGLE)]
    return (
        f" The measured {STICKING_ANGLE} deg T ({T_70:.3g} ms) is an estimate only: Eq. 12 "
        "assumes that the tip slides throughout, and the paper (Sec. 5.1.3) describes that "
        "impact as sliding at first and sticking, rolling, at its end."
    )


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
    rigid, flex = RIGID, FLEX

    def x(config: str, column: str) -> float:
        return float(at.loc[at["configuration"] == config, column].iloc[0])

    scar, e = x(MEASURED, SCAR), x(MEASURED, E)
    i = _angles(table).index(PILE_UP_ANGLE)
    near: dict[str, str] = {}  # the explained columns: the nearest value there, in words
    for column in (E, SCAR):
        measured, nearest, close = closeness(table, column)
        if close[i]:
            m, n = measured[i], nearest[i]
            how = f"{n / m:.3g} times the measured one" if TOLERANCES[column][1] else f"{n:.3g}"
            near[column] = f"{how}, within {tol(column)}"
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


def _closing(table: pd.DataFrame, calibration: Mapping[str, Any] | None = None) -> Para:
    """The section's conclusion, without damping (every row's zeta = 0): how large the effects
    are (with each estimate of the rate constants), what they explain, where and under which
    rate law; with ``calibration`` (the next section's summary), where its fitted damping
    brings what they explain at no angle within the same tolerance."""
    angles, dp = _angles(table), "delta_p [um]"
    rated = [n for n in (RATE, LOWER) if n in present(table)]
    factors = {n: _series(table, RIGID, dp) / _series(table, n, dp) for n in rated}
    none = TOLERANCES[dp][0]
    effects = {n: dent_effect(f, angles, none, LARGE_EFFECT) for n, f in factors.items()}
    effect = effects[RATE]
    if len(set(effects.values())) > 1:
        effect = f"{effects[RATE]} with the upper estimate of the rate constants, and "
        effect += f"{effects[LOWER]} with the lower"
    ratios = [" / ".join(f"{r:.3g}" for r in factors[n]) for n in rated]
    how = f"{ratios[0]} times the flexible rod's on the rate-dependent flat"
    if len(ratios) > 1:
        how += f" with the upper estimate, {ratios[1]} with the lower"
    explained: list[str] = []
    missed: list[str] = []
    missed_columns: list[str] = []
    for column in TOLERANCES:
        ok, bad, miss = verdict(table, column)
        every = len(ok) + len(bad)
        if not ok:
            missed.append(NOUNS[column])
            missed_columns.append(column)
        else:
            where = f" (not {_at(bad, every)}: {miss})" if bad else ""
            explained.append(f"{NOUNS[column]} {_at(ok, every)}{where}{which(table, column, ok)}")
    said = [f"they explain {_listed(explained)}"] if explained else []
    if missed:
        said.append(f"they do not explain {_listed(missed, 'or')} at any angle")
    after = ""
    if calibration is not None and missed_columns:
        after = " " + damped(calibration, missed_columns, len(angles))
    return Para(
        f"Rod flexibility and rate sensitivity {effect} (the rigid rod's dent is {how}): "
        f"without damping (zeta = 0 in every row), {', but '.join(said)}.{after}"
    )


def _fe_row(table: pd.DataFrame) -> list[Block]:
    """What the FE-tabulated row (hardening flat) gives, in numbers (none if it was not run)."""
    fe, flex = FE_TABULATED.name, FLEX
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
    table: pd.DataFrame | None,
    figures: Mapping[str, str],
    number: int,
    calibration: Mapping[str, Any] | None = None,
) -> list[Block]:
    """The section's blocks, headed ``number``; none when the simulations were not run
    (``table`` None). ``calibration``: the next section's summary (``calibration_report.
    shipped_calibration``), whose fitted damping the conclusion sets beside its undamped rows."""
    if table is None:
        return []
    shown = set(table["configuration"])
    configs = tuple(f"{c.name}: {c.description}" for c in TABLE_ROWS if c.name in shown)
    B: list[Block] = [
        Heading(f"{number}. Can physics explain the experiment?"),
        Para(
            "Nothing tuned: every configuration uses the paper's rod, flat (AISI 1010), drop "
            f"velocity and measured mu (as the local coefficient of the {FRICTION!r} model; "
            f"{MU_COLUMN}: the measured mu beside each row's own, below), the "
            f"{LAW!r} law with "
            "impactlab's defaults (the last row: the FE-tabulated law instead), gravity on and "
            "no structural damping (the next section "
            "calibrates the damping of every configuration but the Johnson-Cook one). The "
            "rate-dependent flat comes twice, with the product's two rate laws for this steel: "
            "Cowper-Symonds (an upper estimate of the rate effect) and Johnson-Cook (a lower "
            f"one). {T} is Eq. 12's in every row, measured or simulated alike: the measured "
            "row's is no measurement but the inversion of the measured drop (Eq. 12 from the "
            "dent and scar, the scar read as slip, Section 3), each simulated row's the same "
            f"inversion of its own e, dent and scar; {SEQUENCE_COLUMN} is the simulation's "
            "first touch to last separation (the flights between its contacts included; the "
            f"rigid rod: its contact), {CONTACT_TIME_COLUMN} the sum of its contacts. "
            f"{SCAR} is the extent of the mark the "
            "tip left, as a scan measures it (the measured L_s): |contact_travel| for "
            "the rigid rod, not the signed slip (sliding_length, Section 4's L_s [um]), and "
            "scar_length (x-extent of the tip's contact path over all contacts) for the "
            f"flexible rod; {E}: {E_DEFINITION} (not the impact's e of Section 4). "
            "max_delta_ratio is delta_max over the row's own delta_c (Jackson-Green's, Eq. 15, "
            f"{DELTA_C_COLUMN}; on a rate-dependent flat that of the rate-raised S_y, larger as "
            "S_y^2), so it does not compare across the rows; "
            f"{LIMIT_COLUMN} is the upper end of the row's law's range in the same ratio (for "
            f"the {LAW!r} law its range verified against FE at the pair's E*/S_y; for the "
            "FE-tabulated law the end of its curves, beyond which it is refused), which "
            "LAW_EXTRAPOLATED marks as exceeded. The model and its verification: "
            "docs/flexible.md."
        ),
        Bullets(configs),
        Table(
            _shown(table),
            "Measured vs rigid, flexible, flexible + rate-dependent (Cowper-Symonds, upper "
            "estimate; Johnson-Cook, lower) and flexible + FE-tabulated (hardening flat)",
            digits=4,
        ),
        *_findings(table),
        _closing(table, calibration),
    ]
    if "physics_drop_20" in figures:
        B.append(
            Figure(
                figures["physics_drop_20"],
                "Flexible rod, 20 deg: contact forces on the tip, tip height and tip trajectory "
                "over the whole contact sequence (grey: contacts)" + drop_flag(table),
            )
        )
    return B
