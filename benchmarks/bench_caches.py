"""What each module-level cache on the engine's path saves, measured in ONE run.

For every cache: the cost per call of what it serves, with the cache (a hit) and without it
(the work it saves), beside the call it serves (``simulate``'s fast path and full path, a
16-impact ``simulate_batch``), all measured here, best of several repeats (the shared
machine's speed drifts). A cache pays when it saves more than a few per cent of the call it
serves (docs/architecture.md, "Caches").

    .venv/bin/python benchmarks/bench_caches.py

Writes benchmarks/results/caches.json and prints a table.
"""

from __future__ import annotations

import json
import timeit
from collections.abc import Callable
from pathlib import Path

import numpy as np

import impactlab as il
from impactlab import units as U
from impactlab.contact import get_law
from impactlab.contact import range_note as RN
from impactlab.contact.tabulate import with_table
from impactlab.dynamics import batch as B
from impactlab.dynamics import export as E
from impactlab.dynamics import models as M
from impactlab.dynamics import outcome as O
from impactlab.flags import ResultFlag
from impactlab.friction import get_friction
from impactlab.materials import AISI_1010, ContactPair

ROOT = Path(__file__).resolve().parent
ROD, FLAT = il.Rod.paper(), AISI_1010
FAST = {"law": "ghaednia", "mu": 0.2, "angle": 0.7, "velocity": (0.0, -1.4)}
FULL = {**FAST, "angle": "40 deg"}  # text: the full path of checks
ANGLES = np.radians(np.linspace(10.0, 80.0, 16))


def best_us(fn: Callable[[], object], number: int, repeat: int = 7) -> float:
    """Best microseconds per call over ``repeat`` runs of ``number`` calls."""
    return 1e6 * min(timeit.repeat(fn, number=number, repeat=repeat)) / number


def _cleared(cache: dict, fn: Callable[[], object]) -> Callable[[], object]:
    def run() -> None:
        cache.clear()
        fn()

    return run


def measure() -> dict[str, dict[str, float]]:
    model = M.contact_model(ROD, FLAT, "ghaednia")
    fric = get_friction("coulomb")
    p = np.asarray(model.params)
    il.simulate(ROD, FLAT, **FAST)
    il.simulate(ROD, FLAT, **FULL)

    def batch() -> None:
        il.simulate_batch(ROD, FLAT, law="ghaednia", mu=0.2, angle=ANGLES, vy=-1.4)

    batch()
    calls = {
        "simulate_fast": best_us(lambda: il.simulate(ROD, FLAT, **FAST), 300),
        "simulate_full": best_us(lambda: il.simulate(ROD, FLAT, **FULL), 100),
        "simulate_batch_16": best_us(batch, 20),
    }

    def setup() -> None:
        M.engine_setup(ROD, FLAT, "ghaednia", "coulomb")

    def refs() -> None:
        M.references_used(model, fric, True)

    def law_flag() -> None:
        O._law_flag(model, 1e-5)

    def table() -> None:
        B.shared_table(model.law_id, p)

    def text() -> None:
        U.magnitude("angle", "40 deg", "rad")

    def described() -> None:
        E.batch_setup(ROD, FLAT, friction="coulomb", gravity=True, rtol=None, constant_angle=False)

    def note() -> None:
        RN.range_note(model.law_id, p)

    pair = ContactPair(ROD.material, FLAT)
    caches = {  # name: (served call, with, without)
        "models._build": (
            "simulate_full",
            best_us(lambda: M.build_contact_model("ghaednia", ROD.material, FLAT, 8.8e-3), 3000),
            best_us(lambda: get_law("ghaednia").build(pair, ROD.tip_radius), 5, 3),
        ),
        "models._PARAMS": (
            "simulate_full",
            best_us(lambda: M.kernel_params(model), 3000),
            best_us(lambda: with_table(model.law_id, p), 20, 3),
        ),
        "models._LAST_MODELS": (
            "simulate_full",
            best_us(lambda: M.contact_model(ROD, FLAT, "ghaednia"), 3000),
            best_us(_cleared(M._LAST_MODELS, lambda: M.contact_model(ROD, FLAT, "ghaednia")), 3000),
        ),
        "models._REFERENCES": (
            "simulate_full",
            best_us(refs, 3000),
            best_us(_cleared(M._REFERENCES, refs), 3000),
        ),
        "models._SETUPS": (
            "simulate_fast",
            best_us(setup, 3000),
            best_us(_cleared(M._SETUPS, setup), 500),
        ),
        "body_params (not cached)": (
            "simulate_full",
            best_us(lambda: M.body_params(ROD, FLAT), 3000),
            best_us(lambda: M.body_params(ROD, FLAT), 3000),
        ),
        "outcome._RANGES": (
            "simulate_fast",
            best_us(law_flag, 3000),
            best_us(_cleared(O._RANGES, law_flag), 3000),
        ),
        "ResultFlag(value) (not cached)": (
            "simulate_fast",
            best_us(lambda: ResultFlag(0), 20000),
            best_us(lambda: ResultFlag(0), 20000),
        ),
        "units._TEXT_VALUES": (
            "simulate_full",
            best_us(text, 3000),
            best_us(_cleared(U._TEXT_VALUES, text), 200),
        ),
        "export._DESCRIBED": (
            "simulate_batch_16",
            best_us(described, 3000),
            best_us(_cleared(E._DESCRIBED, described), 200),
        ),
        "range_note._NOTES": (
            "simulate_batch_16",
            best_us(note, 3000),
            best_us(_cleared(RN._NOTES, note), 200),
        ),
        "batch._TABLES": (
            "simulate_batch_16",
            best_us(table, 2000),
            best_us(_cleared(B._TABLES, table), 20, 3),
        ),
    }
    out: dict[str, dict[str, float]] = {"calls_us": calls}
    for name, (served, hit, miss) in caches.items():
        out[name] = {
            "serves": served,  # type: ignore[dict-item]
            "with_us": hit,
            "without_us": miss,
            "saved_share_of_call": (miss - hit) / calls[served],
        }
    return out


def main() -> None:
    res = measure()
    (ROOT / "results").mkdir(exist_ok=True)
    (ROOT / "results" / "caches.json").write_text(json.dumps(res, indent=2) + "\n")
    calls = res.pop("calls_us")
    print("calls: " + ", ".join(f"{k} {v:.1f} us" for k, v in calls.items()))
    print(f"{'cache':32s} {'serves':18s} {'with':>10s} {'without':>10s} {'saved':>8s}")
    for name, r in res.items():
        print(
            f"{name:32s} {r['serves']:18s} {r['with_us']:8.2f}us {r['without_us']:8.2f}us "
            f"{100 * r['saved_share_of_call']:7.1f}%"
        )


if __name__ == "__main__":
    main()
