"""The numbers docs/paper/errata.md and docs/tutorials/reproduce.md state are the numbers the
code computes, at the precision the pages quote them: the errata's self-consistency table is
read from the page, row by row, and its key computed numbers from the text."""

from __future__ import annotations

import math
import re

import pytest

from impactlab.bodies import Rod
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import invert_case

LAWS = {"Ghaednia": "ghaednia", "Brake": "brake", "Kogut-Komvopoulos": "kogut-komvopoulos"}
NUMBER = r"[-+]?\d+(?:\.\d+)?"


@pytest.fixture(scope="module")
def run(full_reproduction):
    return full_reproduction


# --------------------------------------------------------------------------------------------
# docs/paper/errata.md
# --------------------------------------------------------------------------------------------


def test_errata_consistency_table(page, run):
    check, table = page.check, page.table
    cons = run.consistency
    cons = cons[cons["source"] != "Sec. 5.2 text"].set_index(["angle [deg]", "model"])
    rows = table(page.errata, "| Row | F T [N s] |")
    assert len(rows) == 6
    for cells in rows:
        ang, name = cells[0].split(" deg ")
        c = cons.loc[(int(ang), LAWS[name])]
        where = cells[0]
        check(re.findall(NUMBER, cells[1])[-1], c["F T [N s]"], f"{where} F T")
        check(re.findall(NUMBER, cells[2])[-1], c["(1+e)|v_i|/K_y [N s]"], f"{where} P")
        check(cells[3], c["ratio"], f"{where} ratio")
        check(cells[4], c["(1+e) m |v_i| [N s]"], f"{where} bound")
        outcome, ranges = cells[5].split(": ")
        assert outcome == c["vs bound"], where
        quoted = re.findall(r"\d+\.\d+", ranges)
        values = [c[f"{what} {end} [N s]"] for what in ("F T", "bound") for end in ("min", "max")]
        for q, v in zip(quoted, values, strict=True):
            check(q, v, f"{where} printed range")


def test_errata_key_numbers(page, run, sims):
    check, numbers = page.check, page.numbers
    exp = run.experimental.set_index("angle [deg]")
    alphas = numbers(rf"three experiments \(({NUMBER}), ({NUMBER}), ({NUMBER})\)", page.errata)
    for q, ang in zip(alphas, D.ANGLES_DEG, strict=True):
        check(q, exp.loc[ang, "alpha"], f"alpha {ang} deg")
    # the readings of the rod's length (Table 1)
    readings = run.extras["length_readings"]
    text = page.errata.replace("\n", " ")
    used = numbers(rf"two readings mixed, which give T = ({NUMBER}) / ({NUMBER}) ms", text)
    one_way = numbers(
        rf"Eq. 12 gives T = ({NUMBER}) / ({NUMBER}) ms \(L the overall length.*?or ({NUMBER}) / "
        rf"({NUMBER}) ms \(L between the centres",
        text,
    )
    quoted = [used, one_way[:2], one_way[2:]]
    for q, (_, r) in zip(quoted, readings.iterrows(), strict=True):
        check(q[0], r["T 20 deg [ms]"], r["reading"])
        check(q[1], r["T 45 deg [ms]"], r["reading"])
    other = numbers(rf"I_C = m \(L - 2R\)\^2/12\) gives ({NUMBER}) / ({NUMBER}) ms", text)
    m, L, R_ = D.PAPER_ROD.mass, D.PAPER_ROD.length, D.PAPER_ROD.tip_radius
    rod = Rod(length=L - 2 * R_, tip_radius=R_, mass=m, inertia=m * (L - 2 * R_) ** 2 / 12)
    for q, ang in zip(other, (20, 45), strict=True):
        check(q, invert_case(D.EXPERIMENTS[ang], rod=rod).duration * 1e3, f"other mixed {ang}")
    spans = numbers(
        rf"the two 45 deg values lie ({NUMBER}) % to ({NUMBER}) % and ({NUMBER}) % to "
        rf"({NUMBER}) % from it, across the 5 % tolerance",
        text,
    )
    consistent = readings[readings["self-consistent"]]
    for q, (_, r) in zip((spans[:2], spans[2:]), consistent.iterrows(), strict=True):
        check(q[0], 100 * r["T 45 deg rel. diff low"], "over the rounding, low")
        check(q[1], 100 * r["T 45 deg rel. diff high"], "over the rounding, high")
        assert r["T 45 deg verdict"] == "UNDECIDED"
    (moves,) = numbers(rf"The reading moves T by up to ({NUMBER}) %", text)
    spread = [
        abs(r[f"T {a} deg [ms]"] / exp.loc[a, "T [ms]"] - 1)
        for _, r in readings.iterrows()
        for a in (20, 45)
    ]
    check(moves, 100 * max(spread), "the reading moves T")
    # the published rows: Eq. 12 on their own numbers, effective masses, forces
    cons = run.consistency.set_index(["source", "model"])
    g, k = cons.loc[("Table 3", "ghaednia")], cons.loc[("Table 3", "kogut-komvopoulos")]
    ls_g, ls_k = numbers(
        rf"but ({NUMBER}) um instead of -74 um for Ghaednia at 45 deg \(the copy error above\) "
        rf"and ({NUMBER}) um instead of -638 um",
        text,
    )
    check(ls_g, g["L_s from Eq. 12 [um]"], "Eq. 12, Ghaednia 45 deg")
    check(ls_k, k["L_s from Eq. 12 [um]"], "Eq. 12, Kogut-Komvopoulos 45 deg")
    tables = run.consistency[run.consistency["source"] != "Sec. 5.2 text"]
    meff = numbers(
        rf"the rows imply ({NUMBER})-({NUMBER}) kg at 20 deg and ({NUMBER})-({NUMBER}) kg at 45 "
        rf"deg, where the rod has 1/K_y = ({NUMBER}) and ({NUMBER}) kg",
        text,
    )
    for i, ang in enumerate((20, 45)):
        rows = tables[tables["angle [deg]"] == ang]
        check(meff[2 * i], rows["implied m_eff [kg]"].min(), f"m_eff {ang} deg")
        check(meff[2 * i + 1], rows["implied m_eff [kg]"].max(), f"m_eff {ang} deg")
        check(meff[4 + i], rows["rod m_eff = 1/K_y [kg]"].iloc[0], f"1/K_y {ang} deg")
    ours = sims.loc[(20, "ghaednia"), "F [N]"]
    below, f_ours, above = numbers(
        rf"Ghaednia force \(2153 N\) is ({NUMBER}) % below impactlab's mean force \((\d+) N\), "
        rf"the table's 2571 N is (\d+) % above it",
        text,
    )
    check(below, 100 * (1 - 2153 / ours), "2153 N below")
    check(f_ours, ours, "impactlab's mean force")
    check(above, 100 * (2571 / ours - 1), "2571 N above")
    back = [
        sims.loc[(int(r.angle_deg), r.model), "T + |delta_p|/(e|v_i|) [ms]"]
        for r in D.TABLE_ROWS
        if r.model != "experiment"
    ]
    lo, hi = numbers(rf"T \+ \|delta_p\|/\(e \|v_i\|\) \(({NUMBER})-({NUMBER}) ms", text)
    check(lo, min(back), "back at the surface, least")
    check(hi, max(back), "back at the surface, largest")


