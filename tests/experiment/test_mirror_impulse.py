"""A mirrored three-marker geometry whose e stays within [0, 1] is found by the rigid-body
impulse relations (the spin change against the centre of mass's velocity change, and the spin
change perpendicular to the rod); an e below 0 by more than 2 sigma draws a warning; clean drops
raise nothing new."""

from __future__ import annotations

import dataclasses
import math
import re
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import MarkerError, MarkerGeometry, measure_impact
from impactlab.experiment.kinematics.impulse import gyration_squared, impulse_check
from impactlab.experiment.kinematics.mirror import checked_against_mirror
from impactlab.experiment.uncertainty import Estimate

#: Flipping the third body coordinate mirrors a geometry and keeps the rod's axis and C.
MIRROR = np.diag([1.0, 1.0, -1.0])
#: The words of the new checks' messages, none of which a clean drop may show.
NEW_WORDS = ("impulse relations", "off the perpendicular", "sigma below 0", "sigma above 1")


def _drop(rod: Any, angle: float, e: float, *, seed: int = 1, **kw: Any) -> tuple[Any, Any]:
    """(tracks, info) of an impulse-model drop at ``angle`` deg with restitution ``e``."""
    v = -1.41 if angle < 40 else -2.5
    truth = S.rigid_impulse_impact(rod, math.radians(angle), (0.0, v), e=e, mu=0.15)
    return S.marker_tracks(rod, truth, seed=seed, **kw)


def _geometry(info: dict[str, Any], reflect: bool = False) -> MarkerGeometry:
    markers = info["markers_body"] @ MIRROR if reflect else info["markers_body"]
    return MarkerGeometry(markers, info["labels"])


@pytest.mark.parametrize(("angle", "e"), [(80.0, 0.5), (80.0, 0.8), (80.0, 0.3), (10.0, 0.8)])
def test_a_mirrored_geometry_with_e_inside_zero_one_is_named(
    rod: Any, angle: float, e: float
) -> None:
    """At 80 deg the mirror gave e = 0.317 for 0.5 and an angle of 58 deg as a normal result;
    at 10 deg e = 0.16 and mu = 1.18 for e = 0.8 and mu = 0.15."""
    tracks, info = _drop(rod, angle, e)
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod, geometry=_geometry(info, reflect=True))
    message = str(caught.value)
    assert "break the rigid-body impulse relations" in message
    good = re.search(r"they hold: .*; e = ([0-9.]+) ± [0-9.e-]+, angle ([0-9.]+) deg", message)
    assert good is not None
    assert abs(float(good.group(1)) - e) < 0.05
    assert abs(float(good.group(2)) - angle) < 1.0
    assert "the geometry is mirrored" in message and "left-handed" in message


def test_a_turn_off_the_perpendicular_alone_is_a_warning(rod: Any) -> None:
    """At 20 deg the mirror gave e = -0.01 for 0.8 with the spin change agreeing with the
    impulse; only the turn's axis, 8 deg off the perpendicular to the rod, shows it (a rod that
    rolls about its axis would too)."""
    tracks, info = _drop(rod, 20.0, 0.8, seed=5)
    k = measure_impact(tracks, rod, geometry=_geometry(info, reflect=True))
    (note,) = [w for w in k.warnings if "off the perpendicular" in w]
    assert "the geometry may be mirrored" in note and "the rod rolled about its axis" in note
    good = re.search(r"the mirrored one gives e = ([0-9.]+) ± [0-9.e-]+ and ([0-9.]+) deg", note)
    assert good is not None and abs(float(good.group(1)) - 0.8) < 0.05
    assert abs(float(good.group(2)) - 20.0) < 1.0


def test_the_relation_holds_for_the_true_geometry(rod: Any) -> None:
    tracks, info = _drop(rod, 80.0, 0.5)
    k2 = gyration_squared(rod)
    assert k2 == pytest.approx(rod.inertia / rod.mass)
    true = impulse_check(measure_impact(tracks, rod, geometry=_geometry(info)), k2)
    assert true.consistent and true.relative < 0.03
    assert abs(true.axis_sine) < 0.05


