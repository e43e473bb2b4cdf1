"""A calibration's saved chains: a shorter run uses the first steps of a longer saved chain, one
calibration at a time uses a folder, a chain file another program holds open and Ctrl-C are one
line each, with how to resume."""

from __future__ import annotations

import json
import warnings

import numpy as np
import pytest
from typer.testing import CliRunner

from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
from impactlab.calibrate.posterior import LogPosterior
from impactlab.calibrate.statelock import (
    CalibrationInterrupted,
    SavedChainError,
    StateInUseError,
    state_lock,
)
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.cli import app

MU = parse_parameter("mu", "uniform(0, 0.6)")
runner = CliRunner()
pytestmark = pytest.mark.filterwarnings("ignore::impactlab.calibrate.CalibrationWarning")


def _data(template):
    return synthetic_measurements(template, CandidateModel(), [MU], [0.15],
                                  np.random.default_rng(0))  # fmt: skip


def _run(data, **kw):
    return calibrate(data, [MU], walkers=6, n_ppc=0, **kw)


def test_a_shorter_run_uses_the_first_steps_of_a_saved_chain(template, tmp_path):
    data = _data(template)
    _run(data, steps=30, burn=10, state_dir=tmp_path)
    short = _run(data, steps=20, burn=10, state_dir=tmp_path)
    fresh = _run(data, steps=20, burn=10)
    np.testing.assert_array_equal(short.best.samples, fresh.best.samples)
    assert short.best.summary == fresh.best.summary
    assert (short.settings["steps"], short.best.steps) == (20, 20)
    assert "the saved chain holds 30 steps; the first 20 are used (steps = 20)" in (
        short.best.warnings
    )


def test_one_calibration_at_a_time_in_a_folder(template, tmp_path):
    with state_lock(tmp_path), pytest.raises(StateInUseError, match=rf"another calibration is "
                                             rf"using {tmp_path}: wait for it"):  # fmt: skip
        _run(_data(template), steps=10, state_dir=tmp_path)
    _run(_data(template), steps=10, state_dir=tmp_path)  # free again


def test_a_chain_file_held_open_elsewhere_is_one_line(template, tmp_path, monkeypatch):
    import emcee

    def locked(self, *a, **kw):
        raise BlockingIOError(11, "Unable to synchronously open file (unable to lock file)")

    monkeypatch.setattr(emcee.backends.HDFBackend, "save_step", locked)
    with pytest.raises(StateInUseError, match=r"cannot open the saved chain .*h5: another "
                       r"program has it open .*; close it, then run the same command again to "
                       r"resume from step 0") as info:  # fmt: skip
        _run(_data(template), steps=10, state_dir=tmp_path)
    assert "\n" not in str(info.value)


def _interrupt_after(monkeypatch, calls: int) -> None:
    real = LogPosterior.__call__
    seen = {"n": 0}

    def call(self, theta):
        seen["n"] += 1
        if seen["n"] > calls:
            raise KeyboardInterrupt
        return real(self, theta)

    monkeypatch.setattr(LogPosterior, "__call__", call)


def test_ctrl_c_names_the_step_and_prints_no_traceback(template, tmp_path, monkeypatch, capfd):
    data = _data(template)
    _interrupt_after(monkeypatch, 5)
    with pytest.raises(CalibrationInterrupted) as info:
        _run(data, steps=20, state_dir=tmp_path)
    step = info.value.step  # emcee: one call for the start, two per step (half the walkers)
    assert step == 2 and info.value.saved
    assert str(info.value) == (
        "interrupted at step 2 of 20 (ghaednia/coulomb); run the same command again to resume"
    )
    out = capfd.readouterr()
    assert "Traceback" not in out.out + out.err and "emcee:" not in out.out + out.err
    monkeypatch.undo()
    resumed = _run(data, steps=20, state_dir=tmp_path)
    np.testing.assert_array_equal(resumed.best.samples, _run(data, steps=20).best.samples)


def _csv(template, tmp_path):
    return _data(template).to_csv(tmp_path / "drops.csv")


def test_cli_ctrl_c_is_one_line_with_exit_status_130(template, tmp_path, monkeypatch):
    path = _csv(template, tmp_path)
    _interrupt_after(monkeypatch, 7)
    r = runner.invoke(app, ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)", "--walkers", "6",
                            "--steps", "20", "--out", str(tmp_path / "o"), "--quiet"])  # fmt: skip
    assert r.exit_code == 130
    assert "interrupted at step 3 of 20 (ghaednia/coulomb); run the same command again to " in (
        r.output
    )


def test_cli_another_run_on_the_same_out(template, tmp_path):
    path, out = _csv(template, tmp_path), tmp_path / "o"
    with state_lock(out / "state"):
        r = runner.invoke(app, ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)",
                                "--steps", "10", "--out", str(out), "--quiet"])  # fmt: skip
    assert isinstance(r.exception, ValueError)
    assert str(r.exception) == (
        f"another calibration is using {out}: wait for it to end or choose another --out"
    )


