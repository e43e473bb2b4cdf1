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

from impactlab.contact.ranges import RANGES, law_range
from impactlab.contact.verified_ranges import tolerance_text
from impactlab.materials import ContactPair
from impactlab.paper import data as D
from impactlab.paper.calibration_report import calibration_section, shipped_calibration
from impactlab.paper.fe_reference_rows import FE_REFERENCE_TEXT, fe_reference_summary
from impactlab.paper.physics_report import physics_section
from impactlab.paper.quantities import (
    EXTRAPOLATED_MARK,
    PAPER_DEPTH,
    PAPER_SIGN_NOTE,
    count_extrapolated,
)
from impactlab.paper.report import (
    Block,
    Bullets,
    Code,
    Figure,
    Heading,
    Para,
    Table,
    fmt_pct,
)
from impactlab.paper.report_acceptance import acceptance
from impactlab.paper.report_reasons import not_reproduced
from impactlab.paper.simulations import FRICTIONS

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
    #: the paper's laws against the FE law (``paper.fe_reference_rows``; None: not simulated)
    fe_reference: pd.DataFrame | None = None


def build_report(d: ReportData) -> list[Block]:
    """Every section of the report, in order."""
    return [
        *acceptance(d),
        *_inputs(),
        *_experimental(d),
        *_simulated(d),
        *not_reproduced(d.comparison),
        *_consistency(d),
        *_eq12(d),
        *_inertia(d),
        *_figures(d),
        *_discrepancies(),
        *physics_section(d.physics, d.figures, 11),
        *([] if d.physics is None else calibration_section(shipped_calibration(), 12)),
        *_run(d),
    ]


def _frame(items: Iterable[Any], *columns: str | tuple[str, Callable[[Any], Any]]) -> pd.DataFrame:
    """A table of ``items``, one row each: a column is an attribute's name, or (its title, a
    function of the item)."""
    getters = [(c, attrgetter(c)) if isinstance(c, str) else c for c in columns]
    return pd.DataFrame([{title: get(item) for title, get in getters} for item in items])


def _inputs() -> list[Block]:
    columns = ("body", "symbol", "printed", ("value (SI)", attrgetter("value")), "unit")
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
        Para(PAPER_SIGN_NOTE),
    ]


def _experimental(d: ReportData) -> list[Block]:
    return [
        Heading("3. Experimental-analytic rows (Eqs. 12 and 29)"),
        Para(
            "T = (|L_s|/|alpha| + |delta_p|)/|v_i| with the corrected alpha of Eq. 13 (slip "
            "of the tip, gravity neglected: the paper's method), F from the rigid-body "
            "identity F T = (1 + e)|v_i| / K_y because the paper does not print the measured "
            "centre-of-mass velocities that Eq. 29 needs. Variants: with gravity "
            "((g/2) T^2 added to Eq. 12, g T to the impulse) and with L_s read as the "
            "travel of the contact patch instead of the slip."
        ),
        Table(d.experimental, "Experimental rows", digits=4),
    ]


def _simulated(d: ReportData) -> list[Block]:
    B: list[Block] = [Heading("4. Simulated rows, side by side")]
    for ang, name in (
        (20, "Table 2"),
        (45, "Table 3"),
        (70, "Table 4 (ours; the paper's is missing)"),
    ):
        B.append(Table(_marked(d.tables[ang], "model"), f"{name}: {ang} deg", digits=4))
    if d.simulations is not None:
        B.append(Para(_extrapolation_note(d.simulations)))
        B.append(
            Para(
                "Both friction models give the same numbers here: the tip starts without "
                "tangential velocity and mu < mu_c at every angle, so Coulomb friction "
                "slides throughout and reduces to the paper's impulse ratio P_x = mu P."
            )
        )
        B.append(
            Table(
                _marked(d.simulations, "law"),
                "All simulations (impactlab ImpactResult scalars)",
                digits=4,
            )
        )
        B += _sim_vs_experiment(d.simulations, d.experimental)
    if d.fe_reference is not None:
        B += [
            Para(FE_REFERENCE_TEXT),
            Table(
                _percent(d.fe_reference, "vs FE"),
                "The paper's laws against the FE reference",
                digits=4,
            ),
            Para(fe_reference_summary(d.fe_reference)),
        ]
    return B


