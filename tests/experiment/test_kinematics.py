"""Impact kinematics from marker tracks: accuracy against a known truth, and the clear errors."""

from __future__ import annotations

import math
import re
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import (
    ImpactNotFoundError,
    MarkerError,
    MarkerGeometry,
    MarkerTracks,
    RigidityError,
    TooFewFramesError,
    measure_impact,
    read_c3d,
)
from impactlab.materials import AISI_1010

from .conftest import CASES


def _checks(k: Any, tr: S.ImpactTruth) -> dict[str, tuple[float, float, float]]:
    """name -> (measured, sigma, truth)."""
    pairs = {
        "v_cx_in": (k.v_c_in[0], tr.v_in[0]),
        "v_cy_in": (k.v_c_in[1], tr.v_in[1]),
        "v_cx_out": (k.v_c_out[0], tr.v_out[0]),
        "v_cy_out": (k.v_c_out[1], tr.v_out[1]),
        "spin_in": (k.spin_in, tr.spin_in),
        "spin_out": (k.spin_out, tr.spin_out),
        "v_tip_y_in": (k.v_tip_in[1], tr.v_tip_in[1]),
        "v_tip_y_out": (k.v_tip_out[1], tr.v_tip_out[1]),
        "angle": (k.angle_in, tr.angle),
        "e": (k.e, tr.e),
        "mu": (k.mu, tr.mu),
    }
    return {n: (m.value, m.sigma, t) for n, (m, t) in pairs.items()}


@pytest.mark.parametrize("case", sorted(CASES))
def test_recovers_the_truth_from_c3d(drops: dict, rod: Any, case: int) -> None:
    """Acceptance: velocities within 3 sigma of the truth, e and mu within 0.02 (0.15 mm noise,
    500 fps, occlusions, real C3D file in mm)."""
    d = drops[case]
    tracks = read_c3d(d.c3d)
    k = measure_impact(tracks, rod, geometry=d.geometry)
    # a contact of finite duration T: the fits are evaluated at one instant inside it, the truth
    # at its start (before) and end (after); they differ by up to g T (a few mm/s)
    allow = {
        n: 9.81 * d.truth.duration for n in ("v_cy_in", "v_cy_out", "v_tip_y_in", "v_tip_y_out")
    }
    allow["e"] = 9.81 * d.truth.duration / abs(d.truth.v_tip_in[1])
    for name, (m, s, t) in _checks(k, d.truth).items():
        assert abs(m - t) <= 3.0 * s + allow.get(name, 0.0), f"{name}: {m} vs {t}, sigma {s}"
    assert abs(k.e.value - d.truth.e) < 0.02
    assert abs(k.mu.value - d.truth.mu) < 0.02
    t_mid = d.info["t_impact"] + 0.5 * d.truth.duration
    assert abs(k.t_impact.value - t_mid) < 3.0 * k.t_impact.sigma + 1e-4
    assert k.geometry_source == "given"
    assert not k.warnings
    # the out-of-plane velocity is zero within its uncertainty
    assert abs(k.v_c_z_in.value) < 4.0 * k.v_c_z_in.sigma + 1e-3


def test_exact_without_noise(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, noise=0.0, occlusion=0.0, seed=4)
    k = measure_impact(tracks, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    for name, (m, _, t) in _checks(k, tr).items():
        assert m == pytest.approx(t, abs=1e-7), name
    assert k.t_impact.value == pytest.approx(info["t_impact"], abs=1e-9)


def test_y_up_camera_frame(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, up="+y", seed=5)
    geo = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    k = measure_impact(tracks, rod, geometry=geo, up="+y")
    assert abs(k.e.value - tr.e) < 0.02
    with pytest.raises(MarkerError, match="up"):
        measure_impact(tracks, rod, geometry=geo, up="+z")


@pytest.mark.parametrize(("lab_up", "wrong_up"), [("+z", "-z"), ("+z", "+y"), ("+y", "-x")])
def test_wrong_up_names_gravity_and_the_measured_axis(rod: Any, lab_up: str, wrong_up: str) -> None:
    """The error gives gravity's measured direction (downwards) and the up= the data indicate."""
    tr = S.rigid_impulse_impact(rod, math.radians(20), (0.0, -1.41), e=0.5, mu=0.2)
    tracks, info = S.marker_tracks(rod, tr, up=lab_up, seed=5)
    geo = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod, geometry=geo, up=wrong_up)
    message = str(caught.value)
    axis = "xyz".index(lab_up[1])
    down = re.search(r"gravity in the data points along \(([^)]*)\)", message)
    assert down is not None
    assert float(down.group(1).split(",")[axis]) == pytest.approx(-1.0, abs=0.05)
    assert message.endswith(f"pass up='{lab_up}' (impactlab analyze --up {lab_up})")


