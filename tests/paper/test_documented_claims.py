"""docs/paper/reproduction.md's comparative claims against the numbers: the FE yardstick's own
bias on e (Hertzian unloading), within which no law is ranked on e, and the
undamped verdict on e of "Can physics explain the experiment?" beside the calibration's fitted
damping (e at 20 deg within 0.03)."""

from __future__ import annotations

import pytest

from impactlab.paper import fe_reference_rows as FR
from impactlab.paper.calibration_report import PAPER_SIGMAS, shipped_calibration

NUMBER = r"[-+]?\d+(?:\.\d+)?"
LAWS = {"ghaednia": "Ghaednia", "brake": "Brake", "kogut-komvopoulos": "Kogut-Komvopoulos"}


def test_the_fe_yardsticks_bias_on_e_is_the_shipped_datas():
    """The FE law's e against the 1-DOF impact on the FE curves themselves, as quoted, is what
    the shipped impact tables give (its unloading is Hertzian, theirs the FE's)."""
    from impactlab.verification.fe_impact import compare_impacts

    measured = []
    for case in ("paper-ball-on-aisi1010", "rod-mass-on-aisi1010"):
        c = compare_impacts(case, laws=("tabulated",))
        for fe_row, law_row in zip(
            c.columns["quasi-static FE 1-DOF"], c.columns["tabulated"], strict=True
        ):
            measured.append((fe_row["delta_max"] / c.delta_c, law_row["e"], fe_row["e"]))
    assert len(measured) == len(FR.UNLOADING_E_BIAS)
    for (ratio, law, fe), (q_ratio, q_law, q_fe) in zip(measured, FR.UNLOADING_E_BIAS, strict=True):
        assert round(ratio, 1) == q_ratio and round(law, 3) == q_law and round(fe, 3) == q_fe
        assert law < fe  # Hertzian unloading returns less energy than the FE's


def test_the_page_ranks_no_law_on_e_within_that_bias(page, fe):
    """docs/paper/reproduction.md states the bias with the module's numbers and takes it out
    with its sign: the FE law's e lies below the FE curves', so a negative 'e vs FE' is made
    larger, not absorbed (Brake's -4 % to -1 % once read as within a symmetric 4.5 % band)."""
    text = " ".join(page.reproduction.split())
    below = [1 - law / f for _, law, f in FR.UNLOADING_E_BIAS]
    shift = [f / law - 1 for _, law, f in FR.UNLOADING_E_BIAS]
    assert f"its e lies {100 * min(below):.1f}-{100 * max(below):.1f} % below" in text
    assert f"reads {100 * min(shift):.1f}-{100 * max(shift):.1f} % higher" in text
    laws = " / ".join(f"{law:.3f}" for _, law, _ in FR.UNLOADING_E_BIAS)
    fes = " / ".join(f"{f:.3f}" for _, _, f in FR.UNLOADING_E_BIAS)
    assert f"({laws} against {fes} at 7.9 / 58 / 315 `delta_c`" in text
    assert "closest" not in text and "steadiest" not in text
    assert "Brake's -4 % to -1 %" not in text  # no longer "within" the bias
    rows = fe.dropna(subset=["e vs FE"]).set_index(["angle [deg]", "law"])
    curves = rows["e vs FE curves"]
    brake = [f"{100 * curves[(a, 'brake')]:.1f}" for a in (20, 45, 70)]
    assert (
        f"Brake's e lies below the FE curves at every angle, by more than the FE law's own "
        f"bias: {brake[0]} / {brake[1]} / {brake[2]} % at 20 / 45 / 70 deg" in text
    )
    not_ranked = {k for k, r in rows.iterrows() if FR.in_bias(r["e vs FE"], -r["FE law's e bias"])}
    assert not_ranked == {(45, "ghaednia"), (20, "kogut-komvopoulos")}
    bias = rows["FE law's e bias"]
    assert all(curves[(a, "brake")] < bias[(a, "brake")] for a in (20, 45, 70))
    beyond = {
        (20, "ghaednia"): "-9",
        (70, "ghaednia"): "+21",
        (45, "kogut-komvopoulos"): "+15",
        (70, "kogut-komvopoulos"): "+37",
    }
    words = text[text.index("What the e column shows beyond the bias") :]
    for key, quoted in beyond.items():
        assert key not in not_ranked and f"{quoted} % at {key[0]} deg" in words
        assert round(100 * rows.loc[key, "e vs FE"]) == int(quoted)


