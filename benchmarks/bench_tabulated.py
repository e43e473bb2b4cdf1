"""Cost per impact of the tabulated law relative to Ghaednia's, measured in ONE run.

Case: bench_engine.py's (the paper's rod, 20 deg, vy = -1.41 m/s, mu = 0.2, Coulomb friction,
gravity on, default tolerance), once with ``law="ghaednia"`` (its loading curve from the
polynomial table) and once with ``law="tabulated"`` (the shipped FE curves of the paper's
pair), plus a faster impact (vy = -5 m/s, deeper into the plastic range). numba runs on one
thread; the two laws run interleaved, round after round, and the best CPU time of each is kept
(the shared machine's speed drifts). Target: tabulated / ghaednia <= 1.5.

    .venv/bin/python benchmarks/bench_tabulated.py [--quick]

Writes benchmarks/results/tabulated.json and prints a summary.
"""

from __future__ import annotations

import argparse
import json
import math
import time
from pathlib import Path

import numba
import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import FRICTION_IDS, OUTPUT_FIELDS, run_arrays
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010

ROOT = Path(__file__).resolve().parent
LAWS = ("ghaednia", "tabulated")
TARGET = 1.5


def _inputs(law: str, n: int, vy: float) -> tuple:
    model = contact_model(PAPER_ROD, AISI_1010, law)
    init = np.zeros((n, 4))
    init[:, 0] = math.radians(20.0)
    init[:, 2] = vy
    return (
        model.law_id,
        FRICTION_IDS["coulomb"],
        kernel_params(model),
        PAPER_ROD.to_params(AISI_1010),
        init,
        np.full(n, 0.2),
    )


def measure(n: int, rounds: int, vy: float) -> dict[str, float]:
    """Best CPU microseconds per impact of each law (interleaved rounds) and their ratio."""
    numba.set_num_threads(1)
    args = {law: _inputs(law, n, vy) for law in LAWS}
    steps = {}
    for law in LAWS:  # warm, and check that every impact succeeds
        out, status = run_arrays(*args[law])
        assert np.all(status == 0), law
        steps[law] = float(out[0, OUTPUT_FIELDS.index("n_steps")])
    best = dict.fromkeys(LAWS, math.inf)
    for _ in range(rounds):
        for law in LAWS:
            c0 = time.process_time()
            run_arrays(*args[law])
            best[law] = min(best[law], time.process_time() - c0)
    us = {law: 1e6 * best[law] / n for law in LAWS}
    return {
        "vy": vy,
        "n": n,
        "us_per_impact_ghaednia": us["ghaednia"],
        "us_per_impact_tabulated": us["tabulated"],
        "ratio": us["tabulated"] / us["ghaednia"],
        "steps_ghaednia": steps["ghaednia"],
        "steps_tabulated": steps["tabulated"],
    }


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer impacts and rounds")
    a = ap.parse_args()
    n, rounds = (2000, 3) if a.quick else (20000, 7)
    cases = [measure(n, rounds, vy) for vy in (-1.41, -5.0)]
    result = {"target_ratio": TARGET, "cases": cases}
    (ROOT / "results").mkdir(exist_ok=True)
    (ROOT / "results" / "tabulated.json").write_text(json.dumps(result, indent=2) + "\n")
    for c in cases:
        print(
            f"vy = {c['vy']:g} m/s: ghaednia {c['us_per_impact_ghaednia']:.2f} us, tabulated "
            f"{c['us_per_impact_tabulated']:.2f} us per impact (CPU, 1 thread): ratio "
            f"{c['ratio']:.3f} (target <= {TARGET}); steps {c['steps_ghaednia']:g} / "
            f"{c['steps_tabulated']:g}"
        )


if __name__ == "__main__":
    main()
