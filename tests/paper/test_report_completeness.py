"""What the reproduction's report records and says it covers: every simulation behind it in
simulation_inputs.json (each run again to the same numbers), what a report without the
simulations leaves out and does not compare (every section, part and file named, and the
published numbers not compared counted beside those not reproduced), which of the paper's
figures are regenerated, the criterion of the 70 deg "significantly larger" check, and the
conclusion of "Can physics explain the experiment?" qualified by its damping (zeta = 0) and set
beside the calibration's fitted damping."""

from __future__ import annotations

import json
from pathlib import Path

import pandas as pd
import pytest

import impactlab as il
from impactlab.paper import data as D
from impactlab.paper import quantities as Q
from impactlab.paper import reproduction as R
from impactlab.paper.physics import E_COLUMN, SCAR_COLUMN
from impactlab.paper.physics_words import damped

#: the repository root (the tutorials quote the command's lines)
ROOT = Path(__file__).resolve().parents[2]
CS = "flexible rod + rate-dependent flat (Cowper-Symonds, upper estimate)"
FE_HARD = "flexible rod + FE-tabulated law (hardening flat)"


@pytest.fixture(scope="module")
def analytic(analytic_reproduction) -> R.ReproductionResult:
    """``reproduce(simulate=False)``: the analytic part only (conftest.py: one run)."""
    return analytic_reproduction


def _section(text: str, number: int) -> str:
    """Section ``number`` of a report's Markdown, its heading included."""
    start = text.index(f"\n## {number}. ")
    end = text.find("\n## ", start + 4)
    return text[start : end if end > 0 else len(text)]


def test_every_simulation_behind_the_report_is_recorded(full_reproduction):
    """The 18 impacts of the tables, the 3 FE-reference impacts and the 15 rows of Section 11
    (only the 18 were recorded, while the report said "one record per row of the tables")."""
    records = json.loads(full_reproduction.files["simulation_inputs"].read_text())
    law_keys = [k for k in records if k.count(", ") == 2 and k.split(", ")[1] in D.PAPER_LAWS]
    fe_keys = [k for k in records if k.endswith(", tabulated, coulomb")]
    physics = full_reproduction.extras["physics"]
    configs = [c for c in dict.fromkeys(physics["configuration"]) if not c.startswith("measured")]
    drop_keys = [f"{a} deg, {c}" for c in configs for a in (20, 45, 70)]
    assert (len(law_keys), len(fe_keys), len(configs)) == (18, 3, 5)
    assert set(records) == {*law_keys, *fe_keys, *drop_keys}
    text = full_reproduction.report_md.read_text()
    run = _section(text, 13)
    assert "`simulation_inputs.json`, one record per simulation, 36 in all: 18 for" in run
    assert "3 for the FE-reference impacts of Section 4 (law 'tabulated')" in run
    assert "15 for the rows of Section 11 (keyed by configuration)" in run
    assert "one record per row of the tables" not in text


@pytest.mark.parametrize(
    "key",
    [
        "20 deg, ghaednia, impulse_ratio",  # a row of Tables 2-4
        "45 deg, tabulated, coulomb",  # an FE-reference impact
        f"70 deg, {CS}",  # a drop on the rate-dependent flat
        f"20 deg, {FE_HARD}",  # a drop with the FE-tabulated law of a hardening flat
    ],
)
def test_a_record_of_each_kind_runs_again_to_the_same_numbers(full_reproduction, key):
    records = json.loads(full_reproduction.files["simulation_inputs"].read_text())
    again = il.rerun(records[key])
    ang = int(key.split()[0])
    if key.endswith("impulse_ratio"):
        s = full_reproduction.simulations
        row = s[(s["angle [deg]"] == ang) & (s["law"] == "ghaednia")]
        row = row[row["friction"] == "impulse_ratio"].iloc[0]
        assert again.e == row["e"] and again.duration * 1e3 == row["T [ms]"]
    elif key.endswith("tabulated, coulomb"):
        fe = pd.read_csv(full_reproduction.files["fe_reference"])
        row = fe[(fe["angle [deg]"] == ang) & fe["law"].str.startswith("tabulated")].iloc[0]
        assert again.e == pytest.approx(row["e"], rel=1e-15)
        assert again.delta_p * 1e6 == pytest.approx(row["delta_p [um]"], rel=1e-15)
    else:
        p = full_reproduction.extras["physics"]
        row = p[(p["angle [deg]"] == ang) & (p["configuration"] == key.split(", ", 1)[1])]
        row = row.iloc[0]
        assert again.e == row[E_COLUMN]
        assert abs(again.dent_depth) * 1e6 == row["delta_p [um]"]
        assert abs(again.scar_length) * 1e6 == row[SCAR_COLUMN]


