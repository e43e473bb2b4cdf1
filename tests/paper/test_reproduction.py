"""The reproduction: output-folder safety, the analytic part, and the full run end to end."""

from __future__ import annotations

import json
import re
import shutil
import sys
from pathlib import Path

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
    # the folder is named as the user gave it: the option, not the Python keyword
    assert f"--out {str(tmp_path)!r} is not empty" in err and "out_dir" not in err
    assert [p.name for p in tmp_path.iterdir()] == ["keep.txt"]


def test_python_refusal_names_the_keyword(tmp_path):
    (tmp_path / "keep.txt").write_text("x")
    with pytest.raises(ValueError, match=r"^out_dir '.*' is not empty"):
        R.reproduce(tmp_path, simulate=False)


@pytest.mark.parametrize("value", ["False", 0, 1, None])
def test_simulate_must_be_a_bool(tmp_path, value):
    out = tmp_path / "never"
    with pytest.raises(TypeError) as exc:
        R.reproduce(out, simulate=value)
    assert str(exc.value) == f"simulate must be True or False, got {value!r}"
    assert not out.exists()  # refused before anything is written


@pytest.mark.parametrize("angles", [(30,), (20, 30), 30, ("20",), (True,)])
def test_simulations_refuse_other_angles(angles):
    from impactlab.paper.physics import run_physics
    from impactlab.paper.simulations import run_simulations

    bad = next(a for a in (angles if isinstance(angles, tuple) else (angles,)) if a != 20)
    line = f"angles: {bad!r} is not an angle of the paper's experiments (allowed: 20, 45, 70 deg)"
    for run in (run_simulations, run_physics):
        with pytest.raises(ValueError, match=r"^angles: ") as exc:
            run(angles=angles)
        assert str(exc.value) == line


@pytest.fixture(scope="module")
def analytic_run(analytic_reproduction):
    return analytic_reproduction  # conftest.py: into "new/folder", made with its parents


def test_analytic_part(analytic_run):
    res = analytic_run
    exp = res.experimental.set_index("angle [deg]")
    # the T checks are decided over the rounding of the printed numbers, not at the point
    # (-4.5 % lies within 5 %, yet -5.7 % to -3.3 % straddles it): the comparison says so
    comp = res.comparison
    checks = comp[(comp["model"] == "experiment") & (comp["quantity"] == "T [ms]")]
    checks = checks[checks["published"].notna()].set_index("angle [deg]")
    assert checks.loc[20, "verdict"] == "UNDECIDED" and checks.loc[20, "reproduced"] is None
    assert checks.loc[45, "verdict"] == "PASS" and checks.loc[45, "reproduced"] is True
    assert res.report_md.is_file() and res.report_html.is_file()
    assert (res.out_dir / R.MARKER).is_file()
    # published rows are not self-consistent: F T is ~2.4 times the allowed impulse
    cons = res.consistency
    tab = cons[cons["source"].isin(["Table 2", "Table 3"])]
    assert (tab["ratio"] > 2.2).all() and (tab["ratio"] < 2.5).all()
    # the rigid-body bound over the printed rounding: two 45 deg rows exceed it beyond the
    # rounding, Kogut-Komvopoulos's lies within the rounding of it (undecidable)
    rows = tab["angle [deg]"].astype(str) + " " + tab["model"]
    outcome = dict(zip(rows, tab["vs bound"], strict=True))
    assert outcome == {
        "20 ghaednia": "within",
        "20 brake": "within",
        "20 kogut-komvopoulos": "within",
        "45 ghaednia": "exceeds",
        "45 brake": "exceeds",
        "45 kogut-komvopoulos": "within rounding",
    }
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
    assert re.search(r"20 deg: T = 4\.106 ms vs published 4\.30 ms .*UNDECIDED", text)
    assert re.search(r"45 deg: T = 1\.382 ms vs published 1\.40 ms .*PASS", text)
    # the headline says what the PASS checks, and what it does not
    assert "What was checked, and what was not" in text
    assert "it does not check that T is the duration of the impact" in text
    assert "paper's sign" in text  # the paper's negative depths only under that label
    assert '<img src="data:image/png;base64,' in html  # self-contained (figures embedded)
    # --no-simulate skips "Can physics explain the experiment?"
    assert "Can physics explain" not in text
    assert "physics_comparison" not in analytic_run.files


