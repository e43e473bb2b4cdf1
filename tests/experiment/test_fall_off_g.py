"""A time base a few percent off: the free fall before the impact passes the refusal (10 % of g)
but lies many sigma from g. examples/data/drop.csv with its times 4 % long gave a fall of
9.148 m/s^2 (11 sigma below g) and mu -4.5 sigma off, and the only doubt blamed the marker
geometry. The fall now marks the result not ok, naming the frame rate and the length unit, and
the geometry's doubt names them too."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, measure_impact, read_markers
from impactlab.experiment.kinematics.gravity import FALL_DOUBT, GRAVITY_SIGMAS, LOCAL_G

DATA = Path(__file__).resolve().parents[2] / "examples" / "data"
GEOMETRY = MarkerGeometry.from_mapping(
    {"units": "mm", "M1": [-30.0, 18.0, 0.0], "M2": [-90.0, 0.0, 22.0], "M3": [-130.0, -20.0, 4.0]}
)


@pytest.fixture(scope="module")
def tracks() -> object:
    return read_markers(DATA / "drop.csv")


def _fall_doubts(k: object) -> list[str]:
    return [d for d in k.doubts if d.startswith(FALL_DOUBT)]  # type: ignore[attr-defined]


def test_the_example_is_not_in_doubt(tracks: object) -> None:
    k = measure_impact(tracks, PAPER_ROD, geometry=GEOMETRY, up="+y")
    assert k.ok and not _fall_doubts(k), k.doubts
    assert abs(k.fitted_gravity - k.gravity) < LOCAL_G * k.gravity + GRAVITY_SIGMAS * 0.1


@pytest.mark.parametrize("stretch", [1.04, 1.03, 0.97])
def test_a_frame_rate_a_few_percent_off_is_a_doubt(tracks: object, stretch: float) -> None:
    off = dataclasses.replace(tracks, time=tracks.time * stretch)  # type: ignore[attr-defined]
    k = measure_impact(off, PAPER_ROD, geometry=GEOMETRY, up="+y")
    assert not k.ok
    (doubt,) = _fall_doubts(k)
    assert "frame rate" in doubt and "length unit" in doubt and doubt in k.warnings
    rate = float(doubt.split("frame rate were ")[1].split(" times")[0])
    assert rate == pytest.approx(stretch, rel=0.01)
    for other in k.doubts:
        if other.startswith("the marker geometry is in doubt"):
            assert "the frame rate" in other and "the length unit" in other, other