def test_without_the_simulations_the_numbers_not_compared_are_counted(analytic):
    """34 published numbers (Tables 2-3 and the Sec. 5.2 text) are not compared: the count,
    Section 1 and Section 5 say so beside the one not reproduced (they said only "1 published
    number not reproduced")."""
    assert Q.comparison_counts(analytic.comparison) == (1, 34)
    line = Q.not_reproduced_line(1, 34)
    assert line.startswith("1 published number not reproduced within the stated tolerances, and")
    assert "34 not compared: the simulations were skipped (--no-simulate" in line
    assert Q.not_reproduced_line(19) == (
        "19 published numbers not reproduced within the stated tolerances (explained in "
        "Section 5 of the report)"
    )
    # the command's line counts the UNDECIDED 20 deg T apart: neither reproduced nor not
    assert Q.verdict_counts(analytic.comparison) == (2, 1)
    assert Q.summary_line(analytic.comparison) == (
        "2 published numbers reproduced within the stated tolerances, 1 undecided (the printed "
        "digits allow either), 1 not reproduced, and 34 not compared: the simulations were "
        "skipped (--no-simulate; Section 5 of the report lists them)"
    )
    text = analytic.report_md.read_text()
    one = _section(text, 1)
    assert "Not compared: 34 published numbers of the paper's simulations" in one
    # the section's counts are the command's line's: the undecided one is counted apart
    assert (
        "of the others, 2 reproduced, 1 undecided (the printed digits allow either) and 1 not "
        "reproduced (Section 5 lists the not compared and the not reproduced)"
    ) in " ".join(one.split())
    five = _section(text, 5)
    assert (
        "Not compared: 34 published numbers of the paper's simulations (Table 2: 15 (delta_p, "
        "L_s, e, T, F); Sec. 5.2 text: 4 (T, F, L_s); Table 3: 15 (delta_p, L_s, e, T, F)), "
        "because the simulations were skipped"
    ) in five
    assert "Simulations not run (`--no-simulate`): impactlab's numbers" in _section(text, 4)


def test_without_the_simulations_every_skipped_part_is_named(analytic, full_reproduction):
    """Section 1 names every section, part, figure and file left out (it named Sections 7, 11
    and 12 only: Fig. 4, the force plots and the FE-reference part of Section 4 went unsaid)."""
    one = _section(analytic.report_md.read_text(), 1)
    for part in (
        "Section 7 (",
        "Section 11 (",
        "Section 12 (",
        "the paper's laws against the FE reference",
        "the simulations against the experiments with the paper's 70 deg statements",
        "in Section 9, Fig. 4 (the simulated dent) and the three force plots",
        "in Section 13, the record of every simulation's input",
    ):
        assert part in one, part
    written = {p.name for p in analytic.files.values()}
    everything = {p.name for p in full_reproduction.files.values()}
    for name in everything - written:
        assert name in one, name
    assert "Simulations not run" not in full_reproduction.report_md.read_text()


def test_section_1_says_which_of_the_papers_figures_are_regenerated(analytic, full_reproduction):
    fig4 = {
        "full": "and Fig. 4 (the simulated dent at 20 deg).",
        "analytic": "with the simulations only (not in this run), Fig. 4",
    }
    for res, kind in ((full_reproduction, "full"), (analytic, "analytic")):
        one = _section(res.report_md.read_text(), 1)
        assert "The paper's figures: Section 9 regenerates Fig. 5 (alpha against the angle)" in one
        assert fig4[kind] in one
        assert "Figs. 1-3 are schematics" in one and "Figs. 6-8 the measured scans" in one
    assert "fig4_dent.png" in {p.name for p in full_reproduction.files.values()}
    assert "fig4_dent.png" not in {p.name for p in analytic.files.values()}


def test_the_70_deg_check_states_its_criterion(full_reproduction):
    s = full_reproduction.simulations
    e70 = s[s["angle [deg]"] == 70]["e_gravity_removed"]  # as the measured e: like for like
    text = full_reproduction.report_md.read_text()
    assert (
        "- the simulated e is significantly larger than the measured 0.05 (criterion: every "
        f"simulated e more than 2 times it, above 0.1; they are {e70.min():.3g}-{e70.max():.3g}, "
        "gravity's impulse removed): yes"
    ) in text


def test_the_physics_conclusion_is_that_of_no_damping_and_names_the_calibrated_one(
    full_reproduction,
):
    """Section 11's verdicts are at zeta = 0; with the damping Section 12 fits the Cowper-Symonds
    row's e at 20 deg is within the same 0.03 (0.4887 against 0.5), and the conclusion says so
    (it said "they do not explain e ... at any angle" unqualified)."""
    eleven = _section(full_reproduction.report_md.read_text(), 11)
    assert "at an angle where the undamped flexible rod, zeta = 0," in eleven
    assert (
        "without damping (zeta = 0 in every row), they explain the dent depth at 20 and 70 deg"
    ) in eleven
    assert (
        "but they do not explain e, the scar or the duration at any angle. With the damping "
        "ratio the next section fits (its best fits, column 'best fit'): e comes within 0.03 at "
        f"20 deg ({CS}: 0.489 against the measured 0.5), not at 45 and 70 deg; the scar comes "
        "within 10 % at no angle; the duration is not among its measurements."
    ) in eleven


