"""Shared synthetic experiments for the experiment-pipeline tests (real C3D and scan files).

The drops come from the impact engine (finite contact duration, ``impactlab.testing``); the
dents from the analytic groove of ``impactlab.testing.groove_surface``.
"""

from __future__ import annotations

import math
import os
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import pytest

os.environ.setdefault("MPLBACKEND", "Agg")

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry
from impactlab.materials import AISI_1010

#: The paper's three drops (Sec. 5.1.3): angle [deg], v_i [m/s], e, mu, delta_p [m], L_s [m].
CASES = {
    20: (20.0, -1.41, 0.50, 0.20, 22e-6, 1400e-6),
    45: (45.0, -2.18, 0.49, 0.13, 26e-6, 1650e-6),
    70: (70.0, -3.45, 0.05, 0.10, 105e-6, 200e-6),
}

#: A marker geometry file (body frame, mm) of the synthetic drops' three markers.
GEOMETRY_TOML = """
[markers]
units = "mm"
M1 = [-30.0, 18.0, 0.0]
M2 = [-90.0, 0.0, 22.0]
M3 = [-130.0, -20.0, 4.0]
"""

#: Realistic noise: 0.15 mm per marker coordinate, 0.1 um on the scan heights.
MARKER_NOISE = 0.15e-3
SCAN_NOISE = 0.1e-6


@dataclass(frozen=True)
class Drop:
    angle_deg: float
    truth: S.ImpactTruth
    info: dict[str, Any]
    c3d: Path
    geometry: MarkerGeometry


@dataclass(frozen=True)
class Scan:
    truth: S.ScanTruth
    z: np.ndarray
    dx: float
    files: dict[str, Path]


def impact_truth(angle_deg: float, v_i: float, e: float, mu: float) -> S.ImpactTruth:
    """The impact engine's result (ghaednia law, Coulomb friction, AISI 1010 flat; finite contact
    duration; ``e`` is the engine's, not the paper's)."""
    return S.engine_impact(PAPER_ROD, AISI_1010, math.radians(angle_deg), (0.0, v_i), mu=mu)


@pytest.fixture(scope="session")
def rod() -> Any:
    return PAPER_ROD


@pytest.fixture(scope="session")
def data_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("experiment_data")


@pytest.fixture(scope="session")
def drops(data_dir: Path) -> dict[int, Drop]:
    """One drop per paper case, written as a real C3D file (mm, 500 fps, noise, occlusions)."""
    out: dict[int, Drop] = {}
    for key, (ang, vi, e, mu, _, _) in CASES.items():
        tr = impact_truth(ang, vi, e, mu)
        tracks, info = S.marker_tracks(PAPER_ROD, tr, noise=MARKER_NOISE, seed=key)
        path = S.write_c3d(tracks, data_dir / f"drop_{key}.c3d")
        out[key] = Drop(ang, tr, info, path, MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    return out


@pytest.fixture(scope="session")
def scans(data_dir: Path) -> dict[int, Scan]:
    """One dent per paper case (delta_p, L_s of Sec. 5.1.3), tilted, noisy, with dropouts, in
    X3P, Gwyddion and ISO 25178-71 SDF."""
    out: dict[int, Scan] = {}
    for key, (*_, dp, ls) in CASES.items():
        z, dx, _, truth = S.synthetic_scan(
            delta_p=dp, sliding_length=ls, noise=SCAN_NOISE, seed=key
        )
        files = {}
        for fmt, ext in (("x3p", "x3p"), ("gwy", "gwy"), ("sdf", "sdf")):
            files[fmt] = S.write_scan(z, dx, dx, data_dir / f"dent_{key}.{ext}", fmt=fmt)
        out[key] = Scan(truth, z, dx, files)
    return out


@pytest.fixture(scope="session")
def analysed_drop(
    tmp_path_factory: pytest.TempPathFactory, drops: dict[int, Drop], scans: dict[int, Scan]
) -> Callable[[int], tuple[Any, Path]]:
    """``analysed_drop(case)``: ``analyze`` of the case's drop and its X3P dent (the paper's rod,
    the markers' geometry, 2000 Monte Carlo samples) into a new output folder, run once per case:
    (result, folder). Read-only: tests that write in the folder work on a copy of it."""
    from impactlab.experiment import analyze

    done: dict[int, tuple[Any, Path]] = {}

    def get(case: int) -> tuple[Any, Path]:
        if case not in done:
            d, sc = drops[case], scans[case]
            out = tmp_path_factory.mktemp(f"analysed_{case}") / "out"
            res = analyze(
                d.c3d, sc.files["x3p"], PAPER_ROD, geometry=d.geometry, out_dir=out, n_samples=2000
            )
            done[case] = (res, out)
        return done[case]

    return get


@pytest.fixture(scope="session")
def junk(data_dir: Path) -> dict[str, Path]:
    """Files that exist but cannot be read ("c3d": markers, "x3p": a scan): their stage fails
    and the others go on (a path that names no file is refused before any work instead)."""
    out = {}
    for ext in ("c3d", "x3p"):
        path = data_dir / f"junk.{ext}"
        path.write_bytes(b"not a measurement\n" * 8)
        out[ext] = path
    return out


#: The example data of the docs (examples/data): a drop, its dent and the marker geometry.
EXAMPLE_DATA = Path(__file__).resolve().parents[2] / "examples" / "data"


def analyse_example(**kwargs: Any) -> Any:
    """``analyze`` of the docs' example drop and dent (12 um pixels, heights in um, +y up), with
    ``kwargs`` on top."""
    import tomllib

    from impactlab.experiment import analyze

    table = tomllib.loads((EXAMPLE_DATA / "markers.toml").read_text())["markers"]
    return analyze(
        EXAMPLE_DATA / "drop.csv",
        EXAMPLE_DATA / "dent.npy",
        pixel_size=12e-6,
        height_unit="um",
        up="+y",
        geometry=MarkerGeometry.from_mapping(table),
        **kwargs,
    )


@pytest.fixture(scope="session")
def analysed_example() -> Any:
    """:func:`analyse_example` with the defaults."""
    return analyse_example()


@pytest.fixture(scope="session")
def saved_example(tmp_path_factory: pytest.TempPathFactory) -> Any:
    """:func:`analyse_example` with the defaults and an output folder (both figures and
    results.json written)."""
    return analyse_example(out_dir=tmp_path_factory.mktemp("example") / "out")


@pytest.fixture(scope="session")
def flat_json(
    tmp_path_factory: pytest.TempPathFactory, drops: dict[int, Drop], scans: dict[int, Scan]
) -> tuple[list[str], Any]:
    """``impactlab analyze`` of the 45 deg drop and its SDF dent with the marker geometry file:
    (its arguments, the run of those with ``--flat aisi-1010 --json``, a typer ``Result``)."""
    from typer.testing import CliRunner

    from impactlab.cli import app

    geo = tmp_path_factory.mktemp("flat_json") / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    args = ["analyze", str(drops[45].c3d), str(scans[45].files["sdf"]), "--geometry", str(geo)]
    return args, CliRunner().invoke(app, [*args, "--flat", "aisi-1010", "--json"])
