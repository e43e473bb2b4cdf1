"""Randomised drops of the flexible rod: the trust checks of the drop over many random inputs.

Each case draws the mode counts (one of ``MODE_SETS``: 0 to 16 axial, with or without the
residual pseudo-modes, 0 to 24 bending), the damping, the contact law, the friction model, mu,
the rate law (none, Cowper-Symonds, Johnson-Cook), the angle (log-uniform from 0.001 deg to
90 deg: both ends near the flat at the low end), the velocities and the spin, and ``stop``
("sequence", or "flight": the other end's impacts too). A drop either fails with a clear
one-line ``ValueError`` (a ``DropError`` with its status, or a refused input), or returns a
result that must pass:

* no missed contact (the drop's own invariant refuses one: status ``ST_MISSED_CONTACT``,
  counted; with ``--history`` also checked on the recorded history: while its force is zero
  the tip never lies deeper than the deepest dent by more than the invariant's tolerance);
* e >= 0, or a flag (not ``ok``);
* no energy gain beyond the tolerance without a flag (final rigid kinetic + vibration +
  potential energy against the initial kinetic energy, the ENERGY_GAIN criterion);
* finite outputs; 0 <= delta_p <= delta_max;
* the contacts' works of the normal force and of friction add up to the drop's (to 1e-9 of
  E0 + |W_n| + |W_t|; every result, flagged or not): each contact's are its end's own.

Anything else (an unexpected exception, an unflagged anomaly) is an anomaly and is printed
with the inputs that reproduce it.

    NUMBA_CACHE_DIR=.numba_cache .venv/bin/python benchmarks/bench_flexible_fuzz.py \\
        [--n 100000] [--seconds 600] [--seed 1] [--history 0.02]

Writes benchmarks/results/flexible_fuzz.json (counts, timing, the anomalies) and prints a
summary. The test suite runs a few hundred of the same cases
(tests/flexible/test_drop_fuzz.py).
"""

from __future__ import annotations

import argparse
import collections
import json
import math
import os
import sys
import time
import traceback
from pathlib import Path
from typing import Any

import numba
import numpy as np

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import DropError, simulate_drop
from impactlab.dynamics.flexcore import layout as F
from impactlab.flags import ENERGY_GAIN_RTOL_FACTOR, ENERGY_ROUNDOFF, ResultFlag

ROOT = Path(__file__).resolve().parent
LAWS = ("ghaednia", "jackson-green", "kogut-komvopoulos", "brake", "thornton", "hertz")
FRICTION = ("coulomb", "impulse_ratio", "mindlin", "partial_slip")
RATES = (None, None, "cowper-symonds", "johnson-cook")


#: (n_axial, n_bending, axial_residual) of the drawn rods: a fixed set, so that the modal bases
#: (0.1 to 0.4 s each to build, cached) are built once, not per drop.
MODE_SETS = (
    (0, 0, False), (1, 0, False), (1, 1, True), (2, 4, True), (2, 4, False), (3, 6, True),
    (4, 8, True), (8, 0, True), (0, 12, False), (8, 12, True), (8, 12, False), (16, 24, True),
)  # fmt: skip


def random_case(rng: np.random.Generator, min_speed: float = 0.05) -> dict[str, Any]:
    """The keyword arguments of one random drop (``body`` a FlexibleRod's fields); |vy| from
    ``min_speed`` to 4 m/s, log-uniform."""
    n_axial, n_bending, residual = MODE_SETS[int(rng.integers(0, len(MODE_SETS)))]
    law = str(rng.choice(LAWS))
    return {
        "body": {
            "n_axial": n_axial,
            "n_bending": n_bending,
            "axial_residual": residual,
            "damping": float(rng.choice([0.0, 0.0, rng.uniform(0.0, 0.05)])),
        },
        "law": law,
        "friction": str(rng.choice(FRICTION)),
        "mu": float(rng.choice([0.0, rng.uniform(0.0, 0.6)])),
        "rate": None if law == "hertz" else RATES[int(rng.integers(0, len(RATES)))],
        "angle": math.radians(float(10.0 ** rng.uniform(-3.0, math.log10(90.0)))),
        "velocity": (
            float(rng.uniform(-1.0, 1.0)),
            -float(10.0 ** rng.uniform(math.log10(min_speed), math.log10(4.0))),
        ),
        "spin": float(rng.choice([0.0, rng.uniform(-15.0, 15.0)])),
        "stop": str(rng.choice(["sequence", "flight"])),
    }


def run_case(case: dict[str, Any], history: bool = False) -> Any:
    """The drop of ``case`` (its DropResult; exceptions propagate)."""
    kw = {k: v for k, v in case.items() if k != "body"}
    return simulate_drop(FlexibleRod.paper(**case["body"]), history=history, **kw)


