#!/usr/bin/env python3
"""Calibration benchmark: the cost of a calibration on the compiled batch engine, the full-size
coverage check, and the cost of the models the batch does not run.

    python benchmarks/bench_calibrate.py --quick     # speed parts only (a few minutes)
    python benchmarks/bench_calibrate.py             # + coverage over 50 data sets (~20 min)

Measured in one run (ratios only between numbers of this run):

1. baseline: ``run_arrays`` alone on 20 rigid drops x 5000 parameter vectors, one shared law
   (what the engine costs per impact at best);
2. calibration: flat S_y and mu (2 parameters) over 20 rigid drops of the paper's rod,
   emcee with 20 walkers x 250 steps = 100 000 model evaluations and more; target < 2 minutes
   on the 2-core machine; the ratio of its time per evaluation to (1) is the price of a new
   contact model per walker (S_y enters the law) and of the sampler;
3. partial slip in the batch engine against the batch's Coulomb impacts of the same sphere
   (CPU time per impact with numba on one thread, best of five rounds, and their ratio);
4. flexible rod: the flexible drop per case (``body = "flexible_rod"``) against the rigid rod;
5. (full mode) coverage: 50 synthetic data sets (S_y = 300 MPa, mu = 0.15, 3 drops, e,
   delta_p, spin_out, sliding_length with noise), the share of 90 % intervals holding the
   true value, per parameter; required 80-97 %.

Results go to benchmarks/results/calibrate.json (``--quick``: calibrate_quick.json) with the
machine's load average.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results" / "calibrate.json"
sys.path.insert(0, str(ROOT / "tests" / "calibrate"))


def _drops(n: int, sigmas: dict[str, float], mu: float | None = None):  # type: ignore[no-untyped-def]
    from conftest import paper_drops  # the tests' template of the paper's rod

    angles = np.linspace(10.0, 80.0, n) if n > 3 else (20.0, 45.0, 70.0)
    extra = {} if mu is None else {"mu": mu}
    vy = -1.4
    return paper_drops(angles=tuple(float(a) for a in angles), vy=vy, sigmas=sigmas, **extra)


def _timed(f):  # type: ignore[no-untyped-def]
    t = time.perf_counter()
    out = f()
    return out, time.perf_counter() - t


def baseline(n_drops: int, n_vectors: int) -> dict[str, float]:
    from impactlab.calibrate import CandidateModel, parse_parameter, predict

    m = _drops(n_drops, {"e": 0.01})
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    theta = np.linspace(0.05, 0.5, n_vectors)[:, None]
    predict(CandidateModel(), m, [mu], theta[:10])
    _, dt = _timed(lambda: predict(CandidateModel(), m, [mu], theta))
    n = n_drops * n_vectors
    return {"impacts": n, "seconds": dt, "per_impact_us": dt / n * 1e6}


def calibration(n_drops: int, walkers: int, steps: int) -> dict[str, float]:
    from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
    from impactlab.calibrate.synthetic import synthetic_measurements

    sig = {"e": 0.01, "delta_p": 1e-6, "spin_out": 0.3, "sliding_length": 3e-6}
    params = [
        parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)"),
        parse_parameter("mu", "uniform(0, 0.6)"),
    ]
    data = synthetic_measurements(
        _drops(n_drops, sig), CandidateModel(), params, [3e8, 0.15], np.random.default_rng(0)
    )
    cal, dt = _timed(lambda: calibrate(data, params, walkers=walkers, steps=steps, seed=0))
    post = cal.best
    return {
        "drops": n_drops,
        "walkers": walkers,
        "steps": steps,
        "evaluations": post.evaluations,
        "seconds": dt,
        "per_evaluation_us": dt / post.evaluations * 1e6,
        "S_y_q05_q95_MPa": [post.summary["flat_yield_strength"][k] / 1e6 for k in ("q05", "q95")],
        "mu_q05_q95": [post.summary["mu"][k] for k in ("q05", "q95")],
        "rhat_max": max(s["rhat"] for s in post.summary.values()),
    }


def partial_slip(n: int) -> dict[str, float]:
    from impactlab.calibrate import CandidateModel, Measurements, parse_parameter, predict

    recs = [
        {
            "label": f"{i}",
            "body": "sphere",
            "radius": "2.5 mm",
            "vx": float(v),
            "vy": -3.0,
            "e_t": 0.5,
            "e_t_sigma": 0.1,
        }
        for i, v in enumerate(np.linspace(0.2, 3.0, n))
    ]
    m = Measurements.from_records(recs)
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    theta = np.array([[0.1], [0.2], [0.3], [0.4]])
    import numba

    out: dict[str, float] = {}
    threads = numba.get_num_threads()
    numba.set_num_threads(1)  # CPU time per core: robust against the other load
    try:
        for fr in ("coulomb", "partial_slip"):
            model = CandidateModel("hertz", fr)
            predict(model, m, [mu], theta[:1])
            for _ in range(5):
                t0 = time.process_time()
                predict(model, m, [mu], theta)
                us = (time.process_time() - t0) / (n * len(theta)) * 1e6
                out[fr] = min(out.get(fr, math.inf), us)
    finally:
        numba.set_num_threads(threads)
    out["ratio"] = out["partial_slip"] / out["coulomb"]
    return {"per_impact_us": out, "ratio_partial_slip_to_batch": out["ratio"]}


def flexible(n: int) -> dict[str, float]:
    from impactlab.calibrate import CandidateModel, parse_parameter, predict

    m = _drops(3, {"e": 0.01})
    mu = parse_parameter("mu", "uniform(0, 0.6)")
    theta = np.linspace(0.1, 0.3, n)[:, None]
    out = {}
    for body in (None, "flexible_rod"):
        model = CandidateModel(body=body)
        predict(model, m, [mu], theta[:1])
        _, dt = _timed(lambda model=model: predict(model, m, [mu], theta))
        out[body or "rigid_rod"] = dt / (3 * n) * 1e3
    return {"per_drop_ms": out, "ratio_flexible_to_rigid": out["flexible_rod"] / out["rigid_rod"]}


def coverage(n_sets: int, walkers: int, steps: int) -> dict[str, object]:
    from impactlab.calibrate import CandidateModel, calibrate, parse_parameter
    from impactlab.calibrate.synthetic import synthetic_measurements

    sig = {"e": 0.01, "delta_p": 1e-6, "spin_out": 0.3, "sliding_length": 3e-6}
    params = [
        parse_parameter("flat_yield_strength", "uniform(100 MPa, 1 GPa)"),
        parse_parameter("mu", "uniform(0, 0.6)"),
    ]
    truth = [3e8, 0.15]
    template = _drops(3, sig)
    hits = np.zeros(2, dtype=int)
    t0 = time.perf_counter()
    for i in range(n_sets):
        data = synthetic_measurements(
            template, CandidateModel(), params, truth, np.random.default_rng(10_000 + i)
        )
        cal = calibrate(data, params, walkers=walkers, steps=steps, seed=i, n_ppc=0)
        for j, p in enumerate(params):
            lo, hi = cal.best.interval(p.name)
            hits[j] += lo <= truth[j] <= hi
        print(f"  coverage {i + 1}/{n_sets}: {hits.tolist()}", flush=True)
    share = (hits / n_sets).tolist()
    return {
        "data_sets": n_sets,
        "walkers": walkers,
        "steps": steps,
        "covered": dict(zip(("flat_yield_strength", "mu"), hits.tolist(), strict=True)),
        "share": dict(zip(("flat_yield_strength", "mu"), share, strict=True)),
        "within_80_97": all(0.80 <= s <= 0.97 for s in share),
        "seconds": time.perf_counter() - t0,
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("--quick", action="store_true", help="skip the coverage part")
    ap.add_argument("--sets", type=int, default=50, help="coverage data sets (default 50)")
    args = ap.parse_args(argv)
    res: dict[str, object] = {
        "machine": {
            "cpu": platform.processor(),
            "cores": os.cpu_count(),
            "load_average_start": os.getloadavg(),
        },
    }
    res["baseline"] = b = baseline(20, 5000)
    print(f"baseline: {b['impacts']} impacts in {b['seconds']:.2f} s")
    res["calibration"] = c = calibration(20, 20, 250)
    c["ratio_to_baseline_per_impact"] = c["per_evaluation_us"] / b["per_impact_us"]
    print(
        f"calibration: {c['evaluations']} evaluations in {c['seconds']:.1f} s "
        f"(target < 120 s; {c['ratio_to_baseline_per_impact']:.1f}x the baseline per impact)"
    )
    res["partial_slip"] = ps = partial_slip(20)
    print(f"partial slip: {ps['ratio_partial_slip_to_batch']:.0f}x the batch per impact")
    res["flexible"] = fx = flexible(8)
    print(f"flexible rod: {fx['ratio_flexible_to_rigid']:.0f}x the rigid rod per drop")
    if not args.quick:
        res["coverage"] = cv = coverage(args.sets, 12, 200)
        print(f"coverage: {cv['share']} (required 0.80-0.97: {cv['within_80_97']})")
    res["machine"]["load_average_end"] = os.getloadavg()  # type: ignore[index]
    path = RESULTS.with_name("calibrate_quick.json") if args.quick else RESULTS
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(json.dumps(res, indent=2))
    print(f"written {path}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
