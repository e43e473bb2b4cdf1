"""Faulty marker data named for what it is: a mirrored geometry or lab frame, an e outside
[0, 1], a record that runs on past the first impact, a wrong time base or gravity, wrong samples
in single frames, option values of the wrong kind."""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import MarkerError, MarkerGeometry, MarkerTracks, measure_impact

#: Flipping the third body coordinate mirrors a geometry and keeps the rod's axis and C.
MIRROR = np.diag([1.0, 1.0, -1.0])
#: A fourth marker off the plane of the other three (for the shape test of a mirror image).
FOUR_MARKERS = np.vstack([S.DEFAULT_MARKERS, [-0.060, -0.015, -0.018]])


def _drop(rod: Any, angle: float = 20.0, seed: int = 3, **kw: Any) -> tuple[Any, Any, Any]:
    """(truth, tracks, info) of the paper's drop at ``angle`` deg (impulse model, 0.15 mm)."""
    v, e, mu = {20.0: (-1.41, 0.5, 0.2), 45.0: (-2.18, 0.49, 0.13)}[angle]
    truth = S.rigid_impulse_impact(rod, math.radians(angle), (0.0, v), e=e, mu=mu)
    tracks, info = S.marker_tracks(rod, truth, noise=0.15e-3, seed=seed, **kw)
    return truth, tracks, info


def _geometry(info: dict[str, Any], reflect: bool = False) -> MarkerGeometry:
    markers = info["markers_body"] @ MIRROR if reflect else info["markers_body"]
    return MarkerGeometry(markers, info["labels"])


def _with(tracks: MarkerTracks, *, time: Any = None, positions: Any = None) -> MarkerTracks:
    return MarkerTracks(
        tracks.time if time is None else time,
        tracks.positions if positions is None else positions,
        tracks.labels,
        "drop.csv",
    )


# -- a mirrored geometry or lab frame ------------------------------------------------------------


def test_a_mirrored_geometry_of_three_markers_is_named(rod: Any) -> None:
    """Three markers keep every distance in the mirror image: the pose fits, but e comes out
    negative (-0.19 for e = 0.5); the error says so and names both causes."""
    _, tracks, info = _drop(rod)
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod, geometry=_geometry(info, reflect=True))
    message = str(caught.value)
    e_bad = re.search(r"e = (-?[0-9.]+) ± [0-9.e-]+ is outside \[0, 1\]", message)
    assert e_bad is not None and float(e_bad.group(1)) < 0
    e_good = re.search(r"but e = ([0-9.]+) ± [0-9.e-]+ with the geometry mirrored", message)
    assert e_good is not None and abs(float(e_good.group(1)) - 0.5) < 0.03
    assert "the geometry is mirrored" in message and "left-handed" in message


def test_a_left_handed_lab_frame_is_named(rod: Any) -> None:
    """The right geometry with one camera axis flipped (not the up axis): the same error."""
    _, tracks, info = _drop(rod, seed=5)
    flipped = tracks.positions.copy()
    flipped[..., 1] *= -1.0
    with pytest.raises(MarkerError, match="lab frame of the marker file is left-handed"):
        measure_impact(_with(tracks, positions=flipped), rod, geometry=_geometry(info))


def test_a_mirrored_geometry_of_four_markers_fails_the_shape_test(rod: Any) -> None:
    """Markers off one plane: no rotation maps the mirror image onto them."""
    _, tracks, info = _drop(rod, angle=45.0, markers=FOUR_MARKERS)
    with pytest.raises(MarkerError, match="mirror image of the markers' layout") as caught:
        measure_impact(tracks, rod, geometry=_geometry(info, reflect=True))
    assert "left-handed" in str(caught.value)
    k = measure_impact(tracks, rod, geometry=_geometry(info))
    assert abs(k.e.value - 0.49) < 0.02


def test_e_above_one_is_a_marker_error(rod: Any) -> None:
    """A tip leaving faster than it came (no mirror explains it): refused, not passed on."""
    th = math.radians(45)
    truth = S.ImpactTruth(
        th, (0.0, -2.0), 0.0, (0.0, 3.0), 0.0, (0.0, -2.0), (0.0, 3.0), 1.5, 0.0, "slip"
    )
    tracks, info = S.marker_tracks(rod, truth, seed=3)
    with pytest.raises(MarkerError, match=r"e = 1\.\d+ ± \S+ is outside \[0, 1\] by more than 3"):
        measure_impact(tracks, rod, geometry=_geometry(info))


# -- several impacts in one record ---------------------------------------------------------------


@pytest.mark.parametrize(("angle", "seed"), [(20.0, 3), (20.0, 4), (45.0, 3)])
def test_the_first_impact_is_analysed(rod: Any, angle: float, seed: int) -> None:
    """A record that runs on past a second, larger bounce: the drop's impact is measured and a
    warning names the larger jump that follows it."""
    truth, tracks, info = _drop(rod, angle=angle, seed=seed, second_impact=True, after=0.3)
    k = measure_impact(tracks, rod, geometry=_geometry(info))
    assert abs(k.t_impact.value - info["t_impact"]) < 0.002
    assert abs(k.e.value - truth.e) < 0.03 and abs(k.mu.value - truth.mu) < 0.02
    assert tracks.time[k.post.frames[-1]] < info["t_second_contact"]
    if angle == 20.0:  # the bounce is the larger jump there
        assert any("a larger jump of the rod's velocity" in w for w in k.warnings)


