"""The reproduction: output-folder safety, the analytic part, and the full run end to end."""

from __future__ import annotations

import json
import re
import sys

import pandas as pd
import pytest

import impactlab as il
from impactlab.analytic import invert
from impactlab.cli import main
from impactlab.paper import reproduction as R
from impactlab.paper.data import EXPERIMENTS
from impactlab.paper.quantities import PAPER_DEPTH


def test_refuses_foreign_non_empty_folder(tmp_path):
    (tmp_path / "thesis.tex").write_text("precious")
    with pytest.raises(ValueError, match="not empty"):
        R.reproduce(tmp_path, simulate=False)
    assert [p.name for p in tmp_path.iterdir()] == ["thesis.tex"]
    assert (tmp_path / "thesis.tex").read_text() == "precious"


def test_refuses_a_file(tmp_path):
    f = tmp_path / "x"
    f.write_text("")
    with pytest.raises(ValueError, match="not a folder"):
        R.prepare_output(f)


def test_cli_refusal_is_one_line(tmp_path, monkeypatch, capsys):
    (tmp_path / "keep.txt").write_text("x")
    monkeypatch.setattr(sys, "argv", ["impactlab", "reproduce", "--out", str(tmp_path)])
    with pytest.raises(SystemExit) as exc:
        main()
    assert exc.value.code == 2
    err = capsys.readouterr().err
    assert "refusing" in err and err.count("\n") == 1


@pytest.fixture(scope="module")
def analytic_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("repro_analytic") / "new" / "folder"
    return R.reproduce(out, simulate=False)


def test_analytic_part(analytic_run):
    res = analytic_run
    exp = res.experimental.set_index("angle [deg]")
    assert abs(exp.loc[20, "T rel. diff"]) <= 0.05
    assert abs(exp.loc[45, "T rel. diff"]) <= 0.05
    assert res.report_md.is_file() and res.report_html.is_file()
    assert (res.out_dir / R.MARKER).is_file()
    # published rows are not self-consistent: F T is ~2.4 times the allowed impulse
    cons = res.consistency
    tab = cons[cons["source"].isin(["Table 2", "Table 3"])]
    assert (tab["ratio"] > 2.2).all() and (tab["ratio"] < 2.5).all()
    assert tab[tab["angle [deg]"] == 45]["exceeds bound"].all()
    # inertia sensitivity: 1/12 row equals the experimental rows
    row = res.inertia[res.inertia["I_C/(m L^2)"].astype(str) == str(1 / 12)].iloc[0]
    assert row["T 20 deg [ms]"] == pytest.approx(exp.loc[20, "T [ms]"])


def test_report_numbers_match_library(analytic_run):
    text = analytic_run.report_md.read_text()
    html = analytic_run.report_html.read_text()
    for ang in (20, 45, 70):
        x = EXPERIMENTS[ang]
        T = invert(
            angle=x.angle,
            v_i=x.v_i,
            e=x.e,
            mu=x.mu,
            delta_p=abs(x.delta_p),
            sliding_length=abs(x.L_s),
            n_samples=100,
        ).duration
        assert f"{T * 1e3:.4g}" in text and f"{T * 1e3:.4g}" in html
    assert re.search(r"20 deg: T = 4\.106 ms vs published 4\.30 ms .*PASS", text)
    # the headline says what the PASS checks, and what it does not
    assert "What was checked, and what was not" in text
    assert "it does not check that T is the duration of the impact" in text
    assert "paper's sign" in text  # the paper's negative depths only under that label
    assert '<img src="data:image/png;base64,' in html  # self-contained (figures embedded)
    # --no-simulate skips "Can physics explain the experiment?"
    assert "Can physics explain" not in text
    assert "physics_comparison" not in analytic_run.files


def test_rerun_into_previous_reproduction_keeps_other_files(analytic_run):
    out = analytic_run.out_dir
    (out / "my_notes.txt").write_text("mine")
    res = R.reproduce(out, simulate=False)
    assert (out / "my_notes.txt").read_text() == "mine"
    assert res.report_md.is_file()


def test_end_to_end(tmp_path_factory):
    out = tmp_path_factory.mktemp("repro_full")
    res = R.reproduce(out)
    assert not res.extras.get("engine_error")
    # every simulation ran: 3 angles x 3 laws x 2 friction models
    assert len(res.simulations) == 18
    for name in (
        "fig4_dent",
        "fig5_alpha",
        "forces_20",
        "forces_45",
        "forces_70",
        "report_md",
        "report_html",
        "table2",
        "table3",
        "table4",
        "physics_comparison",
        "physics_drop_20",
        "fe_reference",
    ):
        assert res.files[name].is_file(), name
    # the paper's laws against the FE law of the paper's pair, in the same impacts
    fe = pd.read_csv(res.files["fe_reference"])
    assert len(fe) == 12 and fe["e vs FE"].isna().sum() == 3  # the FE rows: no difference
    brake = fe[fe["law"] == "brake"]
    assert (brake["F vs FE"].between(-0.25, -0.15)).all()  # Brake's force 15-25 % low
    assert "The paper's laws against the FE reference" in res.report_md.read_text()
    assert "Can physics explain the experiment?" in res.report_md.read_text()
    # every not-reproduced number carries a reason
    bad = res.comparison[res.comparison["reproduced"] == False]  # noqa: E712
    assert (bad["reason"].str.len() > 20).all()
    # the report's simulated numbers are the library's
    text = res.report_md.read_text()
    sims = res.simulations
    g20 = sims[
        (sims["angle [deg]"] == 20)
        & (sims["law"] == "ghaednia")
        & (sims["friction"] == "impulse_ratio")
    ].iloc[0]
    assert f"{g20['e']:.4g}" in text and f"{g20[PAPER_DEPTH]:.4g}" in text
    # every simulation's input, rerun to the same numbers
    records = json.loads(res.files["simulation_inputs"].read_text())
    assert len(records) == 18 and "simulation_inputs.json" in text
    again = il.rerun(records["20 deg, ghaednia, impulse_ratio"])
    assert f"{again.e:.4g}" == f"{g20['e']:.4g}"
    # the headline names the simulated durations' disagreement with a factor
    exp_T = res.experimental.set_index("angle [deg]")["T [ms]"]
    low = (sims["T [ms]"] / sims["angle [deg]"].map(exp_T)).min()
    assert f"every simulated impact lasts {low:.2g}-" in text
    assert "Against the paper's own simulated T (Tables 2-3), impactlab's are" in text
    # only our files in the folder
    allowed = {p.name for p in res.files.values()} | {R.MARKER}
    assert {p.name for p in out.iterdir()} <= allowed
    assert isinstance(res.tables["table2"], pd.DataFrame)
    # the LAW_EXTRAPOLATED flag: in the CSVs, marked in the report, explained once
    csv = pd.read_csv(res.files["table2"], keep_default_na=False)
    g = csv[csv["model"] == "ghaednia"]
    assert (g["flags"] == "LAW_EXTRAPOLATED").all()
    assert (g["max_delta_ratio"].astype(float) > 110).all()
    assert "flags" in pd.read_csv(res.files["simulations"]).columns
    assert "| Table 2 | ghaednia \u2020 |" in text
    assert "\u2020 LAW_EXTRAPOLATED: 18 of 18 simulated impacts" in text  # Brake too: verified
    assert "gravity impulse of the contact (sequence) removed" in text
