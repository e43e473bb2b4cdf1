"""``impactlab explain``: JSON with units, the table, the output folder's rule (its own files
replaced, a user's never), one-line errors."""

from __future__ import annotations

import json
import sys

from impactlab._json import shape_problems


def test_json_parses_and_names_units(cli_main, paper_file) -> None:
    code, out, err = cli_main("explain", str(paper_file), "--json", "--quiet")
    assert code == 0, err
    doc = json.loads(out)
    assert shape_problems(doc) == []  # docs/json-schema.md: every number a quantity
    first = doc["comparison"][0]
    assert first["measured"] == {"value": 0.5, "unit": "1", "sigma": 0.03}
    dents = [r for r in doc["comparison"] if r["quantity"] == "delta_p"]
    assert {r["predicted"]["unit"] for r in dents} == {"m"}
    assert doc["summary"][1]["n_contacts"] == 4 and doc["summary"][1]["configuration"] == (
        "flexible rod"
    )
    # the summary's flags are the bitmask, as everywhere; their names and the count beside them
    first = doc["summary"][0]
    assert first["flags"] == 4 and first["flag_names"] == "law_extrapolated"
    assert first["n_measured"] == 3 and "measured" not in first
    assert doc["nothing_tuned"].startswith("nothing is tuned")
    assert "measurement's sigma alone" in doc["z"]
    assert doc["files"] == {}


def test_the_table_and_its_notes(cli_main, paper_file) -> None:
    code, out, err = cli_main("explain", str(paper_file), "--rate", "none", "--quiet")
    assert code == 0, err
    assert "measured (+- sigma)" in out and "delta_p [um]" in out and "0.7239 (z +7.46)" in out
    assert "rate-dependent" not in out
    assert "note: nothing is tuned" in out and "note: z = (predicted - measured) / sigma" in out


def test_out_replaces_its_own_files_and_refuses_a_users(cli_main, paper_file, tmp_path) -> None:
    out = tmp_path / "explained"
    args = ("explain", str(paper_file), "--rate", "none", "--quiet", "--out", str(out))
    assert cli_main(*args)[0] == 0
    csv = (out / "explain.csv").read_text()
    assert csv.startswith("drop,configuration,quantity,measured,sigma,predicted,z,")
    assert cli_main(*args)[0] == 0  # an earlier explanation's files: replaced
    (out / "explain.csv").write_text("my,own\n1,2\n")
    code, stdout, err = cli_main(*args)
    assert code == 2 and stdout == ""
    assert err.startswith(f"error: '{out / 'explain.csv'}' is in the output folder but was not "
                          "written by impactlab explain")  # fmt: skip
    assert err.count("\n") == 1 and "--out" in err
    assert (out / "explain.csv").read_text() == "my,own\n1,2\n"  # left as it was


def test_one_line_errors(cli_main, tmp_path, paper_file) -> None:
    bad = tmp_path / "bad.csv"
    bad.write_text("label,angle [deg],vy [m/s],mu,e\na,20,-1.41,0.2,0.5\n")
    no_mu = tmp_path / "no_mu.csv"
    no_mu.write_text("label,angle [deg],vy [m/s],e,e_sigma\na,20,-1.41,0.5,0.03\n")
    cases = [
        ((str(bad),), "sigma"),
        ((str(no_mu),), "no_mu.csv: drop 1 (a) gives no mu: "),
        ((str(tmp_path / "none.csv"),), "measurements file not found"),
        ((str(paper_file), "--law", "ghaednya"), "ghaednia"),
        ((str(paper_file), "--rate", "cowper"), "--rate must be one of"),
        ((str(paper_file), "--rate", "cowper-symonds(D=-1 1/s, q=4)"), "--rate D must be > 0"),
        ((str(paper_file), "--rate", "cowper-symonds(D=1 m, q=4)"), "--rate D: '1 m' has the"),
        ((str(paper_file), "--rate", "cowper-symonds(D=1 1/s)"), "--rate 'cowper-symonds(D="),
        ((str(paper_file), "--rate", "none", "--rate", "none"), "--rate: 'none' is no rate"),
    ]
    for args, words in cases:
        code, out, err = cli_main("explain", *args, "--quiet")
        assert code == 2 and out == "", (args, err)
        assert err.startswith("error: ") and err.count("\n") == 1 and words in err, (args, err)
        assert "rate_laws" not in err, err  # the option, never the Python keyword


def test_the_bar_leaves_stderr_alone_and_gives_way_to_a_compile(monkeypatch) -> None:
    """On a terminal the bar does not take stderr over (the compile notice of a first run
    updates its one line there with carriage returns), and a compile notice about to be shown
    takes the bar off the screen until the next report."""
    from impactlab import _compile_notice
    from impactlab.cli.explain import _progress

    monkeypatch.setenv("FORCE_COLOR", "1")  # rich: a terminal
    report, bar = _progress(quiet=False)
    stderr = sys.stderr
    try:
        report("rigid body", 1, 4)
        assert bar.live.is_started and sys.stderr is stderr
        with _compile_notice.gives_way(bar):
            _compile_notice._clear_displays()  # what a notice does before its line
        assert not bar.live.is_started
        report("flexible rod", 2, 4)
        assert bar.live.is_started
    finally:
        bar.stop()
