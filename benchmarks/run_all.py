#!/usr/bin/env python3
"""Run the benchmarks of the engine, the sweep and the compile (``python3 tasks.py bench``).

Runs, one after the other: ``bench_engine.py`` (which also rewrites the generated top of
docs/engine/benchmarks.md), ``profile_engine.py``, ``bench_tabulated.py``, ``bench_sweep.py``
(``--quick`` unless ``--full``: the 10 M-impact sweep), ``bench_flexible.py``,
``bench_partial_slip.py``, ``bench_partial_slip_spread.py``, ``bench_compile.py`` and
``bench_caches.py``. Each prints its figures as ratios against a baseline measured in the same
run and writes them to ``benchmarks/results/*.json``.

Not run here, each by hand when its subject changes:

- ``bench_calibrate.py``: a calibration and its coverage check, minutes to about 20 minutes;
- ``bench_fe.py``: one CalculiX indentation curve (needs ``ccx`` and gmsh; about 4 minutes);
- ``bench_flexible_fuzz.py``: random flexible drops against the drop's trust checks, a
  wall-time budget of 10 minutes by default: a test of the drop, not a figure;
- ``profile_compile.py PART``: where one part's first compile goes, a profile for changes to
  the compile (run alternated with the code without the change; docs/engine/performance-history.md).
"""

from __future__ import annotations

import argparse
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent


def commands(full: bool) -> list[list[str]]:
    """The benchmarks' command lines, in the order they run."""
    page = str(HERE.parent / "docs" / "engine" / "benchmarks.md")
    return [
        [sys.executable, str(HERE / "bench_engine.py"), "--markdown", page],
        [sys.executable, str(HERE / "profile_engine.py")],
        [sys.executable, str(HERE / "bench_tabulated.py")],
        [sys.executable, str(HERE / "bench_sweep.py"), *([] if full else ["--quick"])],
        [sys.executable, str(HERE / "bench_flexible.py")],
        [sys.executable, str(HERE / "bench_partial_slip.py")],
        [sys.executable, str(HERE / "bench_partial_slip_spread.py")],
        [sys.executable, str(HERE / "bench_compile.py")],
        [sys.executable, str(HERE / "bench_caches.py")],
    ]


def parse(argv: list[str]) -> argparse.Namespace:
    """The arguments; an unknown one is refused (argparse: usage on stderr, exit status 2)."""
    ap = argparse.ArgumentParser(
        prog="run_all.py",
        description=" ".join(__doc__.split("\n\n")[0].split()),
        epilog="Not run: bench_calibrate.py, bench_fe.py, bench_flexible_fuzz.py, "
        "profile_compile.py (run each by hand; see this file's docstring).",
    )
    ap.add_argument(
        "--full", action="store_true", help="the sweep benchmark in full (10 M impacts)"
    )
    ap.add_argument(
        "--dry-run",
        action="store_true",
        help="print the commands and run none (nothing is measured or written)",
    )
    return ap.parse_args(argv)


def main(argv: list[str]) -> int:
    args = parse(argv)
    rc = 0
    for cmd in commands(args.full):
        print("+", " ".join(cmd), flush=True)
        if not args.dry_run:
            rc |= subprocess.call(cmd)
    return rc


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