def _checks(rows: list[tuple[str, str, str, float, float]]) -> dict[str, object]:
    return {
        "ranking": [
            {"configuration": "rigid rod", "zeta median": None},
            {"configuration": "flexible rod", "zeta median": 0.14},
        ],
        "checks": [
            {"configuration": c, "drop": d, "quantity": q, "measured": m, "best fit": b}
            for c, d, q, m, b in rows
        ],
    }


def test_the_damped_sentence_follows_the_calibration():
    """Only a configuration with a fitted zeta counts (the rigid rod's best fit is its
    undamped one), each within the section's tolerance, by angle."""
    cal = _checks(
        [
            ("rigid rod", "20 deg", "e", 0.5, 0.5),  # no damping fitted: not counted
            ("flexible rod", "20 deg", "e", 0.5, 0.45),
            ("flexible rod", "45 deg", "e", 0.49, 0.47),
            ("flexible rod", "70 deg", "e", 0.05, 0.2),
            ("flexible rod", "20 deg", "scar_length", 1400.0, 1300.0),
        ]
    )
    cal["checks"][-1]["quantity"] = "scar_length [um]"  # type: ignore[index]
    text = damped(cal, [E_COLUMN, SCAR_COLUMN], 3)
    assert text == (
        "With the damping ratio the next section fits (its best fits, column 'best fit'): e "
        "comes within 0.03 at 45 deg (flexible rod: 0.47 against the measured 0.49), not at 20 "
        "and 70 deg; the scar comes within 10 % at 20 deg (flexible rod: 1300 against the "
        "measured 1400)."
    )
    assert damped(_checks([]), [E_COLUMN], 3).endswith("e comes within 0.03 at no angle.")


def test_the_command_counts_the_numbers_not_compared(analytic, tmp_path, monkeypatch, capsys):
    """``impactlab reproduce --no-simulate`` prints every count: reproduced, UNDECIDED, not
    reproduced and not compared (it printed only "1 published number not reproduced ...")."""
    import impactlab.cli.reproduce as cli_reproduce

    monkeypatch.setattr(R, "reproduce", lambda out, simulate: analytic)
    cli_reproduce.reproduce_cmd(out=str(tmp_path / "o"), no_simulate=True)
    assert Q.not_reproduced_line(1, 34, 2, 1) in capsys.readouterr().out.splitlines()


def test_the_full_runs_summary_counts_each_verdict(full_reproduction):
    """With the simulations every published number compared is counted once, under one of
    reproduced, UNDECIDED (the 20 deg experimental T), not reproduced and within tolerance by
    coincidence (the Sec. 5.2 text's Ghaednia F)."""
    assert Q.summary_line(full_reproduction.comparison) == (
        "17 published numbers reproduced within the stated tolerances, 1 undecided (the "
        "printed digits allow either), 19 not reproduced, 1 within its tolerance but not "
        "counted as reproduced (most likely a coincidence) (explained in Section 5 of the report)"
    )
    # every published number compared is counted once: the four counts add up to the 38
    rows = full_reproduction.comparison.drop_duplicates(Q.PUBLISHED_KEY)
    inputs = rows["reason"].fillna("").astype(str).str.startswith("measured input")
    assert 17 + 1 + 19 + 1 == len(rows[rows["published"].notna() & ~inputs]) == 38


def test_the_tutorial_quotes_the_commands_summary_line(analytic, full_reproduction):
    """docs/tutorials/reproduce.md quotes the command's count line of both runs."""
    page = " ".join((ROOT / "docs" / "tutorials" / "reproduce.md").read_text().split())
    assert f"`{Q.summary_line(full_reproduction.comparison)}`" in page
    quiet = Q.summary_line(analytic.comparison)
    assert f"`{quiet.split(': the simulations')[0]}: ...`" in page


def test_the_consistency_ratio_and_the_recorded_values_are_the_tables(full_reproduction):
    """Section 6 states the range of F T / P its table shows (it said "about 2.4" over
    1.99-2.44), and Section 10 prints its numbers with the report's 4 significant digits."""
    text = full_reproduction.report_md.read_text()
    six = " ".join(_section(text, 6).split())
    assert "their F T is 1.99-2.44 times P (Table 2: 2.25-2.39; Table 3: 2.30-2.44;" in six
    ten = _section(text, 10)
    assert "v_Of / \\|v_i\\|: 0.4954 |" in ten
    assert "0.4954128" not in ten
    assert "Table 2: 2571; Sec. 5.2 text: 2153" in ten
