"""The flagged counts of ``sweep info``, the run summary and their JSON lead with the cases that
are not ok (a flag that is not advisory), and count the advisory law extrapolated apart: the
number the uncertainty report excludes (``n_flagged``) is the headline."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from sweep_fakes import FlaggingEvaluator

from impactlab.cli.sweep_summary import flagged_json, run_summary
from impactlab.sweep import Sample, Study, Uniform, flag_counts, run_sweep, store_info
from impactlab.sweep.summary import flagged_text, format_flag_counts


class ExtrapolatingEvaluator(FlaggingEvaluator):
    """Energy gain where mu > 0.4, gravity-dominated where vy > -0.5 (FlaggingEvaluator), and
    the advisory law extrapolated where mu > 0.2."""

    identity = "flag-not-ok-evaluator/1"

    def flags_for(self, cases: Any) -> np.ndarray:
        return super().flags_for(cases) | np.where(cases["mu"] > 0.2, 4, 0)


@pytest.fixture
def finished(tmp_path: Path) -> Any:
    """mu = 0, 0.1, ..., 0.6 x vy = -1.41, -0.3 (14 cases): energy gain 4, gravity-dominated
    7, both 2: 9 not ok; law extrapolated 8 (mu >= 0.3), 2 of them ok (vy = -1.41, mu = 0.3,
    0.4): 11 cases with any flag."""
    study = Study(
        name="notok",
        grid={"mu": np.round(np.linspace(0.0, 0.6, 7), 12), "vy": [-1.41, -0.3]},
        fixed={"angle": 0.5},
        outputs=["e"],
    )
    return run_sweep(study, tmp_path / "n.zarr", evaluator=ExtrapolatingEvaluator(), quiet=True)


def test_counts_lead_with_the_cases_not_ok(finished: Any) -> None:
    counts = flag_counts(finished.dataset["flags"].values, finished.dataset["flags"].attrs)
    assert counts["flagged"] == 11 and counts["not ok"] == 9
    assert counts["law extrapolated"] == 8
    text = (
        "9 case(s) not ok (energy gain: 4, gravity-dominated: 7); advisory (the result stays "
        "ok): law extrapolated: 8; 11 flagged in all"
    )
    assert run_summary(finished, finished.dataset, None, [], as_json=False)["flagged"] == text
    want = {
        "total": 11,
        "not_ok": 9,
        "energy_gain": 4,
        "gravity_dominated": 7,
        "law_extrapolated": 8,
    }
    assert store_info(finished.path)["flagged"] == want
    assert run_summary(finished, finished.dataset, None, [], as_json=True)["flagged"] == want


def test_info_json_reads_the_not_ok_count(cli_main: Any, finished: Any) -> None:
    code, out, err = cli_main("sweep", "info", str(finished.path), "--json")
    assert code == 0, err
    assert json.loads(out)["flagged"]["not_ok"] == 9
    assert json.loads(out)["flagged"]["total"] == 11  # its meaning kept: any flag


def test_the_headline_is_what_the_uncertainty_report_excludes(tmp_path: Path) -> None:
    from impactlab.sweep import uncertainty_reports

    study = Study(
        name="mc",
        fixed={"angle": 0.5, "vy": -1.41},
        sample=Sample(size=50, seed=4, inputs={"mu": Uniform(0.0, 0.6)}),
    )
    res = run_sweep(study, tmp_path / "mc.zarr", evaluator=ExtrapolatingEvaluator(), quiet=True)
    (report,) = uncertainty_reports(res.dataset).values()
    summary = run_summary(res, res.dataset, None, [], as_json=True)
    assert summary["flagged"]["not_ok"] == report.n_flagged > 0
    assert summary["flagged"]["total"] > report.n_flagged  # the advisory flag: ok cases too


@pytest.mark.parametrize(
    "counts",
    [
        {"flagged": 0, "not ok": 0, "energy gain": 0},
        {"flagged": 63, "not ok": 0, "law extrapolated": 63},
        {"flagged": 1234, "not ok": 1234, "energy gain": 1000, "gravity-dominated": 234},
        {"flagged": 80, "not ok": 58, "energy gain": 15, "law extrapolated": 74, "brittle": 43},
        {"flagged": 3, "not ok": 3},  # a flag of a mask this version does not name
    ],
)
def test_the_text_is_that_of_the_counts_json(counts: dict[str, int]) -> None:
    assert flagged_text(flagged_json(counts)) == format_flag_counts(counts)
