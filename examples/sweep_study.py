"""A small parameter sweep into a Zarr store, resumed, then drawn as a regime map.

What it shows:

* ``impactlab.sweep.Study``: a grid over the impact angle and the friction coefficient for the
  paper's rod dropped at 1.41 m/s (Ghaednia law, Coulomb friction);
* ``run_sweep``: the cases computed chunk by chunk into a resumable Zarr store, opened as a lazy
  ``xarray.Dataset`` with named dimensions and units; running it again computes nothing;
* ``plot_regime_map``: slip / stick over (angle, mu) with the rigid-body boundary
  mu_c(theta) = a b / (k^2 + b^2) drawn on top, and the sweep's own boundary compared with it
  over the ok cases alone (status 0, no flag but the advisory ``ADVISORY_FLAGS``);
* ``export_netcdf``: the same data as one NetCDF file.

Run (the store and the figures go into the output folder: the first argument, else
$IMPACTLAB_EXAMPLE_OUT, else a new temporary folder)::

    python examples/sweep_study.py [OUT_DIR]

A finer study of the same map from the shell (81 x 61 cases, mu 0-0.6; a study of its own, so
in a store of its own): ``impactlab sweep examples/study-regime-map.toml --out
OUT_DIR/regime-map-fine.zarr --plot OUT_DIR/plots-fine``. Tutorial: docs/tutorials/sweep.md.
"""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD
from impactlab.flags import ADVISORY_FLAGS
from impactlab.sweep import Study, export_netcdf, plot_regime_map, run_sweep


def output_dir() -> Path:
    """argv[1], else $IMPACTLAB_EXAMPLE_OUT, else a fresh temporary folder."""
    if {"-h", "--help"} & set(sys.argv[1:]):  # how to run it: the docstring
        print(__doc__)
        raise SystemExit(0)
    target = sys.argv[1] if len(sys.argv) > 1 else os.environ.get("IMPACTLAB_EXAMPLE_OUT")
    out = Path(target) if target else Path(tempfile.mkdtemp(prefix="impactlab-sweep-"))
    out.mkdir(parents=True, exist_ok=True)
    return out


def main() -> None:
    out = output_dir()
    study = Study(
        name="regime-map",
        grid={
            "angle": np.radians(np.linspace(5.0, 85.0, 33)),  # SI in Python: radians
            "mu": np.linspace(0.0, 0.8, 33),
        },
        fixed={"vy": -1.41, "law": "ghaednia", "friction": "coulomb"},
        outputs=["e", "delta_p", "sliding_length", "duration", "regime"],
        chunk_size=256,
    )
    store = out / "regime-map.zarr"
    result = run_sweep(study, store, quiet=True)
    ds = result.dataset
    s = result.stats
    print(
        f"sweep: {s.cases_computed} cases in {s.chunks_computed} chunks, "
        f"{s.wall_s:.2f} s ({s.backend}, {s.workers} workers) -> {store.name}"
    )
    print(f"dimensions: {dict(ds.sizes)}; outputs: {', '.join(ds.attrs['outputs'])}")

    # a second run finds every chunk done and computes nothing
    again = run_sweep(study, store, quiet=True)
    print(
        f"resume: {again.stats.chunks_before} chunks already done, "
        f"{again.stats.chunks_computed} computed"
    )

    # the regime boundary of the sweep against the rigid-body mu_c(theta), over the ok cases:
    # computed (status 0) and no flag but the advisory ones (law extrapolated), as
    # BatchResult.ok reads them; "flags > 0" would be every case (each is law-extrapolated)
    names = {int(k): v for k, v in ds["regime"].attrs["regimes"].items()}
    stick = next(code for code, name in names.items() if name == "stick")
    regime = ds["regime"].transpose("angle", "mu").values
    flags = ds["flags"].transpose("angle", "mu").values.astype(np.int64)
    ok = (ds["status"].transpose("angle", "mu").values == 0) & ((flags & ~ADVISORY_FLAGS) == 0)
    print(f"not ok: {int(np.count_nonzero(~ok))} of {ok.size} cases, left out below")
    mu = ds["mu"].values
    partly = False  # an angle printed with some of its cases not ok
    print(f"\n{'angle [deg]':>11s} {'first stick mu':>15s} {'mu_c rigid':>11s}")
    for i, th in enumerate(ds["angle"].values):
        if i % 4:
            continue
        sticking = np.flatnonzero((regime[i] == stick) & ok[i])
        if not ok[i].any():  # e.g. 5 deg: the flat passes the rim of the tip (beyond the tip)
            first = f"all {ok[i].size} not ok"
        else:
            first = f"{mu[sticking[0]]:.3f}" if sticking.size else "-"
            partly |= not ok[i].all()
            first += "" if ok[i].all() else " *"
        print(
            f"{np.degrees(th):11.1f} {first:>15s} {float(critical_friction(th, PAPER_ROD)):11.3f}"
        )
    if partly:
        print("(*: some cases of the angle not ok, left out)")

    e20 = float(ds["e"].sel(angle=np.radians(20.0), mu=0.2, method="nearest"))
    print(f"\ne at 20 deg, mu = 0.2: {e20:.4f}")

    ax = plot_regime_map(ds)
    path = out / "regime_map.png"
    ax.figure.savefig(path, dpi=110)
    plt.close(ax.figure)
    nc = export_netcdf(ds, out / "regime-map.nc")
    print(f"saved {path.name}, {nc.name}")


if __name__ == "__main__":
    main()
