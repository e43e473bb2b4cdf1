"""The LAW_EXTRAPOLATED flag of the simulated rows: the tables' flags columns, the report's mark
and paragraph, the reproduce command's count line, and its wording of the not-reproduced count."""

from __future__ import annotations

from types import SimpleNamespace

import pandas as pd
import pytest

from impactlab.contact.ranges import RANGES
from impactlab.paper import data as D
from impactlab.paper.analytic_rows import experimental_rows, published_consistency
from impactlab.paper.comparison import comparison_table, side_by_side
from impactlab.paper.quantities import (
    EXTRAPOLATED_MARK,
    count_extrapolated,
    extrapolation_line,
    flag_names,
    sim_value,
)
from impactlab.paper.report_simulated import _extrapolation_note, _marked
from impactlab.paper.simulations import run_simulations, simulation_table


@pytest.fixture(scope="module")
def sims20():
    return run_simulations(angles=(20,), history=False)


def test_simulation_table_carries_flags(sims20):
    tab = simulation_table(sims20)
    assert {"flags", "max_delta_ratio"} <= set(tab.columns)
    for (_ang, law, fr), res in sims20.items():
        row = tab[(tab["law"] == law) & (tab["friction"] == fr)].iloc[0]
        assert row["flags"] == flag_names(res)
        assert row["max_delta_ratio"] == pytest.approx(res.max_delta_ratio)
        assert ("LAW_EXTRAPOLATED" in row["flags"]) == res.extrapolated
        assert row["e"] == res.e  # the numbers are unchanged
    g = tab[tab["law"] == "ghaednia"]
    assert (g["flags"] == "LAW_EXTRAPOLATED").all()
    assert (g["max_delta_ratio"] > RANGES["ghaednia"].delta_ratio_max).all()
    assert (tab[tab["law"] == "kogut-komvopoulos"]["flags"] == "LAW_EXTRAPOLATED").all()
    # Brake has no fitted range but a verified one (2 delta_c for the paper's pair): flagged
    assert (tab[tab["law"] == "brake"]["flags"] == "LAW_EXTRAPOLATED").all()
    assert count_extrapolated(tab) == (6, 6)
    assert extrapolation_line(tab) == (
        "6 of 6 simulated impacts lie beyond their law's verified range "
        "(FE, 10 % force / 0.05 delta_r/delta_max); see report"
    )


def test_comparison_and_side_by_side_carry_flags(sims20):
    comp = comparison_table(sims20, experimental_rows(), published_consistency())
    sim = comp[(comp["angle [deg]"] == 20) & (comp["model"] == "ghaednia")]
    assert (sim["flags"] == "LAW_EXTRAPOLATED").all()
    assert (sim["max_delta_ratio"] > 110).all()
    exp = comp[comp["model"] == "experiment"]
    assert (exp["flags"] == "").all() and exp["max_delta_ratio"].isna().all()
    # the published-vs-impactlab numbers are the results'
    res = sims20[(20, "ghaednia", "impulse_ratio")]
    e_row = sim[(sim["friction"] == "impulse_ratio") & (sim["quantity"] == "e")].iloc[0]
    assert e_row["impactlab"] == sim_value(res, "e")
    wide = side_by_side(comp, 20)
    g = wide[wide["model"] == "ghaednia"]
    assert (g["flags"] == "LAW_EXTRAPOLATED").all()
    assert (wide[wide["model"] == "experiment"]["flags"] == "").all()