@pytest.mark.parametrize(
    ("args", "text"),
    [
        (["-p", "mu=uniform(0, 0.6)", "-p", "mu=uniform(0, 0.5)"],
         "--param mu is given twice ('uniform(0, 0.6)' and 'uniform(0, 0.5)')"),
        (["-p", "mu=uniform(0, 0.6)", "--seed", "-1"],
         "--seed must be an integer in [0, 4294967295], got -1"),
        (["-p", "mu=uniform(0, 0.6)", "--restart"], "--restart discards the chains saved in --out"),
        (["-p", "mu=uniform(0, 0.6)", "--scheduler", "tcp://127.0.0.1:1"],
         "cannot reach the Dask scheduler 'tcp://127.0.0.1:1'"),
    ],
)  # fmt: skip
def test_cli_option_errors_are_one_line(template, tmp_path, args, text):
    r = runner.invoke(app, ["calibrate", str(_csv(template, tmp_path)), *args, "--quiet"])
    assert isinstance(r.exception, ValueError), r.output
    assert text in str(r.exception) and "\n" not in str(r.exception)


def test_cli_a_directory_as_the_file(tmp_path):
    r = runner.invoke(app, ["calibrate", str(tmp_path), "-p", "mu=uniform(0, 1)"])
    assert isinstance(r.exception, IsADirectoryError)
    assert "is a directory" in str(r.exception)


def test_cli_table_shows_convergence_and_pareto_k(template, tmp_path, monkeypatch):
    monkeypatch.setenv("COLUMNS", "200")
    path = _csv(template, tmp_path)
    args = ["calibrate", str(path), "-p", "mu=uniform(0, 0.6)", "--walkers", "4", "--steps", "10",
            "--burn", "8", "--quiet"]  # fmt: skip
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = runner.invoke(app, args)
    assert r.exit_code == 0, r.output
    head = next(line for line in r.stdout.splitlines() if "elpd_loo" in line)
    assert "Pareto k" in head and "converged" in head and "note" in head
    assert "not converged" in r.stdout and "n/a" in r.stdout  # R-hat not assessable
    doc = json.loads(runner.invoke(app, [*args, "--json"]).stdout)
    row = doc["ranking"][0]
    assert row["converged"] is False and row["note"] == "not converged"
    assert any("not assessable" in w for w in doc["warnings"])


def test_a_refused_run_leaves_no_empty_folder(template, tmp_path):
    out = tmp_path / "new" / "state"
    with pytest.raises(ValueError, match="steps must be >= 10"):
        _run(_data(template), steps=5, state_dir=out)
    assert not (tmp_path / "new").exists()


def test_a_resumed_chain_reports_the_whole_chains_counts(template, tmp_path):
    """The counts (failures, evaluations, draws) covered only the steps run after a resume: a
    chain with 44 % failed draws, run again, reported none and lost its warning."""
    data = _data(template)
    fresh = _run(data, steps=20, burn=10).best
    _run(data, steps=12, burn=6, state_dir=tmp_path)  # stopped after 12 of 20 steps
    resumed = _run(data, steps=20, burn=10, state_dir=tmp_path).best
    again = _run(data, steps=20, burn=10, state_dir=tmp_path).best  # nothing left to run
    for r in (resumed, again):
        assert (r.evaluations, r.draws, r.failed_draws) == (
            fresh.evaluations,
            fresh.draws,
            fresh.failed_draws,
        )
        assert r.failures == fresh.failures


def test_ctrl_c_inside_a_step_s_save_arrives_after_it(template, tmp_path, monkeypatch):
    """A Ctrl-C while a step is saved waits for the step and its counts to be saved: the
    resumed chain is the uninterrupted one, counts and all (before, a step could be saved
    without its counts, or redone with its acceptances counted twice)."""
    import os
    import signal

    from impactlab.calibrate import sampler

    data = _data(template)
    real = sampler._save_counts
    calls = {"n": 0}

    def save_counts(backend, post):  # type: ignore[no-untyped-def]
        calls["n"] += 1
        if calls["n"] == 5:
            os.kill(os.getpid(), signal.SIGINT)
        real(backend, post)

    monkeypatch.setattr(sampler, "_save_counts", save_counts)
    with pytest.raises(CalibrationInterrupted) as info:
        _run(data, steps=20, state_dir=tmp_path)
    assert info.value.step == 5  # the step being saved was saved whole
    monkeypatch.undo()
    resumed = _run(data, steps=20, state_dir=tmp_path)
    whole = _run(data, steps=20)
    np.testing.assert_array_equal(resumed.best.samples, whole.best.samples)
    assert (resumed.best.evaluations, resumed.best.draws) == (
        whole.best.evaluations,
        whole.best.draws,
    )


def test_a_chain_damaged_in_place_is_refused_on_resume(template, tmp_path):
    """A saved sample outside its prior (written over after the run) was used without a word."""
    import h5py

    data = _data(template)
    _run(data, steps=10, state_dir=tmp_path)
    (chain,) = tmp_path.glob("*.h5")
    with h5py.File(chain, "r+") as f:
        f["chain/chain"][3, 1, 0] = 5.0  # mu, outside uniform(0, 0.6)
    with pytest.raises(SavedChainError, match=r"holds a sample outside its prior's support or not "
                       r"finite \(step 3, walker 1: mu = 5\): damaged after it was written; it is "
                       r"kept: restart=True discards it"):  # fmt: skip
        _run(data, steps=20, state_dir=tmp_path)
    assert _run(data, steps=20, state_dir=tmp_path, restart=True).best.steps == 20