def test_rerun_into_previous_reproduction_keeps_other_files(analytic_run, tmp_path):
    out = tmp_path / "previous"
    shutil.copytree(analytic_run.out_dir, out)
    (out / "my_notes.txt").write_text("mine")
    res = R.reproduce(out, simulate=False)
    assert (out / "my_notes.txt").read_text() == "mine"
    assert res.report_md.is_file()


def test_the_files_that_share_the_full_run_are_run_by_one_worker(request) -> None:
    """``pytest -n N --dist loadfile`` hands each group of files to one worker: every test file
    of this folder is in one group, so the package's ``full_reproduction`` (``reproduce`` with
    the simulations) is computed once per test run, not once per worker."""
    root = Path(__file__).resolve().parents[2]
    conftest = request.config.pluginmanager.get_plugin(str(root / "conftest.py"))
    groups = {
        conftest.same_worker_group(p.relative_to(root).as_posix())
        for p in Path(__file__).parent.glob("test_*.py")
    }
    assert groups == {"paper reproduction"}


@pytest.fixture(scope="module")
def full_run(full_reproduction):
    return full_reproduction  # conftest.py: one run for the paper's tests


def test_rerun_removes_the_earlier_runs_files(full_run, tmp_path, recwarn):
    """A full run, then one without the simulations into the same folder: the files only the
    first wrote are removed, each said in one warning; the folder holds the second run only."""
    out = tmp_path / "again"
    shutil.copytree(full_run.out_dir, out)
    (out / "my_notes.txt").write_text("mine")
    first = json.loads((out / R.MARKER).read_text())["files"]
    res = R.reproduce(out, simulate=False)
    ours = {p.name for p in res.files.values()}
    stale = sorted(set(first) - ours)
    assert {"simulations.csv", "fig4_dent.png", "fe_reference.csv"} <= set(stale)
    assert {p.name for p in out.iterdir()} == ours | {R.MARKER, "my_notes.txt"}
    assert (out / "my_notes.txt").read_text() == "mine"
    assert res.extras["removed"] == tuple(stale)
    said = [str(w.message) for w in recwarn if issubclass(w.category, R.ReproductionWarning)]
    assert said == [
        f"removed {str(out / name)!r}, left by an earlier run (this run does not write it)"
        for name in stale
    ]
    marker = json.loads((out / R.MARKER).read_text())
    assert marker["status"] == "complete" and marker["files"] == sorted(ours)


def test_marker_names_only_files_in_the_folder(tmp_path):
    """A marker listing a path outside its folder (or the marker itself) removes nothing there."""
    out = tmp_path / "r"
    out.mkdir()
    outside = tmp_path / "precious.txt"
    outside.write_text("keep")
    files = ["../precious.txt", str(outside), R.MARKER, "..", 7]
    (out / R.MARKER).write_text(json.dumps({"tool": "impactlab reproduce", "files": files}))
    res = R.reproduce(out, simulate=False)
    assert outside.read_text() == "keep" and res.extras["removed"] == ()


def test_a_failed_run_keeps_the_list_of_its_files(tmp_path, monkeypatch):
    """A run that stops half way leaves a marker listing the earlier run's files and those it
    wrote, so that the next run still removes them."""
    out = tmp_path / "r"
    out.mkdir()
    (out / "simulations.csv").write_text("x")
    (out / R.MARKER).write_text(json.dumps({"status": "complete", "files": ["simulations.csv"]}))

    def stop(*args, **kwargs):
        raise RuntimeError("stopped")

    monkeypatch.setattr(R, "_write_report", stop)
    with pytest.raises(RuntimeError, match="stopped"):
        R.reproduce(out, simulate=False)
    marker = json.loads((out / R.MARKER).read_text())
    assert marker["status"] == "failed"
    assert {"simulations.csv", "comparison.csv", "fig5_alpha.png"} <= set(marker["files"])


def test_cli_lines_share_the_reports_format(full_run, tmp_path, monkeypatch, capsys):
    """The command prints each acceptance check as the report's Section 1 does, and the run
    time as the report's Run section (one decimal)."""
    monkeypatch.setattr(sys, "argv", ["impactlab", "reproduce", "--out", str(tmp_path / "o")])
    monkeypatch.setattr(R, "reproduce", lambda out, simulate: full_run)
    main()
    out = capsys.readouterr().out
    text = full_run.report_md.read_text()
    for line in (
        "20 deg: T = 4.106 ms vs published 4.30 ms (-4.5%; -5.7% to -3.3% over the printed "
        "digits, tolerance 5%): UNDECIDED",
        "45 deg: T = 1.382 ms vs published 1.40 ms (-1.3%; -2.6% to +0.1% over the printed "
        "digits, tolerance 5%): PASS",
    ):
        assert line in out.splitlines() and f"- {line}" in text.splitlines()
    assert f"(reproduced in {full_run.elapsed_s:.1f} s after the imports" in out


