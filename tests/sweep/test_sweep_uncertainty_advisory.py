"""The uncertainty report keeps the cases whose law was extrapolated (the advisory
LAW_EXTRAPOLATED flag) and says how many of the cases used carry it: ``n_extrapolated`` in
Python and JSON, one line in the text reports (impactlab.sweep.uncertainty,
impactlab.cli.sweep_summary)."""

from __future__ import annotations

import json

import numpy as np
from sweep_fakes import FlaggingEvaluator, run_cli

from impactlab._json import shape_problems
from impactlab.flags import ResultFlag
from impactlab.sweep import Sample, Study, Uniform, run_sweep, uncertainty_report
from impactlab.sweep.uncertainty import format_report

EXTRAPOLATED_ABOVE = 0.2  # mu beyond which the fake law is extrapolated (advisory)
GAIN_ABOVE = 0.27  # mu beyond which the fake result gains energy (not plain success)


class AdvisoryEvaluator(FlaggingEvaluator):
    """FakeEvaluator's numbers with the engine's ``flags``: LAW_EXTRAPOLATED where
    mu > EXTRAPOLATED_ABOVE, ENERGY_GAIN too where mu > GAIN_ABOVE."""

    identity = "fake-advisory-evaluator/1"

    def flags_for(self, cases) -> np.ndarray:
        mu = cases["mu"]
        flags = np.where(mu > EXTRAPOLATED_ABOVE, int(ResultFlag.LAW_EXTRAPOLATED), 0)
        return flags | np.where(mu > GAIN_ABOVE, int(ResultFlag.ENERGY_GAIN), 0)


def _store(tmp_path):
    st = Study(
        name="adv",
        chunk_size=16,
        fixed={"angle": 0.5, "vy": -1.41},
        sample=Sample(size=40, seed=2, inputs={"mu": Uniform(0.1, 0.3)}),
    )
    res = run_sweep(st, tmp_path / "adv.zarr", evaluator=AdvisoryEvaluator(), quiet=True)
    mu = res.dataset["mu"].values
    n_gain = int((mu > GAIN_ABOVE).sum())
    n_ext_used = int(((mu > EXTRAPOLATED_ABOVE) & (mu <= GAIN_ABOVE)).sum())
    assert n_gain > 0 and n_ext_used > 0  # the sample has both kinds of flagged case
    return res, n_gain, n_ext_used


def test_extrapolated_cases_are_kept_and_counted(tmp_path) -> None:
    res, n_gain, n_ext_used = _store(tmp_path)
    rep = uncertainty_report(res.dataset, outputs=["e"])
    assert rep.n_flagged == n_gain  # energy gain: excluded
    assert rep.summary.loc["e", "n"] == 40 - n_gain  # extrapolated: kept
    assert rep.n_extrapolated == n_ext_used
    assert rep.to_dict()["n_extrapolated"] == n_ext_used
    line = (
        f"law extrapolated (advisory): {n_ext_used} of the {40 - n_gain} cases used, "
        "kept in the statistics"
    )
    assert line in format_report(rep)
    both = uncertainty_report(res.dataset, outputs=["e"], include_flagged=True)
    n_ext_all = n_ext_used + n_gain  # the energy-gain cases are extrapolated too
    assert both.n_extrapolated == n_ext_all
    assert f"{n_ext_all} of the 40 cases used" in format_report(both)


def test_no_extrapolated_line_without_extrapolated_cases(tmp_path, fake) -> None:
    st = Study(
        name="plain",
        chunk_size=16,
        fixed={"angle": 0.5, "vy": -1.41},
        sample=Sample(size=20, seed=2, inputs={"mu": Uniform(0.1, 0.3)}),
    )
    ds = run_sweep(st, tmp_path / "plain.zarr", evaluator=fake, quiet=True).dataset
    rep = uncertainty_report(ds, outputs=["e"])
    assert rep.n_extrapolated == 0 and "extrapolated" not in format_report(rep)


def test_cli_report_says_how_many_cases_are_extrapolated(tmp_path, monkeypatch, capsys) -> None:
    res, n_gain, n_ext_used = _store(tmp_path)
    store = str(res.path)
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", store)
    assert code == 0, err
    lines = [ln for ln in out.splitlines() if "law extrapolated (advisory)" in ln]
    assert len(lines) == 1, out
    assert f"{n_ext_used} of the {40 - n_gain} cases used, kept in the statistics" in lines[0]
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", store, "--json")
    assert code == 0, err
    data = json.loads(out)
    assert shape_problems(data) == []
    rep = next(iter(data.values()))
    assert rep["n_extrapolated"] == n_ext_used and rep["n_flagged"] == n_gain
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "uncertainty", store, "--json", "--include-flagged"
    )
    assert code == 0, err
    assert next(iter(json.loads(out).values()))["n_extrapolated"] == n_ext_used + n_gain
