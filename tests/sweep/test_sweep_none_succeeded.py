"""A run none of whose cases succeeded (every case refused or failed: no status 0) says so in
Python as the command line does with its exit status 2: one ``FailedCasesWarning`` naming how
many cases and their statuses and where to read why, and ``stats.failed`` / ``stats.succeeded``
in what ``run_sweep`` returns; a run with one case that succeeded does not warn."""

from __future__ import annotations

import warnings
from pathlib import Path

import pytest
from sweep_fakes import VY_LIMIT, FakeEvaluator, run_cli

from impactlab.sweep import FailedCasesWarning, FlaggedCasesWarning, Study, run_sweep


def _study(vy) -> Study:
    return Study(name="af", grid={"mu": [0.1, 0.2, 0.3]}, fixed={"angle": 0.5, "vy": vy})


def test_a_run_where_every_case_failed_warns_and_says_it(tmp_path: Path) -> None:
    store = tmp_path / "af.zarr"
    with pytest.warns(FailedCasesWarning) as caught:
        res = run_sweep(_study(2 * VY_LIMIT), store, evaluator=FakeEvaluator(), quiet=True)
    said = [str(w.message) for w in caught if w.category is FailedCasesWarning]
    assert said == [
        f"sweep 'af' in {str(store)!r}: no case succeeded: 3 case(s) refused or failed (3 with "
        "status 1: fake: vy outside the validity range); the store keeps their status, whose "
        f"meaning is in ds.attrs['status_messages']; impactlab sweep info {store} counts them"
    ]
    assert res.complete and res.stats.failed == 3 and res.stats.succeeded == 0
    assert issubclass(FailedCasesWarning, FlaggedCasesWarning)  # one filter covers both


def test_a_run_with_a_case_that_succeeded_does_not_warn(tmp_path: Path) -> None:
    study = Study(name="some", grid={"vy": [-1.0, 2 * VY_LIMIT]}, fixed={"angle": 0.5, "mu": 0.1})
    with warnings.catch_warnings():
        warnings.simplefilter("error", FailedCasesWarning)
        res = run_sweep(study, tmp_path / "s.zarr", evaluator=FakeEvaluator(), quiet=True)
    assert res.stats.failed == 1 and res.stats.succeeded == 1


def test_the_command_line_says_it_once(tmp_path, monkeypatch, capsys) -> None:
    f = tmp_path / "af.toml"
    f.write_text(  # the brake law of a custom body without its Brinell hardness: refused
        "[study]\nname = 'af'\n[fixed]\nangle = '20 deg'\nvy = -1.41\nlaw = 'brake'\n"
        "body_material = 'custom'\nbody_E = '193 GPa'\nbody_nu = 0.29\n"
        "body_yield_strength = '300 MPa'\nbody_density = 7800\nmass = 0.4607\n"
        "[grid]\nmu = [0.1, 0.2]\n"
    )
    code, _, err = run_cli(monkeypatch, capsys, "sweep", str(f), "--out", str(tmp_path / "a.zarr"))
    assert code == 2 and "error: no case of study 'af' succeeded" in err
    assert "FailedCasesWarning" not in err and "no case succeeded" not in err
