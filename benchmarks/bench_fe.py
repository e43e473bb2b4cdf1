"""Benchmark of the FE indentation reference: one curve of the paper's pair to 1000 delta_c.

Case: AISI 201 sphere (R = 8.8 mm, elastic-perfectly plastic) on AISI 1010, frictionless, mesh
level 1, loaded to 1000 delta_c (436 um) and unloaded, one ccx process (OMP_NUM_THREADS=1),
the cache bypassed. The target: at most 10 minutes on the project's 2-core machine.
Recorded: 2026-11-28, CalculiX 2.20, gmsh 4.15.2, the shared 2-core machine under other load:
about 4 minutes of ccx (95 increments, 19 cut-backs, 2 324 elements), converged.

    python3 benchmarks/bench_fe.py [--mesh N]

Writes benchmarks/results/fe.json and prints a summary.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from impactlab.fe import indent
from impactlab.fe.problem import make_problem
from impactlab.materials import AISI_201, AISI_1010

ROOT = Path(__file__).resolve().parent
TARGET_S = 600.0


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--mesh", type=int, default=1)
    args = parser.parse_args()
    dc = make_problem(AISI_1010, AISI_201, radius=8.8e-3, delta_max=1e-9).delta_c
    t0 = time.perf_counter()
    (res,) = indent(
        AISI_1010,
        AISI_201,
        radius=8.8e-3,
        delta_max=1000 * dc,
        mesh_level=args.mesh,
        use_cache=False,
        workers=1,
    )
    wall = time.perf_counter() - t0
    out = {
        "case": f"paper pair, 1000 delta_c, mesh level {args.mesh}",
        "wall_s": wall,
        "ccx_s": res.run_time,
        "target_s": TARGET_S,
        "converged": res.converged,
        "increments": res.increments,
        "cutbacks": res.cutbacks,
        "elements": res.n_elements,
        "max_force_N": res.max_force,
        "residual_ratio": res.residual_ratio,
    }
    (ROOT / "results").mkdir(exist_ok=True)
    (ROOT / "results" / "fe.json").write_text(json.dumps(out, indent=2) + "\n")
    print(json.dumps(out, indent=2))
    print(f"{'within' if wall <= TARGET_S else 'OVER'} the {TARGET_S:.0f} s target")


if __name__ == "__main__":
    main()
