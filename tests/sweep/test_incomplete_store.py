"""An incomplete store (a sweep stopped part way) is exported, plotted and summarised with a
warning that says how much of it is done, and the uncertainty report counts the cases not yet
computed (status -1) apart from the invalid ones."""

from __future__ import annotations

import json

import pytest
from sweep_fakes import CrashingEvaluator, FakeEvaluator, run_cli

from impactlab.sweep import Study, open_sweep, run_sweep, uncertainty_report
from impactlab.sweep.dimensions import Sample
from impactlab.sweep.distributions import Uniform
from impactlab.sweep.summary import incomplete_note


def _study() -> Study:
    return Study(
        name="part",
        chunk_size=10,
        sample=Sample(size=100, seed=2, inputs={"mu": Uniform(0.0, 0.6)}),
        fixed={"vy": -1.41, "angle": "30 deg"},
    )


@pytest.fixture
def part(tmp_path):
    """A store of 10 chunks, 3 of them done."""
    store = tmp_path / "part.zarr"
    with pytest.raises(RuntimeError, match="simulated crash"):
        run_sweep(_study(), store, evaluator=CrashingEvaluator(after=3), workers=1, quiet=True)
    return store


NOTE = "store incomplete: 3 of 10 chunks done; run the study again to finish it"


def test_the_note_counts_the_chunks_done(part) -> None:
    assert incomplete_note(part) == NOTE
    run_sweep(_study(), part, evaluator=FakeEvaluator(), quiet=True)
    assert incomplete_note(part) is None


def test_the_report_counts_the_cases_not_computed_apart(part) -> None:
    rep = uncertainty_report(open_sweep(part), outputs=["e"])
    assert (rep.n_cases, rep.n_not_computed, rep.n_invalid) == (100, 70, 0)
    assert rep.summary.loc["e", "n"] == 30
    assert rep.to_dict()["n_not_computed"] == 70


def test_export_and_uncertainty_warn(part, tmp_path, monkeypatch, capsys) -> None:
    code, out, err = run_cli(
        monkeypatch, capsys, "sweep", "export", str(part), str(tmp_path / "p.nc")
    )
    assert code == 0 and out.strip() == str(tmp_path / "p.nc")
    assert err.strip() == f"warning: {NOTE}"
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(part), "--json")
    assert code == 0 and f"warning: {NOTE}" in err
    report = next(iter(json.loads(out).values()))
    assert report["n_not_computed"] == 70 and report["n_invalid"] == 0
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "uncertainty", str(part))
    text = " ".join(out.split())  # the table's title wraps
    assert code == 0 and "100 cases, 0 excluded (invalid: status > 0), 70 not computed" in text


def test_a_complete_store_exports_without_a_warning(tmp_path, monkeypatch, capsys) -> None:
    store = run_sweep(_study(), tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True).path
    code, _, err = run_cli(
        monkeypatch, capsys, "sweep", "export", str(store), str(tmp_path / "s.nc")
    )
    assert code == 0 and err == ""
