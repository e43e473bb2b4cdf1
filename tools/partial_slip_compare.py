#!/usr/bin/env python3
"""Outputs of ``friction="partial_slip"`` over a spread of impacts, and the largest relative
change between two such runs (a change of the partial-slip method stays within the tolerance).

    python tools/partial_slip_compare.py OUT.npz                     # write the outputs
    python tools/partial_slip_compare.py OUT.npz --compare BEFORE.npz

The spread: the rod (``Rod.paper()``) at 5 ... 85 deg and a 10 mm sphere at 0.5 ... 5 m/s and
incidence 2 ... 85 deg, each with the hertz, ghaednia and thornton laws and mu 0.1, 0.3, 0.6
(``simulate_batch``, each model's default tolerance). The change of each output is
|after - before| / max(|before|, floor), the floor 1e-3 of the output's largest magnitude over
the spread (an output that passes through zero has no relative change there).
"""

from __future__ import annotations

import argparse
import sys

import numpy as np

import impactlab as il
from impactlab.materials import AISI_1010

FIELDS = (
    "e", "delta_p", "vx_out", "spin_out", "vt_out", "tangential_impulse", "sliding_length",
    "duration", "energy_dissipated", "stick_time", "max_force", "n_steps",
)  # fmt: skip
LAWS = ("hertz", "ghaednia", "thornton")
MUS = (0.1, 0.3, 0.6)


def run(rtol: float | None) -> dict[str, np.ndarray]:
    out: dict[str, list[np.ndarray]] = {f: [] for f in FIELDS}
    status = []
    rod = il.Rod.paper()
    sphere = il.Sphere(radius=0.01)
    ang = np.radians(np.linspace(5.0, 85.0, 9))
    speed, inc = np.meshgrid([0.5, 2.0, 5.0], np.radians([2.0, 10.0, 25.0, 45.0, 65.0, 85.0]))
    for law in LAWS:
        for mu in MUS:
            kw = {"law": law, "friction": "partial_slip", "mu": mu, "rtol": rtol}
            batches = [
                il.simulate_batch(rod, AISI_1010, angle=ang, vy=-1.41, **kw),  # type: ignore[arg-type]
                il.simulate_batch(
                    sphere,
                    AISI_1010,
                    speed=speed.ravel(),
                    incidence=inc.ravel(),
                    **kw,  # type: ignore[arg-type]
                ),
            ]
            for b in batches:
                status.append(np.asarray(b.status))
                for f in FIELDS:
                    out[f].append(np.asarray(b[f], dtype=float))
    res = {f: np.concatenate(v) for f, v in out.items()}
    res["status"] = np.concatenate(status)
    return res


def compare(new: dict[str, np.ndarray], old: dict[str, np.ndarray]) -> float:
    """Print the largest relative change of each output; return the largest over the outputs
    other than ``n_steps``."""
    if not np.array_equal(new["status"], old["status"]):
        print("status differs:", np.flatnonzero(new["status"] != old["status"]))
    worst = 0.0
    for f in FIELDS:
        a, b = new[f], old[f]
        floor = 1e-3 * np.nanmax(np.abs(b))
        rel = np.abs(a - b) / np.maximum(np.abs(b), floor)
        i = int(np.nanargmax(rel))
        if f == "n_steps":
            nb, na = np.nansum(b), np.nansum(a)
            print(f"{f:20s} total {nb:.0f} -> {na:.0f} ({na / nb:.3f})")
            continue
        print(f"{f:20s} max rel change {rel[i]:.2e} (case {i}: {b[i]:.6g} -> {a[i]:.6g})")
        worst = max(worst, float(rel[i]))
    return worst


def main(argv: list[str]) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("out")
    ap.add_argument("--compare", default=None)
    ap.add_argument("--rtol", type=float, default=None, help="the engine's tolerance")
    args = ap.parse_args(argv)
    res = run(args.rtol)
    np.savez(args.out, **res)
    print(f"{len(res['e'])} impacts, {int(np.sum(res['status'] != 0))} not ok -> {args.out}")
    if args.compare:
        old = dict(np.load(args.compare))
        print(f"largest relative change: {compare(res, old):.2e}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