def test_errata_inertia_the_undecided_row_would_need(page):
    """Kogut-Komvopoulos at 45 deg, at the most favourable end of the printed rounding: the
    I_C/(m L^2) at which (1 + e)|v_i|/K_y reaches its F T."""
    check, numbers = page.check, page.numbers
    (quoted,) = numbers(rf"I_C/\(m L\^2\) of at least ({NUMBER})", page.errata)
    r, x = D.published_row(45, "kogut-komvopoulos"), D.EXPERIMENTS[45]
    assert r is not None and r.F is not None and r.T is not None and r.e is not None
    m = D.PAPER_ROD.mass + 0.5e-4
    ft = (r.F - 0.5) * (r.T - 0.5e-5)
    K_y = (1 + r.e + 0.005) * (abs(x.v_i) + 0.005) / ft
    L, R_ = D.PAPER_ROD.length, D.PAPER_ROD.tip_radius
    a = L / 2 * math.cos(x.angle)
    b = L / 2 * math.sin(x.angle) + R_
    k2 = a * (a - x.mu * b) / (m * (K_y - 1 / m))  # K_y = (1/m)[1 + a (a - mu b)/k^2]
    check(quoted, k2 / L**2, "I_C/(m L^2) needed")
    (within,) = numbers(r"would need K_y within (\d+) % of 1/m", page.errata)
    assert K_y * m - 1 <= int(within) / 100


# --------------------------------------------------------------------------------------------
# docs/tutorials/reproduce.md
# --------------------------------------------------------------------------------------------


def test_tutorial_numbers(page, run):
    check, numbers = page.check, page.numbers
    exp = run.experimental.set_index("angle [deg]")
    for ang in (20, 45):
        t, pub, d, f = numbers(
            rf"  {ang} deg: T = ({NUMBER}) ms, published ({NUMBER}) ms \(({NUMBER})%\); "
            rf"F = ({NUMBER}) N",
            page.tutorial,
        )
        check(t, exp.loc[ang, "T [ms]"], f"{ang} deg T")
        check(pub, exp.loc[ang, "T published [ms]"], f"{ang} deg published T")
        check(d, 100 * exp.loc[ang, "T rel. diff"], f"{ang} deg rel. diff")
        check(f, exp.loc[ang, "F [N]"], f"{ang} deg F")
    t70, f70 = numbers(
        rf"70 deg: T = ({NUMBER}) ms, not published; F = ({NUMBER}) N", page.tutorial
    )
    check(t70, exp.loc[70, "T [ms]"], "70 deg T")
    check(f70, exp.loc[70, "F [N]"], "70 deg F")
    line = run.report_md.read_text().splitlines()
    (printed,) = numbers(r"`(20 deg: T = [^`]+)`", page.tutorial.replace("\n", " "))
    assert f"- {printed}" in line  # the command's line, as the report's Section 1
    readings = run.extras["length_readings"]
    q1, q2 = numbers(
        rf"the 45 deg T lands at ({NUMBER}) % / ({NUMBER}) %", page.tutorial.replace("\n", " ")
    )
    consistent = readings[readings["self-consistent"]]
    for q, (_, r) in zip((q1, q2), consistent.iterrows(), strict=True):
        check(q, 100 * r["T 45 deg rel. diff"], r["reading"])
    spans = numbers(
        rf"that is ({NUMBER}) % to ({NUMBER}) % / ({NUMBER}) % to ({NUMBER}) %,",
        page.tutorial.replace("\n", " "),
    )
    for q, (_, r) in zip((spans[:2], spans[2:]), consistent.iterrows(), strict=True):
        check(q[0], 100 * r["T 45 deg rel. diff low"], "over the rounding, low")
        check(q[1], 100 * r["T 45 deg rel. diff high"], "over the rounding, high")
        assert r["T 45 deg verdict"] == "UNDECIDED"