def test_the_bias_is_applied_with_its_sign():
    """(1 + d)(1 - b) - 1: a law 4.4 % below the FE law, whose own e is 3.2 % low, lies about
    7.4 % below the FE curves, not within the bias; +2.7 % with b = 2.6 % is about 0."""
    assert FR.vs_fe_curves(-0.044, 0.032) == pytest.approx(-0.0746, abs=1e-4)
    assert FR.vs_fe_curves(0.027, 0.026) == pytest.approx(0.0003, abs=1e-4)
    assert not FR.in_bias(-0.012, 0.026)  # Brake at 70 deg: -3.8 % from the FE curves
    assert FR.in_bias(0.011, 0.032) and FR.in_bias(0.027, 0.026)
    b, beyond = FR.e_bias(315.4)
    assert b == pytest.approx(1 - 0.408 / 0.419) and not beyond
    assert FR.e_bias(654.0) == (b, True)  # held past the last measured point, and said so
    b178, beyond = FR.e_bias(178.6)
    assert 1 - 0.408 / 0.419 < b178 < 1 - 0.579 / 0.605 and not beyond


def test_the_energy_tables_ratio_is_not_the_bias_on_e():
    """docs/laws/tabulated.md's 0.912 at 300 delta_c unloads the law from the FE run's own
    delta_max, where the law's loading force is 2.7 % below the run's: the quoted numbers are
    the shipped data's."""
    from impactlab.contact.tabulated import Tabulated
    from impactlab.fe.curves import load_cases
    from impactlab.fe.tabulated import unloading_energy_ratios

    at, w_u, force = FR.UNLOADING_ENERGY_300
    case = next(c for c in load_cases() if c.name == "paper-aisi201-on-aisi1010")
    assert round(unloading_energy_ratios()[case.name][at], 3) == w_u
    model = Tabulated().build(case.pair, case.radius)
    (run,) = [r for r in case.runs if round(r.delta_max / case.delta_c) == at]
    assert round(model.force(run.delta_max) / max(run.loading_force), 3) == force
    assert w_u / force < 0.95 < (1 - 0.026) ** 2 + 0.002  # the rest: near the impact's 0.948


def test_the_reports_fe_text_states_the_bias():
    text = FR.FE_REFERENCE_TEXT
    assert "unloading is Hertzian" in text and "a negative d is made larger by it" in text
    assert "0.408" in text and "0.419" in text and "2.5-4.3 %" in text
    assert "0.912" in text and "not this bias" in text and "held at its 315 delta_c" in text


def _summary_table():
    import pandas as pd

    return pd.DataFrame(
        [
            {"law": law, "e vs FE": 0.01, "delta_p vs FE": 0.02, "F vs FE": 0.03}
            for law in ("ghaednia", "brake", "kogut-komvopoulos")
        ]
    )


def test_the_undamped_verdict_on_e_and_the_calibrated_damping(page):
    """The page's numbers of the calibrated Cowper-Symonds row are the shipped calibration's,
    and 20 deg is its only angle within the section's 0.03."""
    check, numbers = page.check, page.numbers
    zeta, best, measured = numbers(
        rf"the Cowper-Symonds row's best fit \(zeta median ({NUMBER})\) gives ({NUMBER}) against "
        rf"the measured ({NUMBER}), within the same 0.03",
        page.reproduction,
    )
    cal = shipped_calibration()
    name = "flexible rod + rate-dependent flat (Cowper-Symonds, upper estimate)"
    ranked = next(r for r in cal["ranking"] if r["configuration"] == name)
    check(zeta, ranked["zeta median"], "zeta median")
    rows = {
        r["drop"]: r for r in cal["checks"] if (r["configuration"], r["quantity"]) == (name, "e")
    }
    check(best, rows["20 deg"]["best fit"], "best fit of e at 20 deg")
    check(measured, rows["20 deg"]["measured"], "measured e at 20 deg")
    within = [d for d, r in rows.items() if abs(r["best fit"] - r["measured"]) <= PAPER_SIGMAS["e"]]
    assert within == ["20 deg"]
    assert "Without damping (every row of this table has zeta = 0) neither explains e" in " ".join(
        page.reproduction.split()
    )


@pytest.mark.parametrize("figures", ["Figs. 1-3 are\nschematics", "Figs. 6-8 the measured scans"])
def test_the_page_names_the_figures_not_regenerated(page, figures):
    assert " ".join(figures.split()) in " ".join(page.reproduction.split())
