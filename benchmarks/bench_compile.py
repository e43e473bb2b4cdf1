"""Benchmark of the first run: how long impactlab compiles its engine into an empty cache.

Each step runs in a fresh process with an empty cache folder (``NUMBA_CACHE_DIR`` in a temporary
directory) and is measured in CPU seconds of that process and its children (robust against
other load on a shared machine) and in wall seconds. The steps build on each other, in this
order, as a newcomer meets them:

1. ``impactlab simulate rod ...`` on the command line (the rigid engine, Coulomb friction);
2. a first ``partial_slip`` impact (the partial-slip engine, on top of 1);
3. a first flexible-rod drop (the flexible engine, on top of 1-2);
4. a first batch (``simulate_batch``: the parallel batch, on top of 1-3);
5. the same ``impactlab simulate rod ...`` again, from the cache (the baseline: a warm start);
6. ``impactlab warm`` into another empty folder (every part at once);
7. with ``--reproduce``: ``impactlab reproduce`` into another empty folder (the README's main
   job from a cold cache; target 2 minutes of wall time);
8. with ``--test-suite``: ``python3 tasks.py test`` (ruff, mypy, the warm-up, the whole suite)
   into another empty folder (target 6 minutes of wall time; about 10 minutes to measure).

    .venv/bin/python benchmarks/bench_compile.py [--reproduce] [--test-suite]
        [--out benchmarks/results/compile.json]

A step left out keeps its entry of the recorded file (with the date it was measured).

Writes the JSON and prints a table; the ratios are against step 5 (a warm start, measured in the
same run).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parent
CLI = [sys.executable, "-m", "impactlab"]
SIMULATE = [*CLI, "simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2"]
PY = "import math, impactlab as il\n"
STEPS: tuple[tuple[str, list[str]], ...] = (
    ("impactlab simulate rod (cold)", SIMULATE),
    (
        "first partial_slip impact",
        [
            sys.executable,
            "-c",
            PY + "il.simulate(il.Rod.paper(), friction='partial_slip', mu=0.2, "
            "angle=math.radians(20), velocity=(0.0, -1.41))",
        ],
    ),
    (
        "first flexible drop",
        [
            sys.executable,
            "-c",
            PY + "il.simulate(il.FlexibleRod.paper(), mu=0.2, angle=math.radians(20), "
            "velocity=(0.0, -1.41))",
        ],
    ),
    (
        "first batch",
        [
            sys.executable,
            "-c",
            PY + "il.simulate_batch(il.Rod.paper(), mu=0.2, angle=math.radians(20), "
            "vy=[-1.0, -1.41])",
        ],
    ),
    ("impactlab simulate rod (cached)", SIMULATE),
)


#: The optional steps (their targets: wall seconds on the 2-core machine).
REPRODUCE, TEST_SUITE = "cold impactlab reproduce", "cold python3 tasks.py test"
TARGET_WALL_S = {REPRODUCE: 120.0, TEST_SUITE: 360.0}


def _today() -> str:
    return time.strftime("%Y-%m-%d")


def _run(cmd: list[str], cache: Path) -> dict[str, float]:
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), MPLBACKEND="Agg")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    proc = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - w0
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if proc.returncode != 0:
        raise SystemExit(f"{' '.join(cmd)} failed:\n{proc.stderr[-2000:]}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    notices = [ln for ln in proc.stderr.splitlines() if ln.startswith("impactlab: compiling")]
    return {"cpu_s": cpu, "wall_s": wall, "notices": len(notices)}


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=ROOT / "results" / "compile.json")
    ap.add_argument("--reproduce", action="store_true", help="also a cold impactlab reproduce")
    ap.add_argument("--test-suite", action="store_true", help="also a cold tasks.py test")
    args = ap.parse_args()
    recorded = json.loads(args.out.read_text())["steps"] if args.out.exists() else {}
    result: dict[str, object] = {
        "machine": {
            "cpus": os.cpu_count(),
            "python": platform.python_version(),
            "load_average_1min": os.getloadavg()[0],
        },
        "steps": {},
    }
    steps: dict[str, dict[str, Any]] = {}
    with tempfile.TemporaryDirectory() as tmp:
        cache = Path(tmp) / "cache"
        for name, cmd in STEPS:
            steps[name] = _run(cmd, cache)
            print(
                f"{name:<34} {steps[name]['cpu_s']:7.1f} s CPU {steps[name]['wall_s']:7.1f} s wall"
            )
        warm = _run([*CLI, "warm"], Path(tmp) / "warm")
        steps["impactlab warm (cold, every part)"] = warm
        print(f"{'impactlab warm (cold, every part)':<34} {warm['cpu_s']:7.1f} s CPU")
        for name, wanted, cmd in (
            (REPRODUCE, args.reproduce, [*CLI, "reproduce", "--out", str(Path(tmp) / "repro")]),
            (TEST_SUITE, args.test_suite, [sys.executable, str(ROOT.parent / "tasks.py"), "test"]),
        ):
            if wanted:
                steps[name] = _run(cmd, Path(tmp) / name.split()[1]) | {"date": _today()}
                print(f"{name:<34} {steps[name]['cpu_s']:7.1f} s CPU "
                      f"{steps[name]['wall_s']:7.1f} s wall")  # fmt: skip
            elif name in recorded:
                steps[name] = recorded[name]
    base = steps["impactlab simulate rod (cached)"]["cpu_s"]
    for name, s in steps.items():
        s["cpu_ratio_to_cached_start"] = s["cpu_s"] / base
        if name in TARGET_WALL_S:
            s["target_wall_s"] = TARGET_WALL_S[name]
            s["target_met"] = s["wall_s"] <= TARGET_WALL_S[name]
    result["steps"] = steps
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    print(f"-> {args.out}")


if __name__ == "__main__":
    main()
