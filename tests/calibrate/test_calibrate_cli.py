"""``impactlab calibrate``: JSON output, saved results and report, resuming, one-line errors."""

from __future__ import annotations

import json

import numpy as np
from typer.testing import CliRunner

from impactlab._json import shape_problems
from impactlab.calibrate import CandidateModel, parse_parameter
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.cli import app

runner = CliRunner()


def _drops(template, tmp_path):
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    data = synthetic_measurements(template, CandidateModel(), [mu], [0.15],
                                  np.random.default_rng(0))  # fmt: skip
    return data.to_csv(tmp_path / "drops.csv")


def test_json_and_files(template, tmp_path):
    path = _drops(template, tmp_path)
    out = tmp_path / "out"
    args = ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)", "-m", "ghaednia/coulomb",
            "--walkers", "8", "--steps", "30", "--out", str(out), "--json", "--quiet"]  # fmt: skip
    r = runner.invoke(app, args)
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    assert shape_problems(doc) == []  # docs/json-schema.md
    post = doc["models"]["ghaednia/coulomb"]
    assert 0.0 < post["parameters"]["mu"]["median"]["value"] < 0.6
    assert doc["ranking"][0]["model"] == "ghaednia/coulomb"
    assert doc["ranking"][0]["rank"] == 1  # as the table and calibration.json number it
    assert (out / "results.json").is_file() and (out / "report.html").is_file()
    html = (out / "report.html").read_text()
    assert "data:image/png;base64," in html and "<script" not in html  # self-contained
    assert (out / "state" / "ghaednia_coulomb.h5").is_file()
    # run again: the saved chain is complete, nothing is sampled again (only the checks)
    r2 = runner.invoke(app, args)
    assert r2.exit_code == 0, r2.output
    again = json.loads(r2.stdout)["models"]["ghaednia/coulomb"]
    assert again["parameters"]["mu"] == post["parameters"]["mu"]
    # the counts are the whole chain's, saved with it (not sampled again, not lost)
    assert again["evaluations"] == post["evaluations"]


def test_config_file_and_table(template, tmp_path):
    path = _drops(template, tmp_path)
    cfg = tmp_path / "cal.toml"
    cfg.write_text(
        f'measurements = "{path.name}"\nmodels = ["ghaednia/coulomb"]\n'
        '[parameters]\nmu = "uniform(0, 0.6)"\n[sampler]\nwalkers = 8\nsteps = 20\n'
    )
    r = runner.invoke(app, ["calibrate", "--config", str(cfg), "--quiet"])
    assert r.exit_code == 0, r.output
    assert "models ranked by PSIS-LOO" in r.stdout and "90 % interval" in r.stdout


def test_errors_are_one_line(template, tmp_path):
    """Each bad input raises the one-line error (a ValueError or FileNotFoundError) that
    ``impactlab.cli.main`` prints with exit status 2 (tests/core/test_cli_main.py)."""
    path = _drops(template, tmp_path)
    for args, text in (
        (["calibrate", str(path)], "no free parameter"),
        (["calibrate", str(path), "-p", "mu"], "expected name=prior"),
        (["calibrate", str(path), "-p", "mu=uniform(1, 0)"], "excludes every value"),
        (["calibrate", str(tmp_path / "none.csv"), "-p", "mu=uniform(0, 1)"], "not found"),
        (["calibrate", str(path), "-p", "mu=uniform(0, 1)", "-m", "hooke"], "unknown contact"),
    ):
        r = runner.invoke(app, args)
        assert isinstance(r.exception, ValueError | FileNotFoundError), (args, r.output)
        assert text in str(r.exception) and "\n" not in str(r.exception)


def test_piped_tables_keep_every_cell_whole(template, tmp_path, monkeypatch):
    """Not a terminal (a pipe, a file): the tables are as wide as their cells, never cut to 80
    columns with an ellipsis; the notes are one line each."""
    monkeypatch.delenv("COLUMNS", raising=False)
    path = _drops(template, tmp_path)
    r = runner.invoke(app, ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)", "-p",
                            "flat_yield_strength=uniform(250 MPa, 350 MPa)", "-m",
                            "ghaednia/coulomb", "-m", "jackson-green/coulomb", "--walkers", "8",
                            "--steps", "10", "--quiet"])  # fmt: skip
    assert r.exit_code == 0, r.output
    assert "\u2026" not in r.stdout  # no ellipsis
    assert "| jackson-green/coulomb |" in r.stdout.replace("\u2502", "|")
    assert "| flat_yield_strength |" in r.stdout.replace("\u2502", "|")
    assert "not converged" in r.stdout