def _percent(table: pd.DataFrame, suffix: str) -> pd.DataFrame:
    """``table`` with its columns ending in ``suffix`` (relative differences) as percentages."""
    shown = table.copy()
    for col in [c for c in shown.columns if str(c).endswith(suffix)]:
        shown[col] = [fmt_pct(v) for v in shown[col]]
    return shown


def _marked(table: pd.DataFrame, column: str) -> pd.DataFrame:
    """``table`` with ``EXTRAPOLATED_MARK`` after ``column`` on the rows flagged
    LAW_EXTRAPOLATED (the ``flags`` column); unchanged without that column."""
    if "flags" not in table:
        return table
    shown = table.copy()
    flagged = shown["flags"].fillna("").str.contains("LAW_EXTRAPOLATED")
    shown[column] = [
        f"{v} {EXTRAPOLATED_MARK}" if f else v for v, f in zip(shown[column], flagged, strict=True)
    ]
    return shown


def _extrapolation_note(simulations: pd.DataFrame) -> str:
    """The paragraph on the LAW_EXTRAPOLATED flag of the simulated rows."""
    n, m = count_extrapolated(simulations)
    flagged = simulations[simulations["flags"].fillna("").str.contains("LAW_EXTRAPOLATED")]
    laws = sorted(set(flagged["law"]))
    ranges = "; ".join(
        f"{law}: {_verified_words(law)}, max delta/delta_c here "
        f"{flagged[flagged['law'] == law]['max_delta_ratio'].max():.3g}"
        for law in laws
        if law in RANGES
    )
    return (
        f"{EXTRAPOLATED_MARK} LAW_EXTRAPOLATED: {n} of {m} simulated impacts push the "
        "interference beyond the upper end of their contact law's verified range "
        f"({tolerance_text()}, for the pair's E*/S_y; impactlab.contact.ranges; `flags` and "
        "`max_delta_ratio` = delta_max/delta_c in the CSV tables), so the law is used where it "
        "was not verified against the FE reference. "
        + (f"{ranges}. " if ranges else "")
        + "The verified ranges are measured from the shipped FE curves (docs/laws/index.md, "
        '"Verified ranges"); a pair whose E*/S_y lies outside the FE cases keeps the former '
        "stand-in, marked unverified; the flag is advisory and changes no number."
    )


#: E*/S_y of the paper's pair (rod on flat): which verified range applies to the simulations.
_PAPER_PAIR = ContactPair(D.ROD_MATERIAL, D.FLAT_MATERIAL)
_PAPER_RATIO = _PAPER_PAIR.E_star / _PAPER_PAIR.yield_strength


def _verified_words(law: str) -> str:
    """``verified up to 1 delta_c at E*/S_y = 360`` (the paper's pair), or the stand-in."""
    cases = [c for c in law_range(law).verified if abs(c.e_star_over_sy / _PAPER_RATIO - 1) < 1e-3]
    if cases:
        c = cases[0]
        return f"verified up to {c.upper:.3g} delta_c at E*/S_y = {c.e_star_over_sy:.0f}"
    return f"{law_range(law).stand_in_text} (unverified)"


