"""A chunk without its completion marker (never finished, or its marker deleted) reads as not
computed (status -1) wherever the store is read: ``open_sweep``, a CSV export, the uncertainty
report and ``impactlab sweep info``, whatever its files hold."""

from __future__ import annotations

import json
import shutil

import numpy as np
import pandas as pd
import pytest
from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import Sample, Study, Uniform, open_sweep, run_sweep, uncertainty_report

NOT_RUN = "-1: not computed (chunk missing: the sweep was interrupted)"


def _sampled() -> Study:
    return Study(
        name="marks",
        chunk_size=10,
        sample=Sample(size=50, seed=4, inputs={"mu": Uniform(0.0, 0.6)}),
        fixed={"vy": -1.41, "angle": "30 deg"},
    )


@pytest.fixture
def store(tmp_path):
    """A finished store of 5 chunks of 10 cases, every case ok."""
    res = run_sweep(_sampled(), tmp_path / "m.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert (res.dataset["status"].values == 0).all()
    return res.path


def _info(monkeypatch, capsys, store) -> dict:
    code, out, err = run_cli(monkeypatch, capsys, "sweep", "info", str(store), "--json")
    assert code == 0, err
    return json.loads(out)


def test_no_markers_at_all_means_nothing_computed(store, tmp_path, monkeypatch, capsys) -> None:
    shutil.rmtree(store / ".sweep" / "done")
    assert (open_sweep(store)["status"].values == -1).all()
    rep = uncertainty_report(open_sweep(store), outputs=["e"])
    assert (rep.n_cases, rep.n_not_computed, rep.n_invalid) == (50, 50, 0)
    info = _info(monkeypatch, capsys, store)
    assert (info["chunks_done"], info["chunks_total"]) == (0, 5)
    assert info["status"] == {NOT_RUN: 50}
    target = tmp_path / "m.csv"
    code, _, err = run_cli(monkeypatch, capsys, "sweep", "export", str(store), str(target))
    assert code == 0, err
    assert (pd.read_csv(target)["status"] == -1).all()


def test_a_chunk_without_its_marker_or_its_files(store, monkeypatch, capsys) -> None:
    (store / ".sweep" / "done" / "1").unlink()
    (store / ".sweep" / "done" / "3").unlink()
    (store / "e" / "c.3").unlink()  # chunk 3's values of e gone too
    status = open_sweep(store)["status"].values
    expected = np.zeros(50, dtype=np.int32)
    expected[10:20] = expected[30:40] = -1
    np.testing.assert_array_equal(status, expected)
    rep = uncertainty_report(open_sweep(store), outputs=["e"])
    assert (rep.n_not_computed, rep.n_invalid, rep.summary.loc["e", "n"]) == (20, 0, 30)
    info = _info(monkeypatch, capsys, store)
    assert (info["chunks_done"], info["chunks_total"]) == (3, 5)
    assert info["status"] == {NOT_RUN: 20, "0: finished": 30}


def test_the_cases_masked_are_those_of_the_chunk_on_a_2d_grid(tmp_path) -> None:
    study = Study(
        name="grid2",
        grid={"angle": np.radians([10, 20, 30, 40, 50]), "mu": [0.1, 0.2, 0.3, 0.4]},
        fixed={"vy": -1.41},
        chunk_size=2,
    )
    path = run_sweep(study, tmp_path / "g.zarr", evaluator=FakeEvaluator(), quiet=True).path
    lay = study.layout
    assert lay.n_chunks == 10 and lay.chunks == (1, 2)
    for k in (3, 8):
        (path / ".sweep" / "done" / str(k)).unlink()
    expected = np.zeros(lay.shape, dtype=np.int32)
    for k in (3, 8):
        expected[lay.block(k)] = -1
    np.testing.assert_array_equal(open_sweep(path)["status"].values, expected)
