"""A prior written by ``Parameter.describe`` (the settings of results.json, the report) is read
back by ``parse_parameter``, ``--param`` and ``[parameters]`` as the same prior: every kind, a
truncated normal with an open end, a Brinell hardness in kgf/mm^2 (or written in HB)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

from impactlab.calibrate import CandidateModel, parse_parameter
from impactlab.calibrate.config import load_config
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.cli import app


def _same(a, b) -> bool:
    def numbers(p):
        return (p.low, p.high, p.mean, p.sd)

    return (a.name, a.kind) == (b.name, b.kind) and all(
        x == y or (math.isnan(x) and math.isnan(y))
        for x, y in zip(numbers(a), numbers(b), strict=True)
    )


@pytest.mark.parametrize(
    ("name", "spec", "text"),
    [
        ("flat_yield_strength", "uniform(100 MPa, 1 GPa)", "uniform(100 MPa, 1000 MPa)"),
        ("mu", "uniform(0, 0.6)", "uniform(0, 0.6)"),
        ("flat_yield_strength", "loguniform(123.456789 MPa, 2 GPa)",
         "loguniform(123.456789 MPa, 2000 MPa)"),
        ("mu", "normal(0.2, 0.05)", "normal(0.2, 0.05)"),
        ("damping", "normal(0.1, 0.05, 0, 0.6)", "normal(0.1, 0.05, 0, 0.6)"),
        ("flat_yield_strength", {"prior": "normal", "mean": "300 MPa", "sd": "50 MPa",
                                 "low": "200 MPa"}, "normal(300 MPa, 50 MPa, 200 MPa, inf)"),
        ("body_E", "normal(210 GPa, 5 GPa)", "normal(210 GPa, 5 GPa)"),
        ("tip_radius", "uniform(1 mm, 6.6 mm)", "uniform(1 mm, 6.6 mm)"),
        ("length", "uniform(0.1, 0.30000000000000004)", None),  # no short text in mm: exact
        ("inertia", "uniform(1e-5, 1e-3)", None),
        ("flat_brinell_hardness", "uniform(50, 200)", "uniform(50 kgf/mm^2, 200 kgf/mm^2)"),
        ("flat_brinell_hardness", "uniform(50 HB, 200 HBW)", "uniform(50 kgf/mm^2, 200 kgf/mm^2)"),
    ],
)  # fmt: skip
def test_a_described_prior_reads_back_as_itself(name, spec, text):
    p = parse_parameter(name, spec)
    described = p.describe()
    if text is not None:
        assert described == text
    assert _same(parse_parameter(name, described), p)


def test_an_open_end_is_a_bound_of_a_normal_only():
    p = parse_parameter("flat_yield_strength", "normal(300 MPa, 50 MPa, 200 MPa, inf)")
    assert (p.low, p.high) == (2e8, math.inf)
    with pytest.raises(ValueError, match="must be finite"):
        parse_parameter("flat_yield_strength", "uniform(100 MPa, inf)")


def test_the_saved_settings_run_the_calibration_again(template, tmp_path):
    """results.json's priors, given back with --param and in [parameters], are the same."""
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    data = synthetic_measurements(template, CandidateModel(), [mu], [0.15],
                                  np.random.default_rng(0))  # fmt: skip
    drops = data.to_csv(tmp_path / "drops.csv")
    runner = CliRunner()
    args = ["calibrate", str(drops), "--walkers", "8", "--steps", "10", "--quiet"]
    r = runner.invoke(app, [*args, "-p", "mu=uniform(0, 0.6)", "--out", str(tmp_path / "a")])
    assert r.exit_code == 0, r.output
    saved = json.loads((tmp_path / "a" / "results.json").read_text())["settings"]["parameters"]
    assert saved == {"mu": "uniform(0, 0.6)"}
    given = [x for k, v in saved.items() for x in ("-p", f"{k}={v}")]
    r = runner.invoke(app, [*args, *given, "--json"])  # the JSON that results.json holds
    assert r.exit_code == 0, r.output
    again = json.loads(r.stdout)["settings"]["parameters"]
    assert again == saved
    cfg = tmp_path / "cal.toml"
    cfg.write_text("[parameters]\n" + "".join(f'{k} = "{v}"\n' for k, v in saved.items()))
    assert _same(load_config(cfg)["parameters"][0], mu)
    for name, text in {
        "flat_yield_strength": "uniform(100 MPa, 1000 MPa)",
        "flat_brinell_hardness": "uniform(50 kgf/mm^2, 200 kgf/mm^2)",
    }.items():
        cfg.write_text(f'[parameters]\n{name} = "{text}"\n')
        assert load_config(cfg)["parameters"][0].describe() == text
