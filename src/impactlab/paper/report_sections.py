"""The reproduction report's content: one function per section, each returning its blocks of the
document model of :mod:`impactlab.paper.report` (rendered to Markdown and HTML there).
"""

from __future__ import annotations

import platform
from collections.abc import Callable, Iterable, Mapping
from dataclasses import dataclass
from operator import attrgetter
from typing import Any

import pandas as pd

from impactlab.paper import data as D
from impactlab.paper.analytic_rows import EXCEEDS, WITHIN_ROUNDING, invert_case
from impactlab.paper.calibration_report import calibration_section, shipped_calibration
from impactlab.paper.physics_report import physics_section
from impactlab.paper.quantities import (
    PAPER_DEPTH,
    PAPER_SIGN_NOTE,
    PRINTED_HALF_UNIT,
    rebound_ratio_range,
    reference_of,
)
from impactlab.paper.report import Block, Code, Figure, Heading, Para, Table, fmt
from impactlab.paper.report_acceptance import (
    CALIBRATION_SECTION,
    EQ12_SECTION,
    PHYSICS_SECTION,
    RUN_SECTION,
    acceptance,
)
from impactlab.paper.report_reasons import not_reproduced
from impactlab.paper.report_simulated import _marked, simulated

TITLE = "impactlab: reproduction of Ghaednia, Marghitu & Jackson (2016)"


@dataclass(frozen=True)
class ReportData:
    """What the report shows. DataFrames as :func:`impactlab.paper.reproduction.reproduce` makes
    them; ``simulations`` and ``eq12`` are None when the simulations were not run; ``figures``
    maps a figure key to its file name; ``tables`` the side-by-side table per angle [deg]."""

    experimental: pd.DataFrame
    comparison: pd.DataFrame
    consistency: pd.DataFrame
    inertia: pd.DataFrame
    simulations: pd.DataFrame | None
    eq12: pd.DataFrame | None
    figures: Mapping[str, str]
    tables: Mapping[int, pd.DataFrame]
    elapsed: float
    version: str
    physics: pd.DataFrame | None = None
    #: the file of every simulation's full input (None: not simulated)
    inputs_file: str | None = None
    #: the keys of its records by kind (``reproduction.simulation_records``; None: not simulated)
    inputs: Mapping[str, tuple[str, ...]] | None = None
    #: the paper's laws against the FE law (``paper.fe_reference_rows``; None: not simulated)
    fe_reference: pd.DataFrame | None = None
    #: T under the readings of the rod's length (``analytic_rows.length_readings``)
    readings: pd.DataFrame | None = None


def build_report(d: ReportData) -> list[Block]:
    """Every section of the report, in order; without the simulations those that need them
    are left out and the others keep their numbers (Section 1 says which are skipped)."""
    calibration = None if d.physics is None else shipped_calibration()
    return [
        *acceptance(d),
        *_inputs(),
        *_experimental(d),
        *simulated(d),
        *not_reproduced(d.comparison),
        *_consistency(d),
        *_eq12(d),
        *_inertia(d),
        *_figures(d),
        *_discrepancies(),
        *physics_section(d.physics, d.figures, PHYSICS_SECTION, calibration),
        *([] if calibration is None else calibration_section(calibration, CALIBRATION_SECTION)),
        *_run(d),
    ]


def _frame(items: Iterable[Any], *columns: str | tuple[str, Callable[[Any], Any]]) -> pd.DataFrame:
    """A table of ``items``, one row each: a column is an attribute's name, or (its title, a
    function of the item)."""
    getters = [(c, attrgetter(c)) if isinstance(c, str) else c for c in columns]
    return pd.DataFrame([{title: get(item) for title, get in getters} for item in items])


