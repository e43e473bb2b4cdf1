"""A given marker geometry that breaks the rigid-body impulse relation, with no mirror image to
explain it (C or the rod's axis misplaced in it, or an inertia that is off), marks the result
not ok; the correct geometry of the example does not."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, measure_impact, read_markers

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
#: The example's marker geometry (body frame, mm).
MARKERS = np.array([[-30.0, 18.0, 0.0], [-90.0, 0.0, 22.0], [-130.0, -20.0, 4.0]])

CliMain = Callable[..., tuple[int, str, str]]


def _geometry(markers: np.ndarray) -> MarkerGeometry:
    rows = {f"M{i + 1}": list(m) for i, m in enumerate(markers)}
    return MarkerGeometry.from_mapping({"units": "mm", **rows})


def _turned(degrees: float) -> np.ndarray:
    c, s = math.cos(math.radians(degrees)), math.sin(math.radians(degrees))
    return MARKERS @ np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])


@pytest.fixture(scope="module")
def tracks() -> object:
    return read_markers(DATA / "drop.csv")


def test_the_true_geometry_is_ok(tracks: object) -> None:
    k = measure_impact(tracks, PAPER_ROD, geometry=_geometry(MARKERS), up="+y")
    assert k.ok and not any("geometry is in doubt" in w for w in k.warnings)


@pytest.mark.parametrize(
    ("markers", "what"),
    [
        (MARKERS - [5.0, 0.0, 0.0], "5 mm along the rod"),
        (MARKERS - [10.0, 0.0, 0.0], "10 mm along the rod"),
        (_turned(10.0), "turned 10 deg"),
    ],
)
def test_a_misplaced_geometry_is_a_doubt(tracks: object, markers: np.ndarray, what: str) -> None:
    """Shifted 5 mm along the rod it read e = 0.5377 and mu = 0.1721 (5 and 6 sigma off the
    true 0.50 and 0.20) with ok True and no warning."""
    k = measure_impact(tracks, PAPER_ROD, geometry=_geometry(markers), up="+y")
    assert not k.ok, what
    (doubt,) = k.doubts
    assert doubt.startswith("the marker geometry is in doubt: ") and doubt in k.warnings
    assert "break the rigid-body impulse relation" in doubt
    assert "C or the rod's axis is misplaced in the geometry" in doubt
    assert "k^2 = I/m is off by more than 5 %" in doubt


def test_the_command_line_refuses_to_append_it(tmp_path: Path, cli_main: CliMain) -> None:
    geo = tmp_path / "shifted.toml"
    rows = "\n".join(f"M{i + 1} = [{x}, {y}, {z}]" for i, (x, y, z) in enumerate(MARKERS - 5.0))
    geo.write_text(f'[markers]\nunits = "mm"\n{rows}\n')
    args = ("analyze", str(DATA / "drop.csv"), str(DATA / "dent.npy"), "--pixel-size", "12 um",
            "--height-unit", "um", "--up", "+y", "--geometry", str(geo))  # fmt: skip
    code, out, _ = cli_main(*args, "--json")
    data = json.loads(out)
    assert code == 0 and data["ok"] is False
    assert any(d.startswith("the marker geometry is in doubt") for d in data["doubts"])
    path = tmp_path / "drops.csv"
    code, _, err = cli_main(*args, "--measurements", str(path))
    assert code == 2 and "--measurements: nothing appended" in err and not path.exists()
