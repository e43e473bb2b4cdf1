"""Where the compiled engine spends its time on the benchmark case (docs/engine/benchmarks.md).

    .venv/bin/python benchmarks/profile_engine.py [--n N] [--out OUT]

Two measurements, combined:

1. counts (a child process with ``NUMBA_DISABLE_JIT=1``: the same code run as plain Python, its
   functions wrapped by counters): accepted and rejected steps, right-hand-side and contact-law
   evaluations, event-function evaluations during event location, events;
2. times (compiled, one thread, minimum of several repeats): one impact, one contact-law
   evaluation on the elastic-plastic branch, one right-hand-side evaluation, and ``simulate()``
   from Python against the bare compiled call.

The split is an estimate: law time = law evaluations x time per evaluation; rhs rest = rhs
evaluations x (time per rhs - time per law evaluation); the remainder of the impact time is the
stepping (stage sums, error norm, controller) and the events.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent
CASE = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2, "angle": math.radians(20.0)}
VY = -1.41


def _counts() -> dict[str, int]:
    """Instrumented run of the benchmark case in plain Python (NUMBA_DISABLE_JIT=1)."""
    from impactlab.bodies import PAPER_ROD
    from impactlab.dynamics.core import approach, driver, ends, integrator
    from impactlab.dynamics.kernels import normal, rhs, transitions
    from impactlab.dynamics.kernels.layout import N_OUT, O_NST
    from impactlab.dynamics.models import body_params, contact_model, kernel_params
    from impactlab.friction import FRICTION_IDS
    from impactlab.materials import AISI_1010

    n: dict[str, int] = {}

    def wrap(mod, name, key):  # type: ignore[no-untyped-def]
        f = getattr(mod, name)

        def counted(*a):  # type: ignore[no-untyped-def]
            n[key] = n.get(key, 0) + 1
            return f(*a)

        setattr(mod, name, counted)
        return f

    for mod in (normal, transitions):
        wrap(mod, "loading_force", "law_evaluations")
    wrap(normal, "table_force", "law_evaluations")  # the tabulated curve, read inline in the stages
    wrap(rhs, "evaluate", "rhs_evaluations")
    wrap(integrator, "event_value", "event_function_evaluations")
    wrap(driver, "integrate_to", "events_recomputed")
    wrap(driver, "handle_event", "events")
    wrap(ends, "handle_event", "events")
    wrap(approach, "_rhs_w", "rhs_evaluations_in_w")
    wrap(approach, "_step", "steps_in_w")
    dp = integrator.dp_step

    def step(*a):  # type: ignore[no-untyped-def]
        res = dp(*a)
        key = "accepted_steps" if res[0] <= 1.0 else "rejected_steps"
        n[key] = n.get(key, 0) + 1
        return res

    driver.dp_step = step
    integrator.dp_step = step
    model = contact_model(PAPER_ROD, AISI_1010, CASE["law"])
    out = np.empty(N_OUT)
    driver.impact(
        model.law_id,
        kernel_params(model),
        FRICTION_IDS[CASE["friction"]],
        body_params(PAPER_ROD, AISI_1010),
        CASE["angle"],
        0.0,
        VY,
        0.0,
        CASE["mu"],
        9.80665,
        False,
        float(os.environ.get("PROFILE_RTOL", "nan")),
        False,
        False,
        out,
    )
    n["n_steps_output"] = int(out[O_NST])
    return n


def _child_counts(rtol: float) -> dict[str, int]:
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PROFILE_RTOL=repr(rtol))
    p = subprocess.run(
        [sys.executable, __file__, "--child"], capture_output=True, text=True, env=env, check=True
    )
    return json.loads(p.stdout.strip().splitlines()[-1])


def _best(f, repeats: int = 7) -> float:  # type: ignore[no-untyped-def]
    best = math.inf
    for _ in range(repeats):
        t0 = time.process_time()
        f()
        best = min(best, time.process_time() - t0)
    return best


def _times(n: int) -> dict[str, float]:
    import numba
    from numba import njit

    from impactlab.bodies import PAPER_ROD
    from impactlab.contact.kernels import P_DSW, loading_force
    from impactlab.dynamics import DEFAULT_RTOL, simulate
    from impactlab.dynamics.core import driver
    from impactlab.dynamics.kernels.layout import N_OUT, O_NST
    from impactlab.dynamics.kernels.rhs import rhs
    from impactlab.dynamics.kernels.setup import constants, initial_mode
    from impactlab.dynamics.models import body_params, contact_model, kernel_params
    from impactlab.friction import FRICTION_IDS
    from impactlab.materials import AISI_1010

    numba.set_num_threads(1)
    model = contact_model(PAPER_ROD, AISI_1010, CASE["law"])
    p = kernel_params(model)
    bp = body_params(PAPER_ROD, AISI_1010)
    fid = FRICTION_IDS[CASE["friction"]]

    @njit
    def law_loop(law, p, d0, m):  # type: ignore[no-untyped-def]
        s = 0.0
        for i in range(m):
            s += loading_force(law, p, d0 * (1.0 + 1e-9 * i))
        return s

    @njit
    def rhs_loop(law, p, fric, bp, th0, mu, d0, m):  # type: ignore[no-untyped-def]
        c = constants(p, bp, th0, mu, 9.80665, False)
        md = initial_mode(fric, p, c, 0.0, -1.0, 0.0)
        s = 0.0
        for i in range(m):
            y = (0.0, -d0 * (1.0 + 1e-9 * i), 0.0, 0.0, -1.0, 0.0, 0.0, 0.0)
            s += rhs(law, p, fric, c, md, y)[4]
        return s

    @njit
    def impact_loop(law, p, fric, bp, th0, vy, mu, rtol, m, out):  # type: ignore[no-untyped-def]
        for _ in range(m):
            driver.impact(law, p, fric, bp, th0, 0.0, vy, 0.0, mu, 9.80665, False, rtol,
                          False, False, out)  # fmt: skip

    d_ep = 3.0 * p[P_DSW]  # on the elastic-plastic branch
    out = np.empty(N_OUT)
    m = 200_000
    law_loop(model.law_id, p, d_ep, 10)
    rhs_loop(model.law_id, p, fid, bp, CASE["angle"], CASE["mu"], d_ep, 10)
    impact_loop(model.law_id, p, fid, bp, CASE["angle"], VY, CASE["mu"], DEFAULT_RTOL, 2, out)
    t_law = _best(lambda: law_loop(model.law_id, p, d_ep, m)) / m
    t_hertz = _best(lambda: law_loop(model.law_id, p, 0.5 * p[P_DSW], m)) / m
    t_rhs = _best(lambda: rhs_loop(model.law_id, p, fid, bp, CASE["angle"], CASE["mu"], d_ep, m))
    t_imp = _best(
        lambda: impact_loop(
            model.law_id, p, fid, bp, CASE["angle"], VY, CASE["mu"], DEFAULT_RTOL, n, out
        )
    )
    kw = dict(CASE, velocity=(0.0, VY), history=False)
    simulate(PAPER_ROD, **kw)
    reps = 3000
    t_sim = _best(lambda: [simulate(PAPER_ROD, **kw) for _ in range(reps)]) / reps
    return {
        "rtol": DEFAULT_RTOL,
        "law_evaluation_ns_elastic_plastic": 1e9 * t_law,
        "law_evaluation_ns_hertz": 1e9 * t_hertz,
        "rhs_evaluation_ns": 1e9 * t_rhs / m,
        "impact_us": 1e6 * t_imp / n,
        "simulate_us": 1e6 * t_sim,
        "n_steps": float(out[O_NST]),
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--n", type=int, default=5000, help="impacts timed")
    ap.add_argument("--out", type=Path, default=ROOT / "results" / "profile.json")
    args = ap.parse_args()
    if args.child:
        print(json.dumps(_counts()))
        return
    t = _times(args.n)
    c = _child_counts(t["rtol"])
    law_us = c.get("law_evaluations", 0) * t["law_evaluation_ns_elastic_plastic"] * 1e-3
    rhs_rest_us = (
        c.get("rhs_evaluations", 0)
        * (t["rhs_evaluation_ns"] - t["law_evaluation_ns_elastic_plastic"])
        * 1e-3
    )
    split = {
        "law_evaluation_us_upper_bound": law_us,
        "rhs_rest_us": rhs_rest_us,
        "stepping_and_events_us": t["impact_us"] - law_us - rhs_rest_us,
        "python_overhead_us": t["simulate_us"] - t["impact_us"],
    }
    res = {"counts": c, "times": t, "split": split}
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(res, indent=2) + "\n")
    print(json.dumps(res, indent=2))


if __name__ == "__main__":
    main()
