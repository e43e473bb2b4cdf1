"""``benchmarks/profile_engine.py`` counts the work of the benchmark case by running the engine
as plain Python with counters on the functions it names: a renamed engine function made its
child process fail (``python3 tasks.py bench`` then stopped). Its counting run, checked here,
takes seconds; the timed part is the benchmark's own."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

SCRIPT = Path(__file__).resolve().parents[2] / "benchmarks" / "profile_engine.py"


def test_the_counting_run_finds_every_function_it_counts() -> None:
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PROFILE_RTOL="2e-07")
    p = subprocess.run(
        [sys.executable, str(SCRIPT), "--child"], capture_output=True, text=True, env=env,
        check=False, timeout=600,
    )  # fmt: skip
    assert p.returncode == 0, p.stderr[-3000:]
    counts = json.loads(p.stdout.strip().splitlines()[-1])
    for key in ("rhs_evaluations", "law_evaluations", "accepted_steps", "events"):
        assert counts.get(key, 0) > 0, counts
