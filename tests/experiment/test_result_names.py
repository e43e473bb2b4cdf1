"""The names and units of an analysis' results: the summary's keys are the glossary's
(``sliding_length``, ``duration``, ``mean_force``, ``v_cx_in``: once ``L_s``, ``T``, ``F``,
``v_c_in_x``), and a dimensionless quantity's unit is ``"1"`` in results.json as in ``--json``
(results.json once wrote ``""``)."""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import pytest

from impactlab.experiment import ExperimentResult, analyze
from impactlab.experiment.saving import written_by_analyze
from impactlab.experiment.uncertainty import Estimate

NAMES = [
    "e", "mu", "angle", "v_i", "v_cx_in", "v_cy_in", "v_cx_out", "v_cy_out", "spin_out",
    "dv_cy", "delta_p", "sliding_length", "pileup", "duration", "mean_force",
]  # fmt: skip


@pytest.fixture(scope="module")
def analysed(
    tmp_path_factory: pytest.TempPathFactory, drops: dict, scans: dict, rod: Any
) -> tuple[ExperimentResult, Path]:
    out = tmp_path_factory.mktemp("names")
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], rod, geometry=d.geometry, out_dir=out,
                  figures=False, n_samples=500)  # fmt: skip
    assert not res.errors, res.errors
    return res, out


def test_the_summary_has_the_glossarys_names(analysed: tuple[ExperimentResult, Path]) -> None:
    res, out = analysed
    assert list(res.summary()) == NAMES
    assert list(json.loads((out / "results.json").read_text())["summary"]) == NAMES
    assert res.summary()["v_cx_in"] is res.kinematics.v_c_in[0]  # type: ignore[union-attr]


def test_dimensionless_units_are_1_everywhere(analysed: tuple[ExperimentResult, Path]) -> None:
    res, out = analysed
    saved = json.loads((out / "results.json").read_text())
    for name in ("e", "mu"):
        assert saved["summary"][name]["unit"] == "1"
        assert saved["kinematics"][name]["unit"] == "1"
        assert res.to_dict()["summary"][name]["unit"] == "1"
    assert saved["summary"]["sliding_length"]["unit"] == "m"
    assert "±" in str(res.summary()["e"]) and not str(res.summary()["e"]).endswith(" 1")


def test_an_estimate_without_a_unit_is_a_plain_number() -> None:
    assert Estimate(0.5, 0.01).unit == Estimate(0.5, 0.01, "").unit == "1"
    assert Estimate(0.5, 0.01, "") == Estimate(0.5, 0.01, "1")
    assert f"{Estimate(0.5, 0.01)}" == "0.5 ± 0.01" and f"{Estimate(2.0, 0.0, 'm')}" == "2 m"


def test_a_results_json_of_an_older_version_is_still_the_analysis_own(
    analysed: tuple[ExperimentResult, Path], tmp_path: Path
) -> None:
    """An older results.json (units "", the keys L_s, T, F) is recognised and replaced."""
    res, out = analysed
    old = json.loads((out / "results.json").read_text())
    renamed = {"sliding_length": "L_s", "duration": "T", "mean_force": "F"}
    old["summary"] = {renamed.get(k, k): v for k, v in old["summary"].items()}
    for q in (old["summary"]["e"], old["summary"]["mu"]):
        q["unit"] = ""
    (tmp_path / "results.json").write_text(json.dumps(old), encoding="utf-8")
    assert written_by_analyze(tmp_path / "results.json")
    again = analyze(None, res.scan_path, out_dir=tmp_path, figures=False)
    assert not again.errors and "results" in again.files
    assert "sliding_length" in json.loads((tmp_path / "results.json").read_text())["summary"]