@pytest.mark.parametrize("angle", [10.0, 15.0, 20.0, 30.0, 45.0, 60.0, 70.0, 80.0])
@pytest.mark.parametrize("e", [0.05, 0.5, 0.8])
def test_clean_drops_raise_nothing_new(rod: Any, angle: float, e: float) -> None:
    tracks, info = _drop(rod, angle, e, seed=int(angle) + int(10 * e))
    if (angle, e) == (15.0, 0.05):  # this one holds too few frames after the impact
        with pytest.raises(MarkerError, match="only 5 free-flight frames"):
            measure_impact(tracks, rod, geometry=_geometry(info))
        return
    k = measure_impact(tracks, rod, geometry=_geometry(info))
    assert not [w for w in k.warnings if any(n in w for n in NEW_WORDS)]
    assert abs(k.e.value - e) < 4 * k.e.sigma + 0.01


@pytest.mark.parametrize(("rate", "noise", "markers"), [
    (250.0, 0.2e-3, None), (1000.0, 0.05e-3, None), (500.0, 0.15e-3, "four"),
    (500.0, 0.15e-3, "five"), (500.0, 0.1e-3, "release"),
])  # fmt: skip
def test_clean_drops_at_other_rates_noises_and_marker_counts_raise_nothing_new(
    rod: Any, rate: float, noise: float, markers: str | None
) -> None:
    extra = np.array([[-0.060, -0.015, -0.012], [-0.110, 0.010, 0.015]])
    kw: dict[str, Any] = {"rate": rate, "noise": noise}
    if markers in ("four", "five"):
        kw["markers"] = np.vstack([S.DEFAULT_MARKERS, extra[: 1 if markers == "four" else 2]])
    if markers == "release":
        kw.update(release=True, before=0.3)
    for angle in (20.0, 45.0, 70.0):
        tracks, info = _drop(rod, angle, 0.5, **kw)
        k = measure_impact(tracks, rod, geometry=_geometry(info))
        assert not [w for w in k.warnings if any(n in w for n in NEW_WORDS)]
        assert abs(k.e.value - 0.5) < 4 * k.e.sigma + 0.01


def test_the_engine_drops_satisfy_the_relation(rod: Any, drops: dict[int, Any]) -> None:
    """A finite contact (the engine's) keeps the relation: its impulse acts at the tip."""
    for drop in drops.values():
        tracks = S.marker_tracks(rod, drop.truth, noise=0.15e-3, seed=7)[0]
        k = measure_impact(tracks, rod, geometry=drop.geometry)
        assert impulse_check(k, gyration_squared(rod)).consistent


def test_a_rod_without_mass_or_inertia_skips_the_relation(rod: Any) -> None:
    assert gyration_squared(object()) is None
    tracks, info = _drop(rod, 80.0, 0.5)
    k = measure_impact(tracks, rod, geometry=_geometry(info))

    def never(_: MarkerGeometry) -> Any:
        raise AssertionError("no mirrored analysis without the relation or a bad e")

    assert checked_against_mirror(k, _geometry(info), None, never, "x", lambda: MarkerError())


@pytest.mark.parametrize(
    ("value", "sigma", "warned"),
    [(-0.038, 0.016, True), (-0.02, 0.016, False), (1.04, 0.015, True), (0.3, 0.01, False)],
)
def test_an_e_outside_zero_one_by_two_to_three_sigma_is_a_warning(
    rod: Any, value: float, sigma: float, warned: bool
) -> None:
    """e = -0.038 +- 0.016 lies 2.4 sigma below 0: accepted within 3 sigma, but not silently."""
    tracks, info = _drop(rod, 20.0, 0.5)
    k = measure_impact(tracks, rod, geometry=_geometry(info))
    odd = dataclasses.replace(k, e=Estimate(value, sigma, ""))
    got = checked_against_mirror(odd, None, None, lambda g: k, "drop.csv", lambda: MarkerError())
    notes = [w for w in got.warnings if w.startswith("e = ")]
    assert bool(notes) == warned
    if warned:
        where = "below 0" if value < 0 else "above 1"
        assert f"sigma {where}" in notes[0] and "accepted as noise within 3 sigma" in notes[0]
