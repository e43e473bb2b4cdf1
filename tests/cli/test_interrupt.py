"""Ctrl-C during a command: one line on stderr and exit status 130. ``interrupted`` for most
commands; ``sweep run`` and ``calibrate`` say more in their own line, and nothing is added.

The signal is sent when the command says it has started (a line it prints, read by the test) or
by the command itself at a named stage (the sweep's test hook): no test depends on timing."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from impactlab.cli import interrupted, main
from impactlab.sweep.hooks import KILL_AT, KILL_SIGNAL
from impactlab.sweep.runner import SweepInterrupted

#: ``impactlab drop`` in a child process whose simulation says "started" and then waits for the
#: signal (the handler Python installs at start: a child of a background job inherits SIGINT
#: ignored).
_WAITING_DROP = textwrap.dedent("""
    import signal, sys, time
    signal.signal(signal.SIGINT, signal.default_int_handler)
    import impactlab.cli.drop
    from impactlab.cli import main

    def wait(*args, **kwargs):
        print("started", flush=True)
        while True:
            time.sleep(0.05)

    impactlab.cli.drop.simulate_drop = wait
    sys.argv = ["impactlab", "drop", "--angle", "20 deg", "--vy", "-1.41 m/s"]
    main()
""")

#: ``impactlab ARGS`` (from argv) in a child process with Python's Ctrl-C handler.
_MAIN = textwrap.dedent("""
    import signal, sys
    signal.signal(signal.SIGINT, signal.default_int_handler)
    from impactlab.cli import main
    sys.argv = ["impactlab", *sys.argv[1:]]
    main()
""")


def _env() -> dict[str, str]:
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("IMPACTLAB_DEBUG", None)
    return env


def test_ctrl_c_during_a_command_prints_interrupted_and_exits_130():
    proc = subprocess.Popen(
        [sys.executable, "-c", _WAITING_DROP],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env=_env(),
    )
    try:
        assert proc.stdout is not None
        assert proc.stdout.readline() == "started\n"  # blocks until the command runs
        proc.send_signal(signal.SIGINT)
        out, err = proc.communicate(timeout=600)  # stops a hung child only
    finally:
        if proc.poll() is None:
            proc.kill()
    assert (proc.returncode, out, err) == (130, "", "interrupted\n")


@pytest.mark.parametrize("quiet", [[], ["--quiet"]], ids=["progress", "quiet"])
def test_ctrl_c_during_a_sweep_prints_the_sweeps_line_only(tmp_path: Path, quiet: list[str]):
    study = tmp_path / "s.toml"
    study.write_text(
        "[study]\nchunk_size = 2\n[fixed]\nvy = '-1.41 m/s'\nmu = 0.2\n"
        "[grid]\nangle = ['20 deg', '30 deg', '45 deg', '60 deg']\n"
    )
    store = tmp_path / "s.zarr"
    env = _env() | {KILL_AT: "chunk:0:done", KILL_SIGNAL: "SIGINT"}
    args = ["sweep", "run", str(study), "--out", str(store), *quiet]
    r = subprocess.run(
        [sys.executable, "-c", _MAIN, *args], capture_output=True, text=True, env=env, timeout=600
    )
    lines = r.stderr.splitlines()
    assert r.returncode == 130, r.stderr
    assert [x for x in lines if x.startswith("interrupted")] == [
        f"interrupted: 1 of 2 chunks stored in {store}; run the same command again to continue"
    ]


def test_ctrl_c_during_calibrate_prints_its_own_line_only(tmp_path, monkeypatch, capsys):
    def stop(**kwargs):
        raise KeyboardInterrupt

    monkeypatch.setattr("impactlab.calibrate.calibrate", stop)
    data = tmp_path / "drops.csv"
    args = ["calibrate", str(data), "-p", "mu=uniform(0, 0.6)", "--quiet"]
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    with pytest.raises(SystemExit) as exc:
        main()
    assert exc.value.code == 130
    assert capsys.readouterr().err == (
        "interrupted (nothing was saved: give --out DIR to resume later)\n"
    )


def test_the_line_of_an_interrupt(capsys):
    interrupted(KeyboardInterrupt())
    assert capsys.readouterr().err == "interrupted\n"
    interrupted(SweepInterrupted("interrupted: 1 of 2 chunks", said=True))  # printed already
    assert capsys.readouterr().err == ""
    interrupted(SweepInterrupted("interrupted: 1 of 2 chunks", said=False))  # --quiet
    assert capsys.readouterr().err == "interrupted: 1 of 2 chunks\n"


#: A process that imports impactlab as the ``impactlab`` command would (``sys.argv[0]`` from
#: argv) and gets Ctrl-C before the command line starts: the libraries' import window.
_AT_START = textwrap.dedent("""
    import os, signal, sys, time
    signal.signal(signal.SIGINT, signal.default_int_handler)
    sys.argv = [sys.argv[1]]
    import impactlab
    os.kill(os.getpid(), signal.SIGINT)
    time.sleep(60)
    print("not interrupted", flush=True)