def test_report_marks_flagged_rows_and_explains(sims20):
    tab = simulation_table(sims20)
    shown = _marked(tab, "law")
    flagged = tab["flags"].str.contains("LAW_EXTRAPOLATED")
    assert (shown.loc[flagged, "law"] == tab.loc[flagged, "law"] + f" {EXTRAPOLATED_MARK}").all()
    assert (shown.loc[~flagged, "law"] == tab.loc[~flagged, "law"]).all()
    assert _marked(pd.DataFrame({"law": ["x"]}), "law")["law"].tolist() == ["x"]
    note = _extrapolation_note(tab)
    assert note.startswith(f"{EXTRAPOLATED_MARK} LAW_EXTRAPOLATED: 6 of 6")
    assert "FE, 10 % force / 0.05 delta_r/delta_max" in note
    # each law's range in the result's own words (law_range: the limit in Jackson-Green's
    # delta_c and in the law's own reference), beside the ratio in that own reference
    for (_, law, _), res in sims20.items():
        assert f"{law}: {res.law_range}, max delta/" in note, law
    assert "verified against FE up to 1 delta_c (E*/S_y = 360.3" in note
    assert "up to 0.3 delta_c (Jackson-Green's; = 0.305 delta_y, the law's own;" in note
    assert "), max delta/delta_y here " in note
    assert "brake: verified against FE up to 2 delta_c (Jackson-Green's; = 2.01 delta_y" in note
    # outside the FE cases: the smallest verified range, not Kogut & Etsion's former 110 delta_c
    assert "former" not in note
    assert "keeps the stand-in, the law's smallest verified range over the FE cases" in note


def _fake_result(tmp_path, simulations):
    experimental = experimental_rows()
    comparison = pd.DataFrame(
        {
            "source": ["Table 2"],
            "angle [deg]": [20],
            "model": ["ghaednia"],
            "quantity": ["e"],
            "reproduced": [False],
        }
    )
    return SimpleNamespace(
        experimental=experimental,
        comparison=comparison,
        simulations=simulations,
        report_md=tmp_path / "report.md",
        report_html=tmp_path / "report.html",
        elapsed_s=1.0,
    )


@pytest.mark.parametrize("simulate", [True, False])
def test_cli_prints_flag_count_and_wording(tmp_path, monkeypatch, capsys, simulate):
    """The command's stdout (the reproduction replaced by a stand-in)."""
    import impactlab.cli.reproduce as cli_reproduce
    import impactlab.paper.reproduction as reproduction  # the command imports it when it runs

    simtab = pd.DataFrame({"law": ["ghaednia", "brake"], "flags": ["LAW_EXTRAPOLATED", ""]})
    fake = _fake_result(tmp_path, simtab if simulate else pd.DataFrame())
    monkeypatch.setattr(reproduction, "reproduce", lambda out, simulate: fake)
    cli_reproduce.reproduce_cmd(out=str(tmp_path / "o"), no_simulate=not simulate)
    out = capsys.readouterr().out
    assert (
        "0 published numbers reproduced within the stated tolerances, 0 undecided (the "
        "printed digits allow either), 1 not reproduced (explained in Section 5 of the report)"
    ) in out
    assert "(within the tolerances)" not in out
    line = (
        "1 of 2 simulated impacts lie beyond their law's verified range "
        "(FE, 10 % force / 0.05 delta_r/delta_max); see report"
    )
    assert (line in out) == simulate
    assert D.ANGLES_DEG  # the paper's angles are still the three of the tables


def test_section5_marks_flagged_models():
    from impactlab.paper.report_reasons import _explained

    bad = pd.DataFrame(
        {
            "source": ["Table 2", "Table 2"],
            "angle [deg]": [20, 20],
            "model": ["ghaednia", "brake"],
            "friction": ["impulse_ratio", "impulse_ratio"],
            "quantity": ["e", "e"],
            "published": [0.5, 0.6],
            "impactlab": [0.4, 0.3],
            "rel. diff": [-0.2, -0.5],
            "reproduced": [False, False],
            "reason": ["because 1", "because 2"],
            "flags": ["LAW_EXTRAPOLATED", ""],
        }
    )
    table, _notes = _explained(bad)
    assert table["model"].tolist() == [f"ghaednia {EXTRAPOLATED_MARK}", "brake"]
    assert _explained(bad.drop(columns="flags"))[0]["model"].tolist() == ["ghaednia", "brake"]