def test_end_to_end(full_run):
    res = full_run
    out = res.out_dir
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
    assert len(records) == 36 and "simulation_inputs.json" in text  # 18 + 3 FE + 15 drops
    again = il.rerun(records["20 deg, ghaednia, impulse_ratio"])
    assert f"{again.e:.4g}" == f"{g20['e']:.4g}"
    # the headline names the simulated durations' disagreement with a factor
    exp_T = res.experimental.set_index("angle [deg]")["T [ms]"]
    low = (sims["T [ms]"] / sims["angle [deg]"].map(exp_T)).min()
    assert f"every simulated impact lasts {low:.2g}-" in text
    # the paper's simulated T, each source named: the tables' ranges, and the text's 0.256 ms
    assert (
        "Against the paper's own simulated T, impactlab's are -51.0% to -46.0% against Table 2; "
        "-52.2% to -38.9% against the Sec. 5.2 text's 0.256 ms; -52.9% to -50.4% against "
        "Table 3 (Section 5)."
    ) in text
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


def test_report_says_what_its_verdicts_rest_on(full_run):
    """Section 1: the acceptance PASS rests on the mixed reading of the rod's length (the
    self-consistent readings' numbers given); Section 4: the paper's claim about e in numbers;
    Sections 5 and 6: the rigid-body bound over the printed rounding, and the reason that L_s
    follows T with the numbers of |delta_p| and |v_i| T."""
    text = full_run.report_md.read_text()
    readings = full_run.extras["length_readings"]
    overall = readings[readings["self-consistent"]].iloc[0]
    # +5.0003 %, but the printed numbers stand for +3.5 % to +6.5 %: undecided
    assert overall["T 45 deg rel. diff low"] < 0.05 < overall["T 45 deg rel. diff high"]
    assert (
        f"T = {overall['T 20 deg [ms]']:.3f} / {overall['T 45 deg [ms]']:.3f} ms "
        f"(+1.0% / +5.0%: PASS / UNDECIDED) with L the overall length"
    ) in text
    assert "+1.7% / +5.1%: PASS / UNDECIDED" in text
    assert "(4.106 / 1.382 ms at 20 / 45 deg: UNDECIDED / PASS)" in text
    assert (
        "at 20 deg, over the rounding of the printed inputs and T (the mixed reading: -5.7% to "
        "-3.3%, UNDECIDED), the PASS is certain only with L the overall length or the whole "
        "rod's I_C; at 45 deg, over the rounding of the printed inputs and T (L the overall "
        "length: +3.5% to +6.5%, UNDECIDED; the whole rod's I_C: +3.6% to +6.6%, UNDECIDED), "
        "the PASS is certain only with the mixed reading. No reading passes at both angles for "
        "certain."
    ) in text
    assert (
        "- 20 deg: T = 4.106 ms vs published 4.30 ms (-4.5%; -5.7% to -3.3% over the printed "
        "digits, tolerance 5%): UNDECIDED"
    ) in text
    assert "FAIL" not in text.split("What these verdicts depend on")[1].split("\n")[0]
    assert "As the paper says" not in text
    assert (
        "impactlab's simulated e lie -20.0% to -4.2% from the measured e there (2 of 6 beyond "
        "15%), the paper's own -16.3% to -8.0%: all below the measured e"
    ) in text
    assert (
        "Table 3 ghaednia (45 deg) and Table 3 brake (45 deg) exceed it beyond the rounding; "
        "Table 3 kogut-komvopoulos (45 deg) lies within the rounding of it"
    ) in text
    assert "<<" not in text
    assert "|delta_p| is smaller than |v_i| T (published 67 against 352 um; impactlab's" in text
    reasons = full_run.comparison.set_index(["source", "model", "friction", "quantity"])["reason"]
    brake_T = reasons[("Table 3", "brake", "coulomb", "T [ms]")]
    kk_T = reasons[("Table 3", "kogut-komvopoulos", "coulomb", "T [ms]")]
    assert "exceeds (1+e) m |v_i| = 1.42 N s" in brake_T and "beyond the rounding" in brake_T
    assert "and exceeds" not in kk_T and "the printed digits cannot tell" in kk_T
    assert "(F T 1.417-1.466 N s, bound 1.428-1.445 N s)" in kk_T
