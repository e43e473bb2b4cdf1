"""Simulate the paper's 20 deg drop with two contact laws and three of the four friction models.

What it shows:

* the paper's rod (``Rod.paper()``: R = 8.8 mm, L = 0.3048 m, m = 0.4607 kg, AISI 201) dropped
  on an AISI 1010 flat at 20 deg with v = 1.41 m/s and mu = 0.2 (the paper's Sec. 5.1.3);
* ``impactlab.dynamics.simulate`` with the ``ghaednia`` and ``brake`` laws and the
  ``impulse_ratio`` (the paper's Eq. 7), ``coulomb`` and ``mindlin`` friction models;
* the result's e, delta_p, L_s, T, F and regime, the force history and the predicted dent;
* a force-time plot (``force_time.png``).

Run (the output folder is the first argument, else $IMPACTLAB_EXAMPLE_OUT, else a new
temporary folder; nothing is written anywhere else)::

    python examples/simulate_impact.py [OUT_DIR]

Tutorial: docs/tutorials/simulate.md.
"""

from __future__ import annotations

import math
import os
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

from impactlab.bodies import Rod
from impactlab.dynamics import simulate
from impactlab.materials import AISI_1010

LAWS = ("ghaednia", "brake")
FRICTIONS = ("impulse_ratio", "coulomb", "mindlin")


def output_dir() -> Path:
    """argv[1], else $IMPACTLAB_EXAMPLE_OUT, else a fresh temporary folder."""
    if {"-h", "--help"} & set(sys.argv[1:]):  # how to run it: the docstring
        print(__doc__)
        raise SystemExit(0)
    target = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("IMPACTLAB_EXAMPLE_OUT")
    out = Path(target) if target else Path(tempfile.mkdtemp(prefix="impactlab-simulate-"))
    out.mkdir(parents=True, exist_ok=True)
    return out


def main() -> None:
    out = output_dir()
    rod = Rod.paper()
    angle = math.radians(20.0)  # the library takes radians
    velocity = (0.0, -1.41)  # (vx, vy) of the centre of mass at first touch [m/s]

    print(
        f"{'law':10s} {'friction':14s} {'regime':8s} {'e':>6s} {'delta_p':>9s} {'L_s':>9s} "
        f"{'T':>8s} {'F':>8s}"
    )
    print(f"{'':10s} {'':14s} {'':8s} {'':>6s} {'[um]':>9s} {'[um]':>9s} {'[ms]':>8s} {'[N]':>8s}")
    results = {}
    for law in LAWS:
        for friction in FRICTIONS:
            r = simulate(
                rod, AISI_1010, law=law, friction=friction, mu=0.2, angle=angle, velocity=velocity
            )
            results[law, friction] = r
            print(
                f"{law:10s} {friction:14s} {r.regime:8s} {r.e:6.3f} {r.delta_p * 1e6:9.2f} "
                f"{r.sliding_length * 1e6:9.2f} {r.duration * 1e3:8.4f} "
                f"{r.mean_force:8.1f}"
            )

    # one result in full: every field, with units
    best = results["ghaednia", "coulomb"]
    print()
    print(best)

    # the predicted permanent dent (height map) of that impact
    dent = best.dent()
    print(
        f"\ndent: depth {dent.max_depth * 1e6:.2f} um, length {dent.length * 1e6:.1f} um, "
        f"width {dent.width * 1e6:.1f} um"
    )

    # force-time plot of the Coulomb runs
    fig, ax = plt.subplots(figsize=(6.4, 4.0), constrained_layout=True)
    for i, law in enumerate(LAWS):
        h = results[law, "coulomb"].history
        assert h is not None  # history=True is the default
        ax.plot(h.t * 1e3, h.normal_force, color=f"C{i}", label=f"{law}: normal force")
        ax.plot(
            h.t * 1e3, h.tangential_force, "--", color=f"C{i}", label=f"{law}: tangential force"
        )
    ax.set_xlabel("time [ms]")
    ax.set_ylabel("force [N]")
    ax.set_title("Paper's rod, 20 deg, 1.41 m/s, Coulomb friction mu = 0.2")
    ax.legend(fontsize=8)
    path = out / "force_time.png"
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(
        f"\nghaednia/coulomb: e = {best.e:.4f}, delta_p = {best.delta_p * 1e6:.2f} um, "
        f"T = {best.duration * 1e3:.4f} ms, F = {best.mean_force:.1f} N"
    )
    print(f"saved {path}")


if __name__ == "__main__":
    main()
