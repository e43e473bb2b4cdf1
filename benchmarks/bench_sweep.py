#!/usr/bin/env python3
"""Sweep benchmark: impacts of the paper's rod (Ghaednia law, Coulomb friction) into Zarr.

    python benchmarks/bench_sweep.py --quick        # 200k impacts, about a minute on 2 cores
    python benchmarks/bench_sweep.py                # the full 10 million impacts

Measured in one run (ratios only between numbers of this run):

1. kernel: ``run_arrays`` alone over the chunks of a subset (all cores, no writes): the baseline.
2. sweep of the same subset, backend "threads", 1 core and all cores: throughput ratio, and the
   overhead of chunking, case generation, Zarr writes and progress reporting against (1).
3. sweep of the subset with the local process pool (2 processes) for comparison.
4. (full mode) the whole sweep end to end, default settings, with a progress bar.
5. (full mode) scaling: 1 core against all cores on a 1 000 000-impact study, where the fixed
   costs of a sweep no longer weigh in the ratio.

Results go to benchmarks/results/sweep.json (with the machine and its load average, since a
shared machine disturbs the timings).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results" / "sweep.json"


def _study(n_angle: int, n_vy: int, n_mu: int, name: str, chunk: int):  # type: ignore[no-untyped-def]
    from impactlab.sweep import Study

    return Study(
        name=name,
        chunk_size=chunk,
        grid={
            "angle": np.radians(np.linspace(5.0, 85.0, n_angle)),
            "vy": np.linspace(-4.0, -0.5, n_vy),
            "mu": np.linspace(0.0, 0.6, n_mu),
        },
        fixed={"law": "ghaednia", "friction": "coulomb"},
    )


def _machine() -> dict[str, object]:
    cpu = platform.processor()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    return {
        "cpu": cpu,
        "cores": len(os.sched_getaffinity(0)),
        "python": platform.python_version(),
        "platform": platform.platform(),
        "load_average_start": os.getloadavg(),
    }


def _kernel_time(study, threads: int) -> tuple[float, int]:  # type: ignore[no-untyped-def]
    """Seconds spent in run_arrays alone over the study's chunks (inputs prepared outside)."""
    import numba

    from impactlab.contact import get_law
    from impactlab.dynamics import batch
    from impactlab.sweep.engine import Statics, build_models

    numba.set_num_threads(threads)
    total, n = 0.0, 0
    for k in range(study.layout.n_chunks):
        num, cat, _ = study.chunk_cases(k)
        lp, bp, _ = build_models(num, Statics(cat))
        init = np.column_stack([num["angle"], num["vx"], num["vy"], num["spin"]])
        mu = np.ascontiguousarray(num["mu"])
        t0 = time.perf_counter()
        batch.run_arrays(
            get_law(cat["law"]).law_id,
            batch.FRICTION_IDS[cat["friction"]],
            lp,
            bp,
            init,
            mu,
            **study.engine.kwargs(),
        )
        total += time.perf_counter() - t0
        n += len(mu)
    return total, n


def _sweep(study, workdir: Path, tag: str, **kw):  # type: ignore[no-untyped-def]
    from impactlab.sweep import run_sweep

    store = workdir / f"{tag}.zarr"
    shutil.rmtree(store, ignore_errors=True)
    t0 = time.perf_counter()
    res = run_sweep(study, store, **kw)
    wall = time.perf_counter() - t0
    shutil.rmtree(store, ignore_errors=True)
    return wall, res.stats