def _inputs() -> list[Block]:
    columns = ("body", "symbol", "printed", ("value", attrgetter("value")), "unit")
    table1 = _frame(D.TABLE1, *columns, "correction")
    experiments = _frame(
        D.EXPERIMENTS.values(),
        ("angle [deg]", attrgetter("angle_deg")),
        ("v_i [m/s]", attrgetter("v_i")),
        ("v_Of [m/s]", attrgetter("v_rebound")),
        "e",
        ("v_Of/|v_i|", attrgetter("e_from_velocities")),
        "mu",
        (PAPER_DEPTH, lambda x: x.delta_p * 1e6),
        ("L_s [um]", lambda x: x.L_s * 1e6),
    )
    return [
        Heading("2. Inputs"),
        Para(
            "Table 1 with its unit corrections (docs/paper/errata.md), and the measurements "
            "of Sec. 5.1.3. The rod's I_C is not in the paper: m L^2/12 is assumed."
        ),
        Table(table1, "Table 1 (corrected)"),
        Table(experiments, "Experiments (Sec. 5.1.3)"),
        Para(_rebound_text()),
        Para(PAPER_SIGN_NOTE),
    ]


def _rebound_text() -> str:
    """v_Of/|v_i| of each experiment against its printed e, over the rounding of the printed
    velocities and of e (``PRINTED_HALF_UNIT`` each)."""
    h = PRINTED_HALF_UNIT
    parts = []
    for ang, x in D.EXPERIMENTS.items():
        ratio = x.e_from_velocities
        lo, hi = rebound_ratio_range(x.v_rebound, x.v_i)
        e_lo, e_hi = x.e - h, x.e + h
        head = f"{ang} deg: {x.v_rebound:.2f}/{abs(x.v_i):.2f} = {ratio:.4g}"
        if round(ratio, 2) == round(x.e, 2):
            parts.append(f"{head}, the printed {x.e:.2f}")
            continue
        head += f" (it rounds to {ratio:.2f}, not the printed {x.e:.2f})"
        span = f"{lo:.3g}-{hi:.3g} over the rounding of v_Of and v_i"
        if lo <= e_hi and hi >= e_lo:
            parts.append(
                f"{head}; {span}, agreeing with the printed {x.e:.2f} ({e_lo:.3f}-{e_hi:.3f}) "
                f"only at its edge ({max(lo, e_lo):.3g}-{min(hi, e_hi):.3g})"
            )
        else:
            parts.append(f"{head}; {span}, outside the printed {x.e:.2f} ({e_lo:.3f}-{e_hi:.3f})")
    return (
        "The column v_Of/|v_i| against the printed e (velocities and e printed with two "
        f"decimals, each standing for +- {h:g}): " + "; ".join(parts) + ". impactlab uses "
        "the printed e (docs/paper/errata.md)."
    )


def _dent_mark(simulations: pd.DataFrame | None) -> str:
    """``; extrapolated: 178 delta_c (LAW_EXTRAPOLATED)`` when Fig. 4's impact (20 deg,
    Ghaednia, impulse-ratio friction) left its law's verified range; ``""`` otherwise."""
    if simulations is None or simulations.empty:
        return ""
    row = simulations[
        (simulations["angle [deg]"] == 20)
        & (simulations["law"] == "ghaednia")
        & (simulations["friction"] == "impulse_ratio")
    ]
    if row.empty or "LAW_EXTRAPOLATED" not in str(row.iloc[0]["flags"]):
        return ""
    ratio = float(row.iloc[0]["max_delta_ratio"])
    return f"; extrapolated: {ratio:.0f} {reference_of('ghaednia')} (LAW_EXTRAPOLATED)"


def _experimental(d: ReportData) -> list[Block]:
    return [
        Heading("3. Experimental-analytic rows (Eqs. 12 and 29)"),
        Para(
            "T = (|L_s|/|alpha| + |delta_p|)/|v_i| with the corrected alpha of Eq. 13 (slip "
            "of the tip, gravity neglected: the paper's method), F from the rigid-body "
            "identity F T = (1 + e)|v_i| / K_y because the paper does not print the measured "
            "centre-of-mass velocities that Eq. 29 needs. Variants: with gravity "
            "((g/2) T^2 added to Eq. 12, g T to the impulse"
            + _gravity_mu_words(d.experimental)
            + ") and with L_s read as the "
            "travel of the contact patch instead of the slip. At 70 deg the paper reads the "
            "profile (Fig. 8) as sliding at the beginning and sticking or rolling at the end, "
            "while Eq. 12 assumes sliding throughout: that row is the method applied outside "
            "its assumption, an estimate rather than a measured duration."
        ),
        Table(d.experimental, "Experimental rows", digits=4),
    ]


