"""``kill PID`` (SIGTERM) ends a sweep as Ctrl-C does: one line saying how many chunks are
stored, the store's lock released, exit status 143; the same command then continues it.

The sweep runs in a subprocess (``impactlab sweep run`` with the fake evaluator) that sends
itself SIGTERM at a named stage (the test hook ``impactlab.sweep.hooks``), so no test depends
on timing."""

from __future__ import annotations

import os
import subprocess
import sys
import textwrap
from pathlib import Path

from sweep_fakes import FakeEvaluator, run_cli

from impactlab.sweep import open_sweep
from impactlab.sweep.hooks import KILL_AT, KILL_SIGNAL

HERE = Path(__file__).resolve().parent

STUDY = (
    '[study]\nname = "t"\nchunk_size = 4\n[fixed]\nangle = "20 deg"\nvy = -1.41\n'
    "[grid]\nmu = { start = 0.05, stop = 0.6, num = 20 }\n"
)

_SCRIPT = textwrap.dedent("""
    import sys
    sys.path.insert(0, {here!r})
    sys.argv = ["impactlab", "sweep", "run", {study!r}, "--out", {store!r}, "--workers", "1"]
    from sweep_fakes import FakeEvaluator
    import impactlab.sweep.runner
    impactlab.sweep.runner.ENGINE = FakeEvaluator()
    from impactlab.cli import main
    main()
""")


def test_sigterm_stops_a_sweep_like_ctrl_c(tmp_path, monkeypatch, capsys) -> None:
    study, store = tmp_path / "t.toml", tmp_path / "t.zarr"
    study.write_text(STUDY)
    script = _SCRIPT.format(here=str(HERE), study=str(study), store=str(store))
    env = {**os.environ, KILL_AT: "chunk:1:done", KILL_SIGNAL: "SIGTERM"}
    proc = subprocess.run(
        [sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 143, proc.stderr
    assert f"interrupted: 2 of 5 chunks stored in {store}" in proc.stderr
    assert "Traceback" not in proc.stderr
    assert not (store / ".sweep" / "lock").exists()
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    code, _out, _err = run_cli(monkeypatch, capsys, "sweep", "run", str(study), "--out", str(store))
    assert code == 0
    assert int((open_sweep(store)["status"] == 0).sum()) == 20


_EXPORT = textwrap.dedent("""
    import sys
    sys.argv = ["impactlab", "sweep", "export", {store!r}, {out!r}]
    from impactlab.cli import main
    main()
""")


def test_sigterm_during_an_export_leaves_no_partial_file(tmp_path, monkeypatch, capsys) -> None:
    """SIGTERM while ``sweep export`` writes (the file under its temporary name): one line,
    status 143, neither the file nor its temporary one left (it ended at the signal's default
    action: no word, status 143 and a ``.NAME.PID.partial`` file for good)."""
    study, store = tmp_path / "t.toml", tmp_path / "t.zarr"
    study.write_text(STUDY)
    monkeypatch.setattr("impactlab.sweep.runner.ENGINE", FakeEvaluator())
    code, _out, _err = run_cli(monkeypatch, capsys, "sweep", "run", str(study), "--out", str(store))
    assert code == 0
    out = tmp_path / "t.csv"
    script = _EXPORT.format(store=str(store), out=str(out))
    env = {**os.environ, KILL_AT: "write:partial", KILL_SIGNAL: "SIGTERM"}
    proc = subprocess.run(
        [sys.executable, "-c", script], env=env, capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 143, proc.stderr
    assert proc.stderr.strip().splitlines()[-1] == "terminated"
    assert "Traceback" not in proc.stderr
    assert sorted(p.name for p in tmp_path.iterdir()) == ["t.toml", "t.zarr"]
