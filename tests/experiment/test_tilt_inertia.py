"""An estimated geometry with the rod's true inertia 10 % off the nominal: a 20 deg drop of
markers laid out along the rod was refused as "+9.0 +- 1.1 deg tilted ... what was read is
wrong" though the angle and e were right. A rod without an inertia skipped the check and
returned ok; a result that is not ok was shown nowhere a notebook looks."""

from __future__ import annotations

import math
import types
import warnings
from pathlib import Path
from typing import Any

import pytest

from impactlab import testing as S
from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies import Rod
from impactlab.experiment import MarkerError, analyze, measure_impact, write_csv_markers
from impactlab.experiment.kinematics.tilt import TiltCheck


def _drop(rod: Any, true_rod: Any, angle: float, rate: float, markers: Any = None) -> Any:
    truth = S.rigid_impulse_impact(true_rod, math.radians(angle), velocity=(0.0, -1.41))
    markers = S.ALIGNED_MARKERS if markers is None else markers
    return S.marker_tracks(true_rod, truth, markers=markers, rate=rate, noise=0.05e-3, seed=0)[0]


def _off(rod: Any, factor: float) -> Rod:
    return Rod(length=rod.length, tip_radius=rod.tip_radius, mass=rod.mass,
               inertia=rod.inertia * factor)  # fmt: skip


@pytest.mark.parametrize(
    ("angle", "factor", "rate"),
    [(20, 1.1, 1000), (30, 1.1, 1000), (40, 1.15, 1000), (20, 0.9, 500), (30, 0.9, 500)],
)
def test_an_inertia_10_percent_off_is_not_refused(
    rod: Any, angle: float, factor: float, rate: float
) -> None:
    k = measure_impact(_drop(rod, _off(rod, factor), angle, rate), rod)
    assert abs(math.degrees(k.angle_in.value) - angle) < 0.5
    assert abs(k.e.value - 0.5) < 0.03
    for doubt in k.doubts:
        assert "k^2 = I/m" in doubt


def test_the_refusal_names_the_inertia(rod: Any) -> None:
    tracks = _drop(rod, rod, 45, 500, S.DEFAULT_MARKERS)
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod)
    message = str(caught.value)
    assert "the markers are not laid out along the rod" in message
    assert "the rod's inertia k^2 = I/m" in message and "--geometry" in message


def test_a_gross_tilt_an_inertia_10_percent_off_explains_is_not_ok() -> None:
    check = TiltCheck(math.radians(17.0), math.radians(5.6), inertia_explains=True)
    assert check.gross and check.verdict == "inertia"
    assert TiltCheck(math.radians(17.0), math.radians(5.6)).verdict == "gross"


def test_a_rod_without_inertia_is_not_ok(rod: Any) -> None:
    tracks = _drop(rod, rod, 45, 500)
    bare = types.SimpleNamespace(length=rod.length, tip_radius=rod.tip_radius, mass=rod.mass)
    k = measure_impact(tracks, bare)
    assert not k.ok
    assert any("the tilt check did not run: the rod has no inertia" in d for d in k.doubts)
    assert measure_impact(tracks, rod).ok


def test_a_result_not_ok_is_shown_and_warned(rod: Any, tmp_path: Path) -> None:
    markers = tmp_path / "drop.csv"
    truth = S.rigid_impulse_impact(rod, math.radians(20), velocity=(0.0, -1.41))
    tracks = S.marker_tracks(rod, truth, markers=S.DEFAULT_MARKERS, rate=250, noise=0.15e-3,
                             seed=1)[0]  # fmt: skip
    write_csv_markers(tracks, markers)
    with pytest.warns(ImplausibleInputWarning, match="not ok: the marker geometry is in doubt"):
        res = analyze(markers, None, rod)
    assert not res.ok and res.doubts
    html = res._repr_html_()
    assert "<td>ok</td>" in html and ">no<" in html and "in doubt" in html
    assert "ok" in str(res) and "doubt" in str(res)


def test_an_ok_result_shows_ok_and_does_not_warn(rod: Any, tmp_path: Path) -> None:
    markers = tmp_path / "drop.csv"
    write_csv_markers(_drop(rod, rod, 45, 500), markers)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ImplausibleInputWarning)
        res = analyze(markers, None, rod)
    assert res.ok and ">yes<" in res._repr_html_()