def _scaling(workdir: Path, cores: int, repeats: int = 3) -> dict[str, object]:
    """All cores against one on a 1 000 000-impact study (16 chunks), interleaved: the ratio
    at a size where the fixed costs of a sweep (store creation, the last chunk's write, ~0.2 s)
    no longer weigh; on the 200 000-impact subset they are ~15 % of the all-cores run."""
    study = _study(125, 80, 100, "bench-1M", 65536)
    one: list[float] = []
    every: list[float] = []
    for _ in range(repeats):
        one.append(_sweep(study, workdir, "scale1", quiet=True, workers=1)[0])
        every.append(_sweep(study, workdir, "scaleN", quiet=True)[0])
    ratio = min(one) / min(every)
    print(
        f"scaling ({study.n_cases:,} impacts): x1 {min(one):.2f} s, x{cores} {min(every):.2f} s, "
        f"throughput ratio {ratio:.2f}",
        flush=True,
    )
    return {
        "impacts": study.n_cases,
        "repeats": repeats,
        "one_core_s": one,
        "all_cores_s": every,
        "throughput_ratio_all_vs_1": ratio,
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="200k impacts instead of 10 million")
    ap.add_argument("--workdir", type=Path, default=None, help="where the stores go (temp)")
    ap.add_argument("--no-write", action="store_true", help="do not update results/sweep.json")
    ap.add_argument("--repeat", type=int, default=3, help="repeats of the subset measurements")
    args = ap.parse_args(argv)

    cores = len(os.sched_getaffinity(0))
    machine = _machine()
    workdir = args.workdir or Path(tempfile.mkdtemp(prefix="bench-sweep-"))
    workdir.mkdir(parents=True, exist_ok=True)
    chunk = 65536
    # subset for the ratios: 200k impacts (the quick mode's whole sweep)
    subset = _study(50, 40, 100, "bench-subset", chunk)
    full = _study(250, 200, 200, "bench-10M", chunk)

    # warm-up: load the compiled engine (numba cache) once
    _kernel_time(_study(2, 2, 2, "warm", 8), cores)

    print(f"machine: {machine['cpu']}, {cores} cores, load {machine['load_average_start']}")
    results: dict[str, object] = {"machine": machine, "mode": "quick" if args.quick else "full"}
    # interleaved repeats; the minimum of each is the least disturbed (shared machine)
    runs: dict[str, list[float]] = {"kernel": [], "all": [], "one": [], "prog": [], "proc": []}
    write_s = []
    n_sub = subset.n_cases
    for rep in range(args.repeat):
        kern, n_sub = _kernel_time(subset, cores)
        runs["kernel"].append(kern)
        w, st = _sweep(subset, workdir, "all", quiet=True)
        runs["all"].append(w)
        write_s.append(st.write_s)
        runs["one"].append(_sweep(subset, workdir, "one", quiet=True, workers=1)[0])
        runs["prog"].append(_sweep(subset, workdir, "prog", progress=True)[0])
        runs["proc"].append(
            _sweep(subset, workdir, "proc", quiet=True, backend="processes", workers=cores)[0]
        )
        print(
            f"repeat {rep + 1}: " + ", ".join(f"{k} {v[-1]:.2f} s" for k, v in runs.items()),
            flush=True,
        )
    best = {k: min(v) for k, v in runs.items()}
    kern = best["kernel"]
    overhead = best["prog"] / kern - 1.0
    ratio = best["one"] / best["all"]
    print(
        f"kernel only ({n_sub} impacts, {cores} threads): {kern:.2f} s, "
        f"{n_sub / kern:,.0f} impacts/s"
    )
    print(
        f"sweep ({n_sub} impacts) threads x{cores}: {best['all']:.2f} s; x1: {best['one']:.2f} s;"
        f" throughput ratio {ratio:.2f}"
    )
    print(
        f"sweep with progress bar: {best['prog']:.2f} s -> overhead vs kernel "
        f"{100 * overhead:.1f} %"
    )
    print(f"local process pool x{cores}: {best['proc']:.2f} s")
    results["subset"] = {
        "impacts": n_sub,
        "chunk_size": chunk,
        "repeats": args.repeat,
        "runs_s": runs,
        "kernel_s": kern,
        "kernel_impacts_per_s": n_sub / kern,
        "sweep_threads_all_cores_s": best["all"],
        "sweep_threads_1_core_s": best["one"],
        "throughput_ratio_all_vs_1": ratio,
        "sweep_with_progress_s": best["prog"],
        "overhead_vs_kernel": overhead,
        "write_s": min(write_s),
        "sweep_processes_s": best["proc"],
        "processes_vs_threads_time": best["proc"] / best["all"],
    }
    if not args.quick:
        n = full.n_cases
        print(f"full sweep: {n:,} impacts ...", flush=True)
        w_full, st_full = _sweep(full, workdir, "full", progress=True)
        # Overhead at scale: the whole sweep against the kernel-only rate of this same run
        # (the subset figure above is dominated by a fixed ~0.2 s per-sweep cost).
        kernel_rate = results["subset"]["kernel_impacts_per_s"]  # type: ignore[index]
        overhead_full = w_full * kernel_rate / n - 1.0
        print(
            f"full sweep: {w_full:.1f} s end to end ({n / w_full:,.0f} impacts/s), "
            f"writes {st_full.write_s:.1f} s, overhead vs kernel rate "
            f"{100 * overhead_full:.1f} %"
        )
        results["full"] = {
            "impacts": n,
            "wall_s": w_full,
            "impacts_per_s": n / w_full,
            "write_s": st_full.write_s,
            "eval_s": st_full.eval_s,
            "overhead_vs_kernel_rate": overhead_full,
            "under_3_minutes": w_full < 180.0,
        }
        results["scaling"] = _scaling(workdir, cores)
    machine["load_average_end"] = os.getloadavg()
    if args.workdir is None:
        shutil.rmtree(workdir, ignore_errors=True)
    if not args.no_write:
        RESULTS.parent.mkdir(parents=True, exist_ok=True)
        old: dict[str, object] = {}
        if RESULTS.is_file():
            old = json.loads(RESULTS.read_text())
        old[results["mode"]] = results  # type: ignore[index]
        RESULTS.write_text(json.dumps(old, indent=2) + "\n")
        print(f"wrote {RESULTS.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
