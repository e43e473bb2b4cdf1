"""A calibration says how much of its predictions use the contact law beyond its verified
range (the advisory LAW_EXTRAPOLATED flag): per model in the ranking, the JSON, results.json
and report.html, and as one warning line; the cases still count."""

from __future__ import annotations

import json
import warnings
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

from impactlab.calibrate import CalibrationWarning, CandidateModel, calibrate, parse_parameter
from impactlab.calibrate import predict as predict_drops
from impactlab.calibrate.models import Prediction
from impactlab.calibrate.result import _extrapolated
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.cli import app
from impactlab.flags import FLAG_LAW_EXTRAPOLATED
from impactlab.sweep.engine import ENGINE

MU = parse_parameter("mu", "uniform(0, 0.6)")
TEXT = "the contact law 'ghaednia' is extrapolated in 100 % of the"


class _WithinRange:
    """The compiled engine with the LAW_EXTRAPOLATED bit cleared: a law inside its range."""

    def __getattr__(self, name: str) -> Any:
        return getattr(ENGINE, name)

    def __call__(self, cases, statics, outputs):
        res, status = ENGINE(cases, statics, outputs)
        flags = np.nan_to_num(res["flags"]).astype(np.int64) & ~FLAG_LAW_EXTRAPOLATED
        return {**res, "flags": flags.astype(np.float64)}, status


def _data(template):
    return synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip


def test_the_prediction_marks_extrapolated_cases(template):
    """The paper's rod at 1.4 m/s presses Ghaednia's law far past its verified 1 delta_c."""
    pred = predict_drops(CandidateModel(), template, [MU], np.array([[0.1], [0.3]]))
    assert pred.extrapolated is not None and pred.extrapolated.all()
    inside = predict_drops(CandidateModel(), template, [MU], np.array([[0.1]]),
                           evaluator=_WithinRange())  # fmt: skip
    assert inside.extrapolated is not None and not inside.extrapolated.any()


def test_the_share_counts_the_ok_cases_of_the_posterior_draws():
    status = np.array([[0, 0], [0, 301], [0, 0]])
    ext = np.array([[False, False], [True, False], [True, False]])
    got = _extrapolated(Prediction({}, status, ext))
    assert got == {"share": pytest.approx(2 / 3), "impacts": 3, "basis": "2 posterior draws"}
    # no draw re-run (n_ppc = 0): the best fit's
    assert _extrapolated(Prediction({}, status[:1], ext[:1] | True)) == {
        "share": 1.0, "impacts": 2, "basis": "the best fit"
    }  # fmt: skip


def test_an_extrapolated_law_is_reported_everywhere(template, tmp_path):
    path = _data(template).to_csv(tmp_path / "drops.csv")
    out = tmp_path / "out"
    args = ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)", "--walkers", "6", "--steps",
            "12", "--out", str(out), "--json", "--quiet"]  # fmt: skip
    r = CliRunner().invoke(app, args)
    assert r.exit_code == 0, r.output
    doc = json.loads(r.stdout)
    assert doc["ranking"][0]["law_extrapolated"] == {"value": 1.0, "unit": "1"}
    model = doc["models"]["ghaednia/coulomb"]["law_extrapolated"]
    assert model["share"] == {"value": 1.0, "unit": "1"} and model["impacts"] > 0
    assert model["basis"].endswith("posterior draws")
    assert sum(w.startswith(f"ghaednia/coulomb: {TEXT}") for w in doc["warnings"]) == 1
    saved = json.loads((out / "results.json").read_text())
    assert saved["ranking"][0]["law_extrapolated"]["value"] == 1.0
    html = (out / "report.html").read_text()
    assert "<th>law extrapolated</th>" in html and "<td>100 %</td>" in html
    assert "law extrapolated (beyond its verified range) in 100 % of the" in html


@pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")
def test_a_law_within_its_range_says_nothing(template):
    cal = calibrate(_data(template), [MU], walkers=6, steps=10, n_ppc=4, evaluator=_WithinRange())
    assert cal.best.law_extrapolated["share"] == 0.0
    assert cal.ranking[0]["law_extrapolated"] == 0.0
    assert not any("extrapolated" in w for w in cal.warnings + cal.best.warnings)


def test_the_calibration_still_runs_and_warns_once(template):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        cal = calibrate(_data(template), [MU], walkers=6, steps=10, n_ppc=0)
    lines = [str(w.message) for w in caught if issubclass(w.category, CalibrationWarning)]
    assert sum(TEXT in w for w in lines) == 1
    assert any(w.startswith(TEXT) for w in cal.best.warnings)  # the model's own note
    assert cal.best.law_extrapolated["basis"] == "the best fit"
    assert np.isfinite(cal.best.summary["mu"]["median"])
