"""A Python script that calls ``run_sweep(..., backend="processes")`` at its top level, without
the main guard, is re-imported by each spawned worker, which runs the sweep again and dies: the
error says so, with the guard to write."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow  # a spawned pool in a fresh interpreter

SCRIPT = """\
import sys

import numpy as np

from impactlab.sweep import Study, run_sweep

study = Study(
    name="guard",
    chunk_size=2,
    fixed={"mu": 0.2},
    grid={"vy": [-1.0, -2.0], "angle": np.radians([20.0, 40.0])},
)
run_sweep(study, sys.argv[1], backend="processes", workers=2, quiet=True)
"""


def test_a_script_without_the_main_guard_is_told_to_add_it(tmp_path: Path) -> None:
    script = tmp_path / "no_guard.py"
    script.write_text(SCRIPT)
    done = subprocess.run(
        [sys.executable, str(script), str(tmp_path / "guard.zarr")],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=tmp_path,
    )
    assert done.returncode == 1
    # the error of the parent; a dying worker's own lines may come before it (or, where the
    # system delivers them late, after it), so it is looked up rather than taken as the last
    lost = [
        line
        for line in done.stderr.strip().splitlines()
        if line.startswith("impactlab.sweep.backends.WorkerLostError: a worker process")
    ]
    assert len(lost) == 1, done.stderr[-2000:]
    last = lost[0]
    assert 'a run_sweep call not under `if __name__ == "__main__":`' in last
    assert "which each worker runs again as it imports the script" in last
    assert "0 of 2 chunks stored" in last