def _sim_vs_experiment(simtab: pd.DataFrame, exp: pd.DataFrame) -> list[Block]:
    """The paper's main claim (simulations vs experiments), and its 70 deg statements."""
    rows = []
    sim = simtab[simtab["friction"] == FRICTIONS[0]]
    e = exp.set_index("angle [deg]")
    for ang, x in D.EXPERIMENTS.items():
        for key, val in (
            ("e", x.e),
            (PAPER_DEPTH, x.delta_p * 1e6),
            ("L_s [um]", x.L_s * 1e6),
            ("T [ms]", e.loc[ang, "T [ms]"]),
            ("F [N]", e.loc[ang, "F [N]"]),
        ):
            row: dict[str, Any] = {"angle [deg]": ang, "quantity": key, "experiment": val}
            for law in D.PAPER_LAWS:
                h = sim[(sim["angle [deg]"] == ang) & (sim["law"] == law)]
                row[law] = None if h.empty else float(h.iloc[0][key])
            rows.append(row)
    out: list[Block] = [
        Heading("Simulations against the experiments (the paper's main claim)", 3),
        Para(
            "Experiment: measured e, delta_p, L_s; T and F from the inversion (Section 3). "
            "As the paper says, the simulated e is close to the measured one at 20 and 45 deg "
            "while the dents differ: the simulations slide tens of micrometres, the "
            "experiments 1.4-1.65 mm. At 70 deg the measured e is far below the simulated one."
        ),
        Table(pd.DataFrame(rows), "Experiment vs simulation (impulse-ratio friction)", digits=4),
    ]
    s70 = sim[sim["angle [deg]"] == 70]
    if not s70.empty:
        T_exp, F_exp = e.loc[70, "T [ms]"], e.loc[70, "F [N]"]
        checks = (
            (
                "the simulated e is significantly larger than the measured 0.05",
                bool((s70["e"] > 2 * D.EXPERIMENTS[70].e).all()),
            ),
            (
                f"the experimental T ({T_exp:.3g} ms) is smaller than every simulated T",
                bool((s70["T [ms]"] > T_exp).all()),
            ),
            (
                f"the experimental F ({F_exp:.4g} N) is larger than every simulated F",
                bool((s70["F [N]"] < F_exp).all()),
            ),
        )
        out.append(
            Para(
                "The paper's Sec. 5.2-5.3 statements about 70 deg (its Table 4 is "
                "missing), checked with impactlab's Table 4:"
            )
        )
        out.append(Bullets(tuple(f"{t}: {'yes' if ok else 'no'}" for t, ok in checks)))
    return out


def _consistency(d: ReportData) -> list[Block]:
    return [
        Heading("6. The published numerical rows are not self-consistent"),
        Para(
            "For a rigid rod in gross sliding with constant angle and without gravity, "
            "v_Oy(T) - v_i = K_y P, so the normal impulse is P = (1 + e)|v_i| / K_y with "
            "K_y = [k^2 + a^2 - mu a b]/(m k^2). K_y >= 1/m whenever mu b <= a, hence "
            "P <= (1 + e) m |v_i| for every rigid body of mass m. A simulation's mean force "
            "is its impulse over its duration, so F T must equal P. The paper's rows break "
            "both: their F T is about 2.4 times P, and at 45 deg above the bound. Eq. 12 "
            "(exact for the paper's model) must also link each row's L_s to its own "
            "delta_p and T."
        ),
        Table(
            d.consistency,
            "Published F T vs the normal impulse, and Eq. 12 on the published rows",
            digits=3,
        ),
    ]


def _eq12(d: ReportData) -> list[Block]:
    if d.eq12 is None:
        return []
    return [
        Heading("7. The inversion applied to impactlab's own simulations"),
        Para(
            "T recovered by Eq. 12 from each simulated dent (delta_p, L_s) and e, against "
            "the simulated duration. The engine includes gravity and lets the rod turn, "
            "which Eq. 12 neglects; the difference measures those neglected effects."
        ),
        Table(d.eq12, "Eq. 12 against the full dynamics", digits=4),
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
                "Experimental T relative to the published value vs I_C/(m L^2); grey band: 5 %",
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
                "Fig. 4 regenerated: simulated dent, 20 deg, 1.41 m/s, Ghaednia et al.",
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
        ("values", lambda d: "; ".join(f"{k}: {v}" for k, v in d.values.items())),
        "note",
    )
    return [
        Heading("10. Inconsistencies of the paper recorded as data"),
        Table(table, "impactlab.paper.data.DISCREPANCIES"),
    ]


def _run(d: ReportData) -> list[Block]:
    return [
        Heading(f"{11 if d.physics is None else 13}. Run"),
        Code(
            f"impactlab {d.version}, Python {platform.python_version()}, "
            f"{platform.platform()}\nelapsed: {d.elapsed:.1f} s"
        ),
        *(
            [
                Para(
                    f"What each simulation simulated (the rod, both materials, the law and its "
                    f"parameters, friction, mu, angle, velocity, gravity, tolerance, the impactlab "
                    f"version): `{d.inputs_file}`, one record per row of the tables; "
                    f'`impactlab.rerun(records["20 deg, ghaednia, coulomb"])` runs one again.'
                )
            ]
            if d.inputs_file
            else []
        ),
    ]
