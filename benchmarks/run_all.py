#!/usr/bin/env python3
"""Run every benchmark (``python3 tasks.py bench``); pass ``--full`` for the 10 M-impact sweep.

Each benchmark prints its figures as ratios against a baseline measured in the same run and
writes them to ``benchmarks/results/*.json``.
"""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def main(argv: list[str]) -> int:
    full = "--full" in argv
    runs = [
        [
            sys.executable,
            str(HERE / "bench_engine.py"),
            "--markdown",
            str(HERE.parent / "docs" / "engine" / "benchmarks.md"),
        ],
        [sys.executable, str(HERE / "profile_engine.py")],
        [sys.executable, str(HERE / "bench_sweep.py"), *([] if full else ["--quick"])],
        [sys.executable, str(HERE / "bench_flexible.py")],
        [sys.executable, str(HERE / "bench_partial_slip.py")],
        [sys.executable, str(HERE / "bench_partial_slip_spread.py")],
        [sys.executable, str(HERE / "bench_compile.py")],
        [sys.executable, str(HERE / "bench_caches.py")],
    ]
    rc = 0
    for cmd in runs:
        print("+", " ".join(cmd), flush=True)
        rc |= subprocess.call(cmd)
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