""")


@pytest.mark.parametrize(
    ("argv0", "rc"),
    [("/usr/local/bin/impactlab", 130), ("-c", -signal.SIGINT)],
    ids=["command", "library"],
)
def test_ctrl_c_while_the_command_imports(argv0: str, rc: int):
    """The ``impactlab`` command: one line and 130, no traceback; a program that imports
    impactlab as a library keeps Python's KeyboardInterrupt."""
    r = subprocess.run(
        [sys.executable, "-c", _AT_START, argv0],
        capture_output=True,
        text=True,
        env=_env(),
        timeout=600,
    )
    assert r.returncode == rc and r.stdout == ""
    if rc == 130:
        assert r.stderr == "interrupted\n"
    else:
        assert r.stderr.rstrip().endswith("KeyboardInterrupt")


def test_the_command_line_takes_ctrl_c_over_from_the_start(monkeypatch):
    from impactlab import _runtime

    monkeypatch.setattr(sys, "argv", ["impactlab"])
    monkeypatch.setattr(signal, "getsignal", lambda s: signal.default_int_handler)
    installed = []
    monkeypatch.setattr(signal, "signal", lambda s, h: installed.append(h))
    _runtime.quiet_start_interrupt()
    assert len(installed) == 1
    with pytest.raises(SystemExit) as exc:
        installed[0](signal.SIGINT, None)
    assert exc.value.code == 130
    monkeypatch.setattr(signal, "getsignal", lambda s: installed[0])
    _runtime.release_start_interrupt()
    assert installed[-1] is signal.default_int_handler


#: A worker process of the ``impactlab`` command (multiprocessing names it; its argv is the
#: parent's): its SIGINT handler after importing impactlab.
_WORKER = textwrap.dedent("""
    import multiprocessing, signal, sys
    signal.signal(signal.SIGINT, signal.default_int_handler)
    multiprocessing.current_process().name = "SpawnProcess-1"
    sys.argv = ["/usr/local/bin/impactlab", "sweep", "run"]
    import impactlab
    print(signal.getsignal(signal.SIGINT) is signal.SIG_IGN)
""")


def test_the_commands_workers_leave_ctrl_c_to_the_command():
    r = subprocess.run(
        [sys.executable, "-c", _WORKER], capture_output=True, text=True, env=_env(), timeout=600
    )
    assert (r.returncode, r.stdout) == (0, "True\n"), r.stderr


def test_a_sweeps_pool_workers_ignore_ctrl_c():
    code = (
        "import os, signal\n"
        "from impactlab.sweep.backends import _pool_init\n"
        "_pool_init(1, os.getppid())\n"
        "print(signal.getsignal(signal.SIGINT) is signal.SIG_IGN)\n"
    )
    r = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, env=_env(), timeout=600
    )
    assert (r.returncode, r.stdout) == (0, "True\n"), r.stderr