def _gravity_mu_words(exp: pd.DataFrame) -> str:
    """How the gravity variant treats mu, with its numbers: ``, and the measured mu corrected
    ...``; the T that keeping the measured mu would give, at the first angle."""
    e = exp.set_index("angle [deg]")
    if "mu with gravity (Eq. 28)" not in e:
        return ""
    ang = int(e.index[0])
    x = D.EXPERIMENTS[ang]
    mus = " / ".join(f"{v:.4g}" for v in e["mu with gravity (Eq. 28)"])
    half = invert_case(x, gravity=True).duration * 1e3
    T_pub, T_g = e.loc[ang, "T published [ms]"], e.loc[ang, "T with gravity [ms]"]
    return (
        ", and the measured mu corrected for gravity as the Eq. 28 erratum derives: the "
        "printed Eq. 28 reads mu from dv_Cy = (P - m g T)/m, so the coefficient is "
        f"mu (1 - m g T/P): {mus} at the three angles, column 'mu with gravity (Eq. 28)'; "
        f"at {ang} deg T with gravity is {T_g:.4g} ms ({T_g / T_pub - 1:+.1%} from the "
        f"published {T_pub:.3g} ms), against {half:.4g} ms ({half / T_pub - 1:+.1%}) with "
        f"gravity in Eq. 12 and the impulse only, mu kept at {x.mu:g}"
    )


def _consistency(d: ReportData) -> list[Block]:
    return [
        Heading("6. The published numerical rows are not self-consistent"),
        Para(
            "For a rigid rod in gross sliding with constant angle and without gravity, "
            "v_Oy(T) - v_i = K_y P, so the normal impulse is P = (1 + e)|v_i| / K_y with "
            "K_y = [k^2 + a^2 - mu a b]/(m k^2). K_y >= 1/m whenever mu b <= a, hence "
            "P <= (1 + e) m |v_i| for every rigid body of mass m. A simulation's mean force "
            "is its impulse over its duration, so F T must equal P. The paper's rows break "
            f"the first: their F T is {_ratio_range(d.consistency)}. "
            f"{_bound_text(d.consistency)} Eq. 12 "
            "(exact for the paper's model) must also link each row's L_s to its own "
            "delta_p and T."
        ),
        Table(
            d.consistency,
            "Published F T vs the normal impulse, and Eq. 12 on the published rows",
            digits=3,
        ),
    ]


def _ratio_range(consistency: pd.DataFrame) -> str:
    """How many times P the published rows' F T is: its range, overall and per source."""

    def span(r: pd.Series) -> str:
        lo, hi = float(r.min()), float(r.max())
        return f"{lo:.2f}" if f"{lo:.2f}" == f"{hi:.2f}" else f"{lo:.2f}-{hi:.2f}"

    per = "; ".join(
        f"{src}: {span(g['ratio'])}" for src, g in consistency.groupby("source", sort=False)
    )
    return f"{span(consistency['ratio'])} times P ({per})"


def _bound_text(consistency: pd.DataFrame) -> str:
    """Which published rows exceed the rigid-body bound, tested over the printed rounding."""

    def rows(outcome: str) -> str:
        g = consistency[consistency["vs bound"] == outcome]
        names = [f"{r['source']} {r['model']} ({r['angle [deg]']} deg)" for _, r in g.iterrows()]
        return " and ".join(names)

    exceed, undecided = rows(EXCEEDS), rows(WITHIN_ROUNDING)
    return (
        "The bound is tested over the rounding of every printed number (half a unit of its "
        "last digit: T, F, e, v_i and m; the columns 'min', 'max' and 'vs bound'): "
        + (f"{exceed} exceed it beyond the rounding" if exceed else "no row exceeds it")
        + (
            f"; {undecided} lies within the rounding of it: the printed digits cannot tell "
            "whether it exceeds the bound"
            if undecided
            else ""
        )
        + "."
    )


