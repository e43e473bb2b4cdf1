"""SIGTERM or Ctrl-C while ccx runs: every ccx ends, no other starts, and each run's temporary
folder is removed before the program ends (SIGTERM left the folders in the temporary directory
and ccx running before; Ctrl-C sent to Python alone waited for every ccx to finish and then
started the runs still waiting). A stand-in ccx (a shell script that sleeps) replaces
CalculiX; the mesh and deck are stand-ins too (no gmsh)."""

from __future__ import annotations

import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

# The program as a terminal starts it: Ctrl-C raises KeyboardInterrupt (a process started in
# the background by a shell without job control inherits SIGINT ignored).
SCRIPT = """
import signal
import sys
signal.signal(signal.SIGINT, signal.default_int_handler)
from impactlab.fe import run as fe_run
from impactlab.materials import AISI_1010

fe_run.build_mesh = lambda spec: None
fe_run.write_deck = lambda mesh, deck: "*HEADING\\n"
fe_run.indent(AISI_1010, radius=8.8e-3, delta_max=[1e-6, 2e-6, 3e-6], sphere="rigid",
              workers=2, cache_dir=sys.argv[1])
"""

FAKE_CCX = """#!/bin/sh
if [ "$1" = "-v" ]; then echo "This is Version 2.22"; exit 0; fi
echo $$ >> "$FAKE_PIDS"
exec sleep 60
"""


def _alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    return True


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT], ids=["SIGTERM", "SIGINT"])
def test_a_signal_ends_ccx_and_removes_its_folders(tmp_path: Path, sig: signal.Signals) -> None:
    exe = tmp_path / "ccx"
    exe.write_text(FAKE_CCX)
    exe.chmod(0o755)
    (tmp_path / "tmp").mkdir()
    script = tmp_path / "run.py"
    script.write_text(SCRIPT)
    pids = tmp_path / "pids"
    env = {
        **os.environ,
        "IMPACTLAB_CCX": str(exe),
        "TMPDIR": str(tmp_path / "tmp"),
        "FAKE_PIDS": str(pids),
    }
    proc = subprocess.Popen(
        [sys.executable, str(script), str(tmp_path / "cache")],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
    )
    try:
        deadline = time.monotonic() + 120.0
        while not (pids.exists() and len(pids.read_text().split()) == 2):
            assert proc.poll() is None, proc.communicate()
            assert time.monotonic() < deadline, "the stand-in ccx did not start"
            time.sleep(0.1)
        folders = list((tmp_path / "tmp").glob("impactlab-fe-*"))
        assert len(folders) == 2  # one per running ccx
        proc.send_signal(sig)
        _, err = proc.communicate(timeout=30)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == -sig, err  # ended as the signal ends it
    assert list((tmp_path / "tmp").iterdir()) == []  # no folder left behind
    started = [int(p) for p in pids.read_text().split()]
    assert len(started) == 2  # the third run never started
    assert not any(_alive(p) for p in started)  # no ccx left running