def _tilted(tracks: MarkerTracks, deg: float) -> MarkerTracks:
    """The same tracks seen by a camera whose vertical is ``deg`` off the lab's (about x)."""
    c, s = math.cos(math.radians(deg)), math.sin(math.radians(deg))
    rot = np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
    return MarkerTracks(tracks.time, tracks.positions @ rot.T, tracks.labels, "tilted")


def test_a_tilted_camera_is_named_with_the_up_that_fixes_it(rod: Any) -> None:
    """A vertical 10 deg off up= biases e and mu: a warning gives the tilt and the measured up
    vector, and with that vector (also as the command line's text) the truth comes back."""
    tr = S.rigid_impulse_impact(rod, math.radians(30), (0.0, -1.41), e=0.6, mu=0.15)
    tracks, info = S.marker_tracks(rod, tr, seed=7)
    geo = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    tilted = _tilted(tracks, 10.0)
    k = measure_impact(tilted, rod, geometry=geo)
    (warning,) = [w for w in k.warnings if "deg away from -up" in w]
    text = re.search(r"--up '([^']*)'", warning)
    assert text is not None and re.search(r"\b(9\.\d|10\.\d) deg away", warning)
    fixed = measure_impact(tilted, rod, geometry=geo, up=text.group(1))
    assert not any("deg away from -up" in w for w in fixed.warnings)
    assert abs(fixed.e.value - tr.e) < 0.02 and abs(fixed.mu.value - tr.mu) < 0.01
    level = measure_impact(tracks, rod, geometry=geo)
    assert not any("deg away from -up" in w for w in level.warnings)


def test_a_wrong_time_base_is_refused(rod: Any) -> None:
    """A frame rate off by 2 (time stretched): the free fall is at g/4, e and mu are wrong:
    refused, naming the time base, not only the length unit."""
    tr = S.rigid_impulse_impact(rod, math.radians(30), (0.0, -1.41), e=0.6, mu=0.15)
    tracks, info = S.marker_tracks(rod, tr, seed=7)
    slow = MarkerTracks(2.0 * tracks.time, tracks.positions, tracks.labels, "slow")
    with pytest.raises(MarkerError, match=r"0\.25\d* times g .* the time base or the length unit"):
        measure_impact(slow, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))


@pytest.mark.parametrize("case", [45, 70])
def test_estimated_geometry(rod: Any, case: int) -> None:
    """Without the marker geometry: axis = the cluster's principal direction (markers laid out
    along the rod), centre of mass = the ballistic body point; its uncertainty is propagated."""
    ang, vi, e, mu, *_ = CASES[case]
    tr = S.rigid_impulse_impact(rod, math.radians(ang), (0.0, vi), e=e, mu=mu)
    tracks, _ = S.marker_tracks(rod, tr, markers=S.ALIGNED_MARKERS, seed=case)
    k = measure_impact(tracks, rod)
    assert k.geometry_source.startswith("estimated")
    for name, (m, s, t) in _checks(k, tr).items():
        assert abs(m - t) <= 4.0 * s + 1e-9, f"{ang} deg {name}: {m} vs {t} +- {s}"
    assert abs(k.e.value - tr.e) < 0.02 and abs(k.mu.value - tr.mu) < 0.02


def test_estimated_geometry_needs_rotation(rod: Any) -> None:
    """A rod that does not turn after the impact cannot show where its centre of mass is."""
    th = math.radians(45)
    tr = S.ImpactTruth(
        th, (0.0, -2.0), 0.0, (0.0, 1.0), 0.0, (0.0, -2.0), (0.0, 1.0), 0.5, 0.0, "slip"
    )
    tracks, _ = S.marker_tracks(rod, tr, markers=S.ALIGNED_MARKERS, seed=3)
    with pytest.raises(MarkerError, match="centre of mass"):
        measure_impact(tracks, rod)


def test_hold_release_and_second_bounce_are_trimmed(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(20), (0.0, -1.41), e=0.5, mu=0.2)
    tracks, info = S.marker_tracks(
        rod, tr, release=True, before=0.25, after=0.2, second_impact=True, seed=6
    )
    geo = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    k = measure_impact(tracks, rod, geometry=geo, max_fit_frames=150)
    t_first = tracks.time[k.pre.frames[0]]
    t_last = tracks.time[k.post.frames[-1]]
    assert t_first >= info["t_release"] - 0.01  # the held rod is not in the fit
    assert t_last < info["t_second_contact"]  # nor the second bounce
    assert k.pre.trimmed > 0
    for name, (m, s, t) in _checks(k, tr).items():
        assert abs(m - t) <= 3.5 * s, f"{name}: {m} vs {t} +- {s}"


