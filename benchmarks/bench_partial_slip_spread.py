#!/usr/bin/env python3
"""``friction="partial_slip"`` against ``friction="mindlin"`` over a spread of impacts: the
cost per impact and its steps, and the work against the accuracy at several tolerances.

    .venv/bin/python benchmarks/bench_partial_slip_spread.py [--repeats 3] [--rtols 2e-7 3e-8]

The spread is that of ``tools/partial_slip_compare.py`` (243 impacts): the paper's rod at 9
angles (5 ... 85 deg, vy = -1.41 m/s) and a 10 mm steel sphere at 18 (speed, incidence) pairs
(0.5, 2 and 5 m/s; 2 ... 85 deg), each with the ``hertz``, ``ghaednia`` and ``thornton`` laws
and mu = 0.1, 0.3 and 0.6.

1. Cost: each (body, law, mu) group in one ``simulate_batch`` call, every case ``TILE`` times
   (the call's fixed cost spread), at each model's default tolerance; CPU seconds of this
   process with numba on one thread, the best of ``--repeats`` rounds; the ratio partial slip /
   mindlin per group and over all, and the integration steps per impact.
2. Work and accuracy: each model at each of ``--rtols`` against its own run at rtol 1e-10:
   the steps of the 243 impacts and the relative errors of e, vt_out and energy_dissipated
   (median, 90th percentile, largest; relative to max(|reference|, 1e-3 of the output's largest
   magnitude over the spread), as in ``tools/partial_slip_compare.py``).

Writes benchmarks/results/partial_slip_spread.json and prints a summary. The 20 cases of
``bench_partial_slip.py`` are the figure of merit; this is the wider view behind it.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numba
import numpy as np

import impactlab as il
from impactlab.materials import AISI_1010

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_partial_slip import best_cpu, cpu_model, write_results

ROOT = Path(__file__).resolve().parent
RESULTS = ROOT / "results" / "partial_slip_spread.json"
LAWS = ("hertz", "ghaednia", "thornton")
MUS = (0.1, 0.3, 0.6)
MODELS = ("mindlin", "partial_slip")
ERROR_FIELDS = ("e", "vt_out", "energy_dissipated")
#: A batch holds each case this many times: its fixed cost per call (about 0.28 ms) spread over
#: 1800 (rod) and 3600 (sphere) impacts, about 1 % of `mindlin`'s time.
TILE = 200
REFERENCE_RTOL = 1e-10


def kinematics(tile: int) -> dict[str, dict[str, np.ndarray]]:
    """The batch arguments of the rod's and the sphere's cases, each case ``tile`` times."""
    angle = np.radians(np.linspace(5.0, 85.0, 9))
    speed, inc = np.meshgrid([0.5, 2.0, 5.0], np.radians([2.0, 10.0, 25.0, 45.0, 65.0, 85.0]))
    return {
        "rod": {"angle": np.tile(angle, tile), "vy": np.full(9 * tile, -1.41)},
        "sphere": {"speed": np.tile(speed.ravel(), tile), "incidence": np.tile(inc.ravel(), tile)},
    }


BODIES = {"rod": il.Rod.paper(), "sphere": il.Sphere(radius=0.01)}


def batch(body: str, law: str, mu: float, model: str, rtol: float | None, tile: int) -> object:
    kin = kinematics(tile)[body]
    return il.simulate_batch(
        BODIES[body],  # type: ignore[arg-type]
        AISI_1010,
        law=law,
        friction=model,
        mu=mu,
        rtol=rtol,
        **kin,  # type: ignore[arg-type]
    )


def cost(repeats: int) -> dict[str, object]:
    groups = []
    total = dict.fromkeys(MODELS, 0.0)
    steps = dict.fromkeys(MODELS, 0.0)
    n_total = 0
    for body in BODIES:
        for law in LAWS:
            for mu in MUS:
                row: dict[str, object] = {"body": body, "law": law, "mu": mu}
                calls = [
                    lambda b=body, la=law, u=mu, m=model: batch(b, la, u, m, None, TILE)
                    for model in MODELS
                ]
                times = best_cpu(calls, repeats)  # the models' rounds alternated
                for model, t in zip(MODELS, times, strict=True):
                    r = batch(body, law, mu, model, None, TILE)
                    n = len(r.status) // TILE  # type: ignore[attr-defined]
                    row[f"{model}_us"] = t / TILE / n * 1e6
                    total[model] += t / TILE
                    steps[model] += float(np.sum(r["n_steps"])) / TILE  # type: ignore[index]
                n_total += n
                row["ratio"] = row["partial_slip_us"] / row["mindlin_us"]  # type: ignore[operator]
                groups.append(row)
                print(f"{body:6s} {law:9s} mu {mu}: ratio {row['ratio']:5.1f}", flush=True)
    return {
        "impacts": n_total,
        "groups": groups,
        "mindlin_us": total["mindlin"] / n_total * 1e6,
        "partial_slip_us": total["partial_slip"] / n_total * 1e6,
        "ratio": total["partial_slip"] / total["mindlin"],
        "steps_per_impact": {m: steps[m] / n_total for m in MODELS},
    }


def outputs(model: str, rtol: float) -> dict[str, np.ndarray]:
    """The error fields and the steps of the 243 impacts at ``rtol``."""
    cols: dict[str, list[np.ndarray]] = {f: [] for f in (*ERROR_FIELDS, "n_steps")}
    for body in BODIES:
        for law in LAWS:
            for mu in MUS:
                r = batch(body, law, mu, model, rtol, 1)
                for f in cols:
                    cols[f].append(np.asarray(r[f], dtype=float))  # type: ignore[index]
    return {f: np.concatenate(v) for f, v in cols.items()}


def work_precision(rtols: list[float]) -> list[dict[str, object]]:
    rows = []
    for model in MODELS:
        ref = outputs(model, REFERENCE_RTOL)
        for rtol in rtols:
            run = outputs(model, rtol)
            row: dict[str, object] = {"model": model, "rtol": rtol}
            row["steps"] = float(np.sum(run["n_steps"]))
            for f in ERROR_FIELDS:
                b = ref[f]
                rel = np.abs(run[f] - b) / np.maximum(np.abs(b), 1e-3 * np.nanmax(np.abs(b)))
                row[f] = [float(np.median(rel)), float(np.quantile(rel, 0.9)), float(rel.max())]
            rows.append(row)
            errs = "; ".join(
                f"{f} {row[f][0]:.1e}/{row[f][1]:.1e}/{row[f][2]:.1e}"  # type: ignore[index]
                for f in ERROR_FIELDS
            )
            print(f"{model:12s} rtol {rtol:.0e}: {row['steps']:.0f} steps; {errs}", flush=True)
    return rows


def main(argv: list[str]) -> int:
    # the docstring's first paragraph, whole (its first line alone stops mid-sentence)
    ap = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    ap.add_argument("--repeats", type=int, default=3, help="rounds of the cost, the best kept")
    ap.add_argument(
        "--rtols",
        type=float,
        nargs="*",
        default=[2e-7, 1e-7, 3e-8],
        help="the tolerances of the work-accuracy comparison (against rtol 1e-10)",
    )
    args = ap.parse_args(argv)
    numba.set_num_threads(1)
    result = {
        "machine": {"cpu": cpu_model(), "numba_threads": 1},
        "setup": {
            "laws": list(LAWS),
            "mus": list(MUS),
            "tile": TILE,
            "repeats": args.repeats,
            "reference_rtol": REFERENCE_RTOL,
            "clock": "process CPU time, numba on one thread, best of repeats",
        },
        "cost": cost(args.repeats),
        "work_precision": work_precision(args.rtols),
    }
    c = result["cost"]
    print(
        f"all {c['impacts']} impacts: mindlin {c['mindlin_us']:.1f} us, partial slip "  # type: ignore[index]
        f"{c['partial_slip_us']:.1f} us per impact, ratio {c['ratio']:.2f}"  # type: ignore[index]
    )
    write_results(result, RESULTS)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
