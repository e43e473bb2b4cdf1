"""Benchmark of the flexible-rod drop against the finite-element reference, measured in ONE run.

Case: the paper's rod as a FlexibleRod at the default mode count (Timoshenko, 8 + 2 axial,
12 bending modes), its three drops (20 / 45 / 70 deg, vy = -1.41 / -2.18 / -3.45 m/s, the
measured mu 0.20 / 0.13 / 0.10 as Coulomb mu), the Ghaednia law, gravity on, the default
tolerance. The baseline is ``impactlab.dynamics.flex_reference.drop_reference`` (corotational
Timoshenko finite elements, Ne = 80, scipy ``solve_ivp`` DOP853 with events, rtol 1e-8), timed
in the same run, both sides best of several (30 flexible drops, 5 FE drops), their rounds
alternated: the figure is the ratio of the bests FE / flexible, robust against other load on a
shared machine. The target: one flexible drop in 10 ms or less on one core (median).

Batch: flexible drops per CPU-second of ``simulate_drops`` (one compiled call over a grid of
BATCH_CASES drops: angles 15-75 deg, vy -0.8 to -3 m/s, mu 0.1-0.3) against ``simulate_drop``
called once per case, both timed in the same run on one thread (process CPU time), their ratio
the figure; the batch's outputs are checked equal to the drops one by one (bit for bit). The
wall time of the batch on every core is recorded beside it.

    .venv/bin/python benchmarks/bench_flexible.py [--quick]

Writes benchmarks/results/flexible.json and prints a summary.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import statistics
import sys
import time
from pathlib import Path

import numba
import numpy as np

from bench_engine import cpu_model  # this folder is on sys.path when run as a script
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_batch import simulate_drops
from impactlab.dynamics.flex_reference import drop_reference
from impactlab.dynamics.flexcore.layout import DROP_DEFAULT_RTOL

ROOT = Path(__file__).resolve().parent
#: angle [deg] -> (vy [m/s], mu)
DROPS = {20: (-1.41, 0.20), 45: (-2.18, 0.13), 70: (-3.45, 0.10)}


def one_angle(deg: int, repeats: int, fe_repeats: int, n_elements: int) -> dict[str, float]:
    """CPU time of the flexible drop (best and median of ``repeats``) and of the FE drop (best
    and median of ``fe_repeats``), their rounds alternated so that a change of the machine's
    load falls on both alike, the ratio of the bests, and the agreement of e, delta_p and T."""
    vy, mu = DROPS[deg]
    kw = {"angle": math.radians(deg), "velocity": (0.0, vy), "mu": mu, "history": False}
    rod = FlexibleRod.paper()
    r = simulate_drop(rod, **kw)  # warm: basis, compiled code
    ref_kw = {k: v for k, v in kw.items() if k != "history"}
    ref_kw |= {"t_stop": r.sequence_duration + 1e-3, "n_elements": n_elements}
    ref = drop_reference(rod, **ref_kw)  # warm
    times: list[float] = []
    t_fe: list[float] = []
    per_round = math.ceil(repeats / fe_repeats)
    for _ in range(fe_repeats):
        for _ in range(per_round):
            t0 = time.process_time()
            simulate_drop(rod, **kw)
            times.append(time.process_time() - t0)
        t0 = time.process_time()
        drop_reference(rod, **ref_kw)
        t_fe.append(time.process_time() - t0)
    return {
        "flexible_ms_median": 1e3 * statistics.median(times),
        "flexible_ms_best": 1e3 * min(times),
        "flexible_repeats": float(len(times)),
        "steps": float(r.n_steps),
        "fe_s": min(t_fe),
        "fe_s_median": statistics.median(t_fe),
        "fe_repeats": float(len(t_fe)),
        "ratio_fe_over_flexible": min(t_fe) / min(times),
        "e": r.e,
        "e_fe": ref.e,
        "delta_p_um": 1e6 * r.dent_depth,
        "delta_p_fe_um": 1e6 * ref.delta_p,
        "duration_ms": 1e3 * r.sequence_duration,
        "duration_fe_ms": 1e3 * ref.duration,
        "contacts": float(r.n_contacts),
        "contacts_fe": float(len(ref.contacts)),
    }


#: Drops in the batch figure's grid (angles x speeds x friction coefficients).
BATCH_GRID = (np.radians([15.0, 30.0, 45.0, 60.0, 75.0]), [-0.8, -1.41, -2.2, -3.0], [0.1, 0.3])
BATCH_CASES = math.prod(len(a) for a in BATCH_GRID)


def batch_throughput(repeats: int) -> dict[str, float]:
    """Drops per CPU-second of ``simulate_drops`` and of ``simulate_drop`` case by case (one
    thread, best of ``repeats``), their ratio, and the batch's wall time on every core."""
    rod = FlexibleRod.paper()
    th, vy, mu = (a.ravel() for a in np.meshgrid(*BATCH_GRID, indexing="ij"))
    kw = {"law": "ghaednia", "friction": "coulomb"}
    threads = numba.config.NUMBA_NUM_THREADS  # every core (main() runs on one thread)
    numba.set_num_threads(1)
    drops = simulate_drops(rod, angle=th, vy=vy, mu=mu, **kw)  # warm
    singles = [
        simulate_drop(
            rod, angle=float(a), velocity=(0.0, float(v)), mu=float(m), history=False, **kw
        )
        for a, v, m in zip(th, vy, mu, strict=True)
    ]
    identical = all(
        drops.e[i] == r.e and drops.dent_depth[i] == r.dent_depth and drops.n_steps[i] == r.n_steps
        for i, r in enumerate(singles)
    )
    t_batch, t_single = [], []
    for _ in range(repeats):
        t0 = time.process_time()
        simulate_drops(rod, angle=th, vy=vy, mu=mu, **kw)
        t_batch.append(time.process_time() - t0)
        t0 = time.process_time()
        for a, v, m in zip(th, vy, mu, strict=True):  # no history, as the batch keeps none
            simulate_drop(rod, angle=float(a), velocity=(0.0, float(v)), mu=float(m),
                          history=False, **kw)  # fmt: skip
        t_single.append(time.process_time() - t0)
    numba.set_num_threads(threads)
    t0 = time.perf_counter()
    simulate_drops(rod, angle=th, vy=vy, mu=mu, **kw)
    wall_all = time.perf_counter() - t0
    numba.set_num_threads(1)
    per_s_batch = BATCH_CASES / min(t_batch)
    per_s_single = BATCH_CASES / min(t_single)
    return {
        "cases": float(BATCH_CASES),
        "ok_cases": float(np.count_nonzero(drops.ok)),
        "identical_to_simulate_drop": identical,
        "batch_drops_per_cpu_s": per_s_batch,
        "simulate_drop_drops_per_cpu_s": per_s_single,
        "ratio_batch_over_simulate_drop": per_s_batch / per_s_single,
        "batch_wall_s_all_threads": wall_all,
        "threads": float(threads),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="20 deg only, fewer repetitions")
    ap.add_argument("--out", type=Path, default=ROOT / "results" / "flexible.json")
    args = ap.parse_args()
    numba.set_num_threads(1)
    angles = (20,) if args.quick else (20, 45, 70)
    t0 = time.time()
    load_start = os.getloadavg()[0]
    reps, fe_reps = (10, 2) if args.quick else (30, 5)
    per_angle = {str(a): one_angle(a, reps, fe_reps, 80) for a in angles}
    batch = batch_throughput(2 if args.quick else 5)
    result = {
        "machine": {
            "cpu": cpu_model(),
            "logical_cores": os.cpu_count(),
            "load_average_1min": load_start,
            "load_average_1min_end": os.getloadavg()[0],
            "python": sys.version.split()[0],
            "numba": numba.__version__,
            "numpy": np.__version__,
        },
        "case": {
            "body": "FlexibleRod.paper() (Timoshenko, 8+2 axial, 12 bending)",
            "law": "ghaednia",
            "friction": "coulomb",
            "rtol": DROP_DEFAULT_RTOL,
            "fe_elements": 80,
        },
        "angles": per_angle,
        "batch": batch,
        "target_ms": 10.0,
        "target_met": all(v["flexible_ms_median"] <= 10.0 for v in per_angle.values()),
        "wall_s": time.time() - t0,
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(result, indent=2) + "\n")
    m = result["machine"]
    print(
        f"machine: {m['cpu']}, {m['logical_cores']} cores, load {m['load_average_1min']:.1f} "
        f"(start) {m['load_average_1min_end']:.1f} (end)"
    )
    for a, v in per_angle.items():
        print(
            f"{a} deg: flexible {v['flexible_ms_median']:.2f} ms (best {v['flexible_ms_best']:.2f},"
            f" {v['steps']:.0f} steps); FE Ne=80 best {v['fe_s']:.2f} s (median "
            f"{v['fe_s_median']:.2f}); ratio of the bests FE/flexible "
            f"{v['ratio_fe_over_flexible']:.0f}; e {v['e']:.4f} vs {v['e_fe']:.4f}, delta_p "
            f"{v['delta_p_um']:.2f} vs {v['delta_p_fe_um']:.2f} um, T {v['duration_ms']:.3f} vs "
            f"{v['duration_fe_ms']:.3f} ms, contacts {v['contacts']:.0f} vs {v['contacts_fe']:.0f}"
        )
    print(f"target (<= 10 ms per drop on one core) met: {result['target_met']}")
    print(
        f"batch of {batch['cases']:.0f} drops on one thread: {batch['batch_drops_per_cpu_s']:.0f}"
        f" drops per CPU-second against {batch['simulate_drop_drops_per_cpu_s']:.0f} for "
        f"simulate_drop case by case (ratio {batch['ratio_batch_over_simulate_drop']:.2f}; "
        f"identical: {batch['identical_to_simulate_drop']}); all {batch['threads']:.0f} "
        f"threads: {batch['batch_wall_s_all_threads']:.2f} s wall"
    )
    print(f"written {args.out}")


if __name__ == "__main__":
    main()