def test_too_few_frames_after_the_impact(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, after=0.012, seed=7)
    with pytest.raises(TooFewFramesError, match="after the impact"):
        measure_impact(tracks, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))


def test_no_impact(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, before=0.15, after=0.0, seed=8)
    cut = tracks.time < info["t_impact"] - 0.004
    t2 = MarkerTracks(tracks.time[cut], tracks.positions[cut], tracks.labels, "flight.c3d")
    with pytest.raises(ImpactNotFoundError, match="no impact"):
        measure_impact(t2, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))


def test_loose_marker(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, seed=9)
    pos = np.array(tracks.positions)
    late = tracks.time > info["t_impact"]
    pos[late, 1, 2] += 0.004  # marker M2 shifts by 4 mm at the impact
    loose = MarkerTracks(tracks.time, pos, tracks.labels, "loose.c3d")
    with pytest.raises(RigidityError, match="M2") as caught:
        measure_impact(loose, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    assert "length unit" not in str(caught.value)


@pytest.mark.parametrize("geometry", [True, False])
def test_marker_file_in_mm_read_as_m_names_the_units(drops: dict, rod: Any, geometry: bool) -> None:
    """Coordinates 1000 times too large: markers metres apart, not a loose marker."""
    d = drops[20]
    tracks = read_c3d(d.c3d, units="m")
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod, geometry=d.geometry if geometry else None)
    message = str(caught.value)
    assert not isinstance(caught.value, RigidityError)
    assert "m apart, but the rod is 0.3048 m long" in message
    assert "another length unit than the one used (read as 'm')" in message


def test_rigidity_failure_with_a_fall_far_from_g_names_the_units(drops: dict, rod: Any) -> None:
    """Coordinates 5 times too large: the scaled noise fails the rigidity check, and the error
    says that the markers fall with 5 g."""
    tracks = read_c3d(drops[20].c3d)
    scaled = MarkerTracks(
        tracks.time, tracks.positions * 5.0, tracks.labels, "scaled.c3d", {"units": "mm"}
    )
    with pytest.raises(RigidityError) as caught:
        measure_impact(scaled, rod, rigidity_tolerance=0.5e-3)
    message = str(caught.value)
    assert "not rigidly attached" in message
    fall = re.search(r"the markers fall with ([0-9.]+) m/s\^2", message)
    assert fall is not None and float(fall.group(1)) == pytest.approx(5 * 9.81, rel=0.1)
    assert "another length unit than the one used (read as 'mm')" in message


def test_geometry_that_does_not_match(rod: Any) -> None:
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, seed=10)
    wrong = MarkerGeometry(S.DEFAULT_MARKERS * 1.2, info["labels"])
    with pytest.raises(MarkerError, match="does not match"):
        measure_impact(tracks, rod, geometry=wrong)
    renamed = MarkerGeometry(S.DEFAULT_MARKERS, ("A", "B", "C"))
    with pytest.raises(MarkerError, match=r"names markers \['A', 'B', 'C'\]"):
        measure_impact(tracks, rod, geometry=renamed)


def test_a_marker_never_seen_is_named(rod: Any) -> None:
    """A marker invalid in every frame: the cluster cannot be measured, nor a given geometry
    checked against it; both messages name the marker."""
    tr = S.rigid_impulse_impact(rod, math.radians(45), (0.0, -2.18), e=0.49, mu=0.13)
    tracks, info = S.marker_tracks(rod, tr, seed=10)
    pos = tracks.positions.copy()
    pos[:, 2, :] = np.nan
    blind = MarkerTracks(tracks.time, pos, tracks.labels, tracks.source)
    lost = f"never seen: [{tracks.labels[2]!r}]"
    with pytest.raises(MarkerError, match=re.escape(lost)) as without:
        measure_impact(blind, rod)
    assert "give the marker geometry" in str(without.value)
    geometry = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
    with pytest.raises(MarkerError, match=re.escape(lost)) as given_one:
        measure_impact(blind, rod, geometry=geometry)
    assert "leave a marker that is never seen out of the geometry" in str(given_one.value)


def test_engine_truth(rod: Any) -> None:
    """With the impact engine (finite contact duration, its history through the contact)."""
    truth = S.engine_impact(rod, AISI_1010, math.radians(45), (0.0, -2.18), mu=0.13)
    assert truth.duration > 0 and truth.contact is not None
    tracks, info = S.marker_tracks(rod, truth, seed=11)
    k = measure_impact(tracks, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    assert abs(k.e.value - truth.e) < 0.02
    assert abs(k.mu.value - truth.mu) < 0.02
    # the crossing of the tip heights lies inside the contact
    assert info["t_impact"] - 3 * k.t_impact.sigma <= k.t_impact.value
    assert k.t_impact.value <= info["t_impact"] + truth.duration + 3 * k.t_impact.sigma