def anomalies(r: Any, rtol: float = F.DROP_DEFAULT_RTOL) -> list[str]:
    """What is wrong with a returned result (``[]``: nothing)."""
    bad = []
    works = r.initial_energy + abs(r.work_normal) + abs(r.work_friction)
    for name in ("work_normal", "work_friction"):  # each contact's are its end's own
        total = sum(getattr(c, name) for c in r.contacts)
        if abs(total - getattr(r, name)) > 1e-9 * works:
            bad.append(
                f"the contacts' {name} add up to {total!r}, the drop's is {getattr(r, name)!r}"
            )
    if not r.ok:
        return bad  # flagged: the result says it is not plain success
    scalars = {
        "e": r.e,
        "dent_depth": r.dent_depth,
        "delta_max": r.delta_max,
        "sequence_duration": r.sequence_duration,
        "vibration_energy": r.vibration_energy,
        "rigid_kinetic_energy": r.rigid_kinetic_energy,
        "sequence_sliding_length": r.sequence_sliding_length,
        "sequence_mean_force": r.sequence_mean_force,
        "energy_error": r.energy_error,
    }
    for name, v in scalars.items():
        if not math.isfinite(v):
            bad.append(f"{name} = {v!r} not finite")
    if not r.e >= 0.0:
        bad.append(f"e = {r.e!r} < 0 without a flag")
    if not 0.0 <= r.dent_depth <= r.delta_max:
        bad.append(f"dent_depth = {r.dent_depth!r} outside [0, delta_max = {r.delta_max!r}]")
    e_end = r.rigid_kinetic_energy + r.vibration_energy + r.potential_energy
    scale = r.initial_energy + r.rigid_kinetic_energy + r.vibration_energy
    scale += abs(r.potential_energy)
    if e_end - r.initial_energy > (ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF) * scale:
        bad.append(f"energy gain {e_end / r.initial_energy - 1.0:.3g} E0 without a flag")
    if r.history is not None:
        miss = history_miss(r)
        if miss:
            bad.append(miss)
    return bad


def history_miss(r: Any) -> str:
    """A missed contact in the recorded history: the tip deeper than its deepest dent (by more
    than the invariant's tolerance, bounded here by 1e-6 of the deepest dent + 1e-12 m) while
    its force is zero ("" if none)."""
    h = r.history
    dr = max((d.delta_p for d in r.dents if d.end == 0), default=0.0)
    over = (h["penetration_0"] - dr) * (h["normal_force_0"] == 0.0)
    worst = float(over.max(initial=0.0))
    tol = max(1e-6 * max(r.delta_max, 1e-9), 1e-12) * 10.0
    if worst > tol:
        i = int(over.argmax())
        return f"tip {worst:.3g} m below its deepest dent with zero force at t = {h.t[i]:.6g} s"
    return ""


def dump(
    args: argparse.Namespace,
    n: int,
    wall: float,
    counts: collections.Counter[str],
    statuses: collections.Counter[str],
    flags: collections.Counter[str],
    slowest: tuple[float, dict[str, Any]],
    found: list[dict[str, Any]],
) -> dict[str, Any]:
    """Write the summary so far to ``args.out``; returns it."""
    summary = {
        "drops": n,
        "wall_s": wall,
        "ms_per_drop": 1e3 * wall / max(n, 1),
        "seed": args.seed,
        "counts": dict(counts),
        "statuses": dict(statuses),
        "flags": dict(flags),
        "slowest_s": slowest[0],
        "slowest_case": slowest[1],
        "anomalies": [a for a in found if not a["what"].startswith("(failed")][:200],
        "failures": [a for a in found if a["what"].startswith("(failed")][:60],
        "cpu": os.cpu_count(),
        "python": sys.version.split()[0],
    }
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(json.dumps(summary, indent=1, default=str) + "\n")
    return summary


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=100_000, help="number of drops (at most)")
    ap.add_argument("--seconds", type=float, default=600.0, help="wall-time budget [s]")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--history", type=float, default=0.02, help="share of drops with history")
    ap.add_argument("--out", type=Path, default=ROOT / "results" / "flexible_fuzz.json")
    args = ap.parse_args()
    numba.set_num_threads(1)
    rng = np.random.default_rng(args.seed)
    simulate_drop(FlexibleRod.paper(), angle=0.35, velocity=(0.0, -1.41))  # compile / load
    counts: collections.Counter[str] = collections.Counter()
    statuses: collections.Counter[str] = collections.Counter()
    flags: collections.Counter[str] = collections.Counter()
    found: list[dict[str, Any]] = []
    t0 = time.perf_counter()
    slowest = (0.0, {})
    n = 0
    last_dump = t0
    while n < args.n and time.perf_counter() - t0 < args.seconds:
        if time.perf_counter() - last_dump > 60.0:  # partial results, in case it is stopped
            last_dump = time.perf_counter()
            dump(args, n, last_dump - t0, counts, statuses, flags, slowest, found)
        case = random_case(rng)
        history = bool(rng.random() < args.history)
        n += 1
        t1 = time.perf_counter()
        try:
            r = run_case(case, history)
        except DropError as exc:
            counts["drop_error"] += 1
            key = F.STATUS_MESSAGES.get(exc.status, str(exc.status))
            statuses[key] += 1
            if statuses[key] <= 3:  # a few inputs that reproduce each failure
                found.append({"case": case, "what": f"(failed, not an anomaly) {exc}"})
            if exc.status == F.ST_MISSED_CONTACT:
                counts["missed_contact_refused"] += 1
            continue
        except ValueError as exc:
            counts["refused_input"] += 1
            statuses[str(exc).split(":")[0][:60]] += 1
            continue
        except Exception as exc:  # an anomaly to report
            counts["exception"] += 1
            found.append({"case": case, "what": f"{type(exc).__name__}: {exc}",
                          "trace": traceback.format_exc(limit=3)})  # fmt: skip
            continue
        finally:
            dt = time.perf_counter() - t1
            if dt > slowest[0]:
                slowest = (dt, case)
        counts["result"] += 1
        for flag in ResultFlag:
            if flag and flag in r.flags:
                flags[flag.name or str(int(flag))] += 1
        if not r.ok:
            counts["flagged"] += 1
        bad = anomalies(r)
        if bad:
            counts["anomaly"] += 1
            found.append({"case": case, "what": "; ".join(bad)})
    summary = dump(args, n, time.perf_counter() - t0, counts, statuses, flags, slowest, found)
    print(json.dumps({k: v for k, v in summary.items() if k != "anomalies"}, indent=1,
                     default=str))  # fmt: skip
    for a in found[:40]:
        print("ANOMALY" if not a["what"].startswith("(failed") else "FAILED", a["what"], a["case"])


if __name__ == "__main__":
    main()
