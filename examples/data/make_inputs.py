"""Write the example inputs of this folder that the package makes (README.md says what each is).

* ``drops.csv``: five drops of the paper's rod on its flat (AISI 201 on AISI 1010), simulated
  with the Ghaednia law and Coulomb friction at a flat yield strength of 305 MPa and mu = 0.2,
  plus Gaussian noise of each value's stated uncertainty (``impactlab.calibrate.synthetic``);
* ``drop.csv``, ``dent.npy``, ``markers.toml``: the paper's 20 deg drop (e = 0.5, mu = 0.2,
  v = -1.41 m/s; a 22 um deep dent with L_s = 1400 um) as another lab's plain files: marker
  tracks in millimetres from a capture system with +y up, a height map in micrometres (float32)
  with 12 um pixels, and the markers' places on the rod (``impactlab.testing``).

``measurements.toml`` is written by hand (the paper's published values). Run from anywhere::

    python examples/data/make_inputs.py

The noise is seeded: the files come out the same each time.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.calibrate import CandidateModel, Measurements, parse_parameter
from impactlab.calibrate.synthetic import synthetic_measurements
from impactlab.experiment import write_csv_markers

HERE = Path(__file__).resolve().parent

#: (label, angle [deg], vy [m/s]): the paper's three drops' kinematics and two more
DROPS = (
    ("d20", 20, -1.41),
    ("d45", 45, -2.18),
    ("d70", 70, -3.45),
    ("d30", 30, -1.8),
    ("d60", 60, -1.8),
)
#: the standard uncertainty of each measured value [SI]
SIGMAS = {"e": 0.02, "spin_out": 0.3, "delta_p": 3e-6, "scar_length": 5e-6}
#: the parameters the drops were made with [SI], and their priors in docs/calibrate.md
TRUTH = {"flat_yield_strength": 305e6, "mu": 0.2}
PRIORS = {"flat_yield_strength": "uniform(100 MPa, 1 GPa)", "mu": "uniform(0, 0.6)"}
#: (column header, factor from SI, decimals) of each measured value in drops.csv
COLUMNS = {
    "e": ("e", 1.0, 3),
    "spin_out": ("spin_out [rad/s]", 1.0, 2),
    "delta_p": ("delta_p [um]", 1e6, 1),
    "scar_length": ("scar_length [um]", 1e6, 1),
}
PIXEL = 12e-6  # [m], the scan's pixel size (the docs' --pixel-size "12 um")


def write_drops(path: Path) -> None:
    """drops.csv: the simulated drops with noise, in display units."""
    template = Measurements.from_records(
        [
            {"label": label, "angle": f"{angle} deg", "vy": vy}
            | {q: 0.5 if q == "e" else 1e-6 for q in SIGMAS}  # placeholders
            | {f"{q}_sigma": s for q, s in SIGMAS.items()}
            for label, angle, vy in DROPS
        ]
    )
    params = [parse_parameter(k, PRIORS[k]) for k in TRUTH]
    data = synthetic_measurements(
        template, CandidateModel(), params, list(TRUTH.values()), np.random.default_rng(0)
    )
    header = ["label", "angle [deg]", "vy [m/s]"]
    for q, (name, _, _) in COLUMNS.items():
        header += [name, f"{q}_sigma"]
    lines = [
        "# Synthetic drops of the paper's rod on AISI 1010, made by impactlab (ghaednia law,",
        "# Coulomb friction, flat_yield_strength = 305 MPa, mu = 0.2) with Gaussian noise of each",
        "# value's _sigma; examples/data/make_inputs.py writes this file.",
        ",".join(header),
    ]
    for d, (label, angle, vy) in enumerate(DROPS):
        row = [label, str(angle), f"{vy:g}"]
        for q, (_, fac, dec) in COLUMNS.items():
            row += [f"{data.observed[q][d] * fac:.{dec}f}", f"{SIGMAS[q] * fac:g}"]
        lines.append(",".join(row))
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")


def write_plain_drop(folder: Path) -> None:
    """drop.csv (markers, mm, +y up), dent.npy (heights in um, float32) and markers.toml."""
    truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(20.0), (0.0, -1.41), e=0.5, mu=0.2)
    tracks, info = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, up="+y", seed=3)
    write_csv_markers(tracks, folder / "drop.csv", units="mm")
    z, _, _, _ = S.synthetic_scan(
        delta_p=22e-6, sliding_length=1400e-6, pixel=PIXEL, margin=0.3e-3, direction=0.0, seed=4
    )
    np.save(folder / "dent.npy", (z * 1e6).astype(np.float32))
    rows = "\n".join(
        f"{label} = [{x * 1e3:.1f}, {y * 1e3:.1f}, {w * 1e3:.1f}]"
        for label, (x, y, w) in zip(info["labels"], S.DEFAULT_MARKERS, strict=True)
    )
    (folder / "markers.toml").write_text(f'[markers]\nunits = "mm"\n{rows}\n', encoding="utf-8")


def main() -> None:
    write_drops(HERE / "drops.csv")
    write_plain_drop(HERE)
    print(f"wrote drops.csv, drop.csv, dent.npy and markers.toml into {HERE}")


if __name__ == "__main__":
    main()