def test_a_first_jump_without_free_flight_before_it_names_every_jump(rod: Any) -> None:
    """A record cut 5 frames before the drop's impact: too few frames before it, and the error
    lists the jumps found and how to cut the record."""
    _, tracks, info = _drop(rod, seed=4, second_impact=True, after=0.3)
    keep = tracks.time > info["t_impact"] - 0.011
    cut = MarkerTracks(tracks.time[keep], tracks.positions[keep], tracks.labels, "cut.csv")
    with pytest.raises(MarkerError) as caught:
        measure_impact(cut, rod, geometry=_geometry(info))
    message = str(caught.value)
    assert "free-flight frames with a pose before the impact" in message
    found = r"several impact-sized jumps of the rod's velocity found, at t = \S+, "
    assert re.search(found, message)
    assert "cut the record so that it starts after" in message


# -- time base and gravity -----------------------------------------------------------------------


def test_a_frame_rate_off_by_twenty_percent_is_refused(rod: Any) -> None:
    """600 fps read for 500 fps: the free fall at 1.44 g was accepted (mu wrong); now refused
    naming the time base."""
    _, tracks, info = _drop(rod)
    fast = _with(tracks, time=tracks.time * 500.0 / 600.0)
    with pytest.raises(MarkerError, match=r"1\.4\d times g .* the time base or the length unit"):
        measure_impact(fast, rod, geometry=_geometry(info))
    right = measure_impact(tracks, rod, geometry=_geometry(info))
    assert right.fitted_gravity is not None and abs(right.fitted_gravity / 9.80665 - 1) < 0.05


def test_times_in_milliseconds_are_named_before_any_segment(rod: Any) -> None:
    """Times 1000 times too large: named as the time base (milliseconds), not as too few
    free-flight frames."""
    _, tracks, info = _drop(rod)
    with pytest.raises(MarkerError, match="milliseconds read as seconds") as caught:
        measure_impact(_with(tracks, time=tracks.time * 1000.0), rod, geometry=_geometry(info))
    assert "time base" in str(caught.value)


@pytest.mark.parametrize("g", [0.0, -9.81, math.inf])
def test_gravity_must_be_positive(rod: Any, g: float) -> None:
    _, tracks, info = _drop(rod)
    with pytest.raises(ValueError, match=r"^g must be a finite number > 0 in m/s\^2"):
        measure_impact(tracks, rod, geometry=_geometry(info), g=g)


def test_a_gravity_far_from_the_data_is_refused(rod: Any) -> None:
    """g given 30 % off the free fall in the data."""
    _, tracks, info = _drop(rod)
    with pytest.raises(MarkerError, match="time base or the length unit"):
        measure_impact(tracks, rod, geometry=_geometry(info), g=7.0)


# -- wrong samples in single frames --------------------------------------------------------------


@pytest.mark.parametrize(
    ("fault", "frames"),
    [("glitch", (10,)), ("garbage", (10, 38)), ("swap", (60, 61, 62, 63))],
)
def test_wrong_samples_are_left_out_and_named(rod: Any, fault: str, frames: tuple[int]) -> None:
    """A marker 50 mm off in one frame, garbage coordinates (1e27 m), two labels swapped for
    four frames after the impact: those frames are left out with a warning naming them, and
    the impact is measured as without them."""
    truth, tracks, info = _drop(rod, occlusion=0.0)
    pos = tracks.positions.copy()
    for k in frames:
        if fault == "glitch":
            pos[k, 1, 0] += 0.050
        elif fault == "garbage":
            pos[k, 2] = 1e27
        else:
            pos[k, [0, 2]] = pos[k, [2, 0]]
    k = measure_impact(_with(tracks, positions=pos), rod, geometry=_geometry(info))
    (warning,) = [w for w in k.warnings if "far off the rigid cluster" in w]
    assert warning.startswith(f"{len(frames)} frame(s) with a marker far off the rigid cluster")
    for f in frames:
        assert f"{f} (t = {tracks.time[f]:.4f} s)" in warning
    assert abs(k.e.value - truth.e) < 0.03 and abs(k.mu.value - truth.mu) < 0.02


# -- option values -------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("options", "error", "needle"),
    [
        ({"window": 2.7}, TypeError, "window must be an integer >= 2"),
        ({"guard": 0}, ValueError, "guard must be an integer >= 1"),
        ({"min_fit_frames": True}, TypeError, "min_fit_frames must be an integer >= 4"),
        ({"rigidity_tolerance": "1 mm"}, TypeError, "rigidity_tolerance must be a finite number"),
        ({"rigidity_tolerance": math.nan}, ValueError, "rigidity_tolerance must be a finite"),
        ({"max_com_sigma": -1.0}, ValueError, "max_com_sigma must be a finite number > 0 in m"),
        ({"max_fit_frames": 5}, ValueError, r"max_fit_frames \(5\) must be >= min_fit_frames"),
    ],
)
def test_option_values_are_checked(
    rod: Any, options: dict[str, Any], error: type, needle: str
) -> None:
    _, tracks, info = _drop(rod)
    with pytest.raises(error, match=needle):
        measure_impact(tracks, rod, geometry=_geometry(info), **options)