def _eq12(d: ReportData) -> list[Block]:
    if d.eq12 is None:
        return []
    return [
        Heading(f"{EQ12_SECTION}. The inversion applied to impactlab's own simulations"),
        Para(
            "T recovered by Eq. 12 from each simulated dent (delta_p, L_s) and e, against "
            "the simulated duration. The engine includes gravity and lets the rod turn, "
            "which Eq. 12 neglects; the difference measures those neglected effects."
        ),
        Table(_marked(d.eq12, "law"), "Eq. 12 against the full dynamics", digits=4),
    ]


def _inertia(d: ReportData) -> list[Block]:
    B: list[Block] = [
        Heading("8. Sensitivity of the experimental T to the rod's inertia"),
        Para(
            "The paper does not give I_C. The last row is the I_C/(m L^2) at which each "
            "published T would be met exactly (a diagnostic only; nothing uses it)."
        ),
        Table(d.inertia, "T [ms] vs I_C/(m L^2)", digits=4),
    ]
    if "inertia" in d.figures:
        B.append(
            Figure(
                d.figures["inertia"],
                "Experimental T relative to the published value (70 deg, which has none: to its "
                "own value at I_C = m L^2/12) vs I_C/(m L^2); grey band: 5 %",
            )
        )
    return B


def _figures(d: ReportData) -> list[Block]:
    figs = d.figures
    B: list[Block] = [Heading("9. Figures")]
    if "alpha" in figs:
        B.append(Figure(figs["alpha"], "Fig. 5 regenerated: alpha vs angle (corrected Eq. 13)"))
    if "dent" in figs:
        B.append(
            Figure(
                figs["dent"],
                "Fig. 4 regenerated: simulated dent, 20 deg, 1.41 m/s, Ghaednia et al."
                + _dent_mark(d.simulations),
            )
        )
    B.extend(
        Figure(
            figs[f"forces_{ang}"],
            f"Force-time and force-penetration, {ang} deg, three laws (impulse-ratio friction)",
        )
        for ang in D.ANGLES_DEG
        if f"forces_{ang}" in figs
    )
    return B


def _discrepancies() -> list[Block]:
    table = _frame(
        D.DISCREPANCIES,
        "key",
        "where",
        "quantity",
        ("values", lambda d: "; ".join(f"{k}: {fmt(v)}" for k, v in d.values.items())),
        "note",
    )
    return [
        Heading("10. Inconsistencies of the paper recorded as data"),
        Table(table, "impactlab.paper.data.DISCREPANCIES"),
    ]


def _run(d: ReportData) -> list[Block]:
    return [
        Heading(f"{RUN_SECTION}. Run"),
        Code(
            f"impactlab {d.version}, Python {platform.python_version()}, "
            f"{platform.platform()}\nelapsed: {d.elapsed:.1f} s"
        ),
        *([Para(_inputs_text(d.inputs_file, d.inputs))] if d.inputs_file else []),
    ]


#: Where each kind of record of the inputs file comes from, as the sentence names it.
_INPUT_KINDS = {
    "simulations": f"the rows of Sections 4, 5 and {EQ12_SECTION}",
    "fe_reference": "the FE-reference impacts of Section 4 (law 'tabulated')",
    "physics": f"the rows of Section {PHYSICS_SECTION} (keyed by configuration)",
}


def _inputs_text(file: str, inputs: Mapping[str, tuple[str, ...]] | None) -> str:
    """The sentence on the inputs file: what a record holds, how many of each kind (with a key
    of each, as the file names them) and how one is run again."""
    kinds = [(k, keys) for k, keys in (inputs or {}).items() if keys]
    parts = [f'{len(keys)} for {_INPUT_KINDS.get(k, k)}, e.g. "{keys[0]}"' for k, keys in kinds]
    held = f", {sum(len(keys) for _, keys in kinds)} in all: " + "; ".join(parts) if parts else ""
    example = kinds[0][1][0] if kinds else "20 deg, ghaednia, coulomb"
    return (
        f"What each simulation behind this report simulated (the body, both materials, the law "
        f"and its parameters, friction, mu, angle, velocity, gravity, tolerance, the impactlab "
        f"version): `{file}`, one record per simulation{held}. "
        f'`impactlab.rerun(records["{example}"])` runs one again, to the same numbers.'
    )
