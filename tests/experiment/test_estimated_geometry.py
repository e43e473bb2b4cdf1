"""Without a marker geometry the rod's axis is the markers' principal direction: markers not laid
out along the rod (the docs' own layout) gave an angle of 40 deg for a 20 deg drop and e = 0.31
for 0.5 as a plain success. The impulse relation (the spin change against the centre of mass's
velocity change) implies the tilt of the rod's axis from the estimated one: a gross tilt is
refused, naming --geometry; a small one (markers glued off the axis) or one the check cannot
tell marks the result not ok; markers laid out along the rod pass, and the docs' quick start
runs."""

from __future__ import annotations

import json
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import MarkerError, MarkerGeometry, measure_impact, write_csv_markers
from impactlab.experiment.kinematics.impulse import gyration_squared
from impactlab.experiment.kinematics.tilt import TiltCheck, tilt_check

from .conftest import GEOMETRY_TOML

#: The paper's drops: angle [deg], v_i [m/s], e, mu.
DROPS = {20: (-1.41, 0.5, 0.2), 45: (-2.18, 0.49, 0.13), 70: (-3.45, 0.05, 0.10)}


def _tracks(rod: Any, angle: int, markers: np.ndarray, seed: int, **kw: Any) -> tuple[Any, Any]:
    v, e, mu = DROPS[angle]
    truth = S.rigid_impulse_impact(rod, math.radians(angle), (0.0, v), e=e, mu=mu)
    return S.marker_tracks(rod, truth, markers=markers, seed=seed, **{"noise": 0.1e-3, **kw})


def _drop(rod: Any, angle: int, markers: np.ndarray, seed: int, rate: float, noise: float) -> Any:
    """The tracks of a drop at 1.41 m/s (e 0.5, mu 0.2) at ``angle`` [deg]."""
    truth = S.rigid_impulse_impact(rod, math.radians(angle), velocity=(0.0, -1.41))
    return S.marker_tracks(rod, truth, markers=markers, rate=rate, noise=noise, seed=seed)[0]


def _glued(offset: float, seed: int) -> np.ndarray:
    """The aligned markers moved ``offset`` [m] off the rod's axis in random directions."""
    rng = np.random.default_rng(1000 + seed)
    d = rng.normal(size=(3, 2))
    markers = S.ALIGNED_MARKERS.copy()
    markers[:, 1:] += offset * d / np.linalg.norm(d, axis=1)[:, None]
    return markers


@pytest.mark.parametrize(("angle", "seed"), [(45, 0), (45, 2), (70, 2)])
def test_markers_off_the_rods_axis_are_refused_without_a_geometry(
    rod: Any, angle: int, seed: int
) -> None:
    tracks, info = _tracks(rod, angle, S.DEFAULT_MARKERS, seed)
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod)
    message = str(caught.value)
    assert "with the marker geometry estimated" in message
    assert "the markers are not laid out along the rod" in message
    assert "--geometry" in message and "geometry= in Python" in message
    # the same drop with its geometry: the true angle and e
    k = measure_impact(tracks, rod, geometry=MarkerGeometry(S.DEFAULT_MARKERS, info["labels"]))
    assert abs(math.degrees(k.angle_in.value) - angle) < 0.5
    assert abs(k.e.value - DROPS[angle][1]) < 0.03


@pytest.mark.parametrize(
    ("rate", "noise", "seed"), [(250, 0.15e-3, 1), (500, 0.05e-3, 1), (500, 0.1e-3, 3)]
)
def test_the_docs_layout_at_20_deg_is_never_a_plain_success(
    rod: Any, rate: float, noise: float, seed: int
) -> None:
    """At 250 fps and 0.15 mm the implied tilt (-15 +- 11 deg) cannot be told from none: not
    refused (aligned markers give such tilts too), but not ok, naming --geometry. At 500 fps
    (-23 +- 5 deg, the rod's inertia known to 5 % included) refused, or not ok where an inertia
    10 % off would explain it."""
    tracks = _drop(rod, 20, S.DEFAULT_MARKERS, seed, rate, noise)
    if rate == 500:
        message = ""
        try:
            k = measure_impact(tracks, rod)
        except MarkerError as exc:
            message = str(exc)
        if message:
            assert "the markers are not laid out along the rod" in message
        else:
            assert not k.ok and "--geometry" in k.doubts[0]
        return
    k = measure_impact(tracks, rod)
    assert not k.ok and len(k.doubts) == 1
    assert "too uncertain to tell a tilt of 5 deg" in k.doubts[0]
    assert "--geometry" in k.doubts[0] and k.doubts[0] in k.warnings
    assert k.to_dict()["ok"] is False


@pytest.mark.parametrize("angle", [20, 45, 70])
@pytest.mark.parametrize("seed", [0, 1, 2])
def test_markers_along_the_rod_pass_without_a_geometry(rod: Any, angle: int, seed: int) -> None:
    tracks, _ = _tracks(rod, angle, S.ALIGNED_MARKERS, seed)
    try:
        k = measure_impact(tracks, rod)
    except MarkerError as exc:  # 20 deg, little flight after the impact: other limits, not this
        refused = str(exc)
    else:
        refused = ""
    if refused:
        assert angle == 20 and "with the marker geometry estimated" not in refused
        return
    check = tilt_check(k, gyration_squared(rod) or 0.0)
    assert abs(check.tilt) < 3.0 * check.sigma
    if angle == 20:  # a shallow angle: the check may not tell a 5 deg tilt from none
        assert check.verdict in ("pass", "undecided") and k.ok == (check.verdict == "pass")
    else:
        assert check.verdict == "pass" and k.ok and not k.doubts
    assert abs(math.degrees(k.angle_in.value) - angle) < 0.5
    assert abs(k.e.value - DROPS[angle][1]) < 0.06


@pytest.mark.parametrize(("angle", "rate", "noise"), [(70, 250, 0.15e-3), (45, 500, 0.05e-3)])
def test_markers_glued_1_mm_off_the_axis_are_not_refused(
    rod: Any, angle: int, rate: float, noise: float
) -> None:
    """1 mm off the axis tilts it ~1 deg: at steep angles that moves the predicted spin by ~17 %
    (refused before), but the implied tilt is small and finds the true angle (within the rod's
    inertia, known to 5 %, such a tilt is not told from none: docs/experiment.md)."""
    k = measure_impact(_drop(rod, angle, _glued(1e-3, 1), 1, rate, noise), rod)
    check = tilt_check(k, gyration_squared(rod) or 0.0)
    assert check.verdict in ("tilted", "pass")
    assert 0.5 < abs(math.degrees(check.tilt)) < 2.0
    assert abs(math.degrees(k.angle_in.value + check.tilt) - angle) < 0.5


def test_the_implied_tilt_finds_the_docs_layout(rod: Any) -> None:
    """The docs' layout tilts the estimated axis 20 deg: at 45 deg (read as 65 deg) the
    relation implies that tilt and the true angle, and the refusal says both."""
    tracks, _ = _tracks(rod, 45, S.DEFAULT_MARKERS, 0, noise=0.05e-3)
    with pytest.raises(MarkerError) as caught:
        measure_impact(tracks, rod)
    found = re.search(
        r"tilted ([-+][\d.]+) \+- ([\d.]+) deg \(a rod's angle of ([\d.]+)", str(caught.value)
    )
    assert found is not None, str(caught.value)
    tilt, sigma, angle = (float(g) for g in found.groups())
    assert abs(tilt + 20.0) < 1.5 and sigma < 2.5 and abs(angle - 45.0) < 1.5


@pytest.mark.parametrize(
    ("tilt_deg", "sigma_deg", "verdict"),
    [
        (-20.0, 0.1, "gross"),
        (-15.2, 4.0, "gross"),  # 15.2 > 5 + 2 * 4 and > 3 sigma
        (-15.2, 9.1, "undecided"),  # 1.7 sigma
        (-15.2, 11.0, "undecided"),
        (-5.1, 1.5, "tilted"),  # beyond 3 sigma, but 5 deg is within 2 sigma of it
        (-1.3, 0.3, "tilted"),
        (0.3, 0.2, "pass"),
        (2.0, 2.4, "pass"),
        (2.0, 2.6, "undecided"),  # a 5 deg tilt within 2 sigma
        (math.nan, math.inf, "gross"),  # no tilt within 45 deg satisfies the relation
        (50.0, 0.1, "gross"),
    ],
)
def test_the_tilt_verdicts(tilt_deg: float, sigma_deg: float, verdict: str) -> None:
    check = TiltCheck(math.radians(tilt_deg), math.radians(sigma_deg))
    assert check.verdict == verdict


@pytest.fixture(scope="module")
def dent_npy(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A dent 5 um deep at 2 um pixels, heights in um (.npy), as the docs' quick start reads
    it; a margin of 0.4 mm around it (half the default) keeps the map small."""
    z, *_ = S.synthetic_scan(delta_p=5e-6, sliding_length=300e-6, pixel=2e-6, margin=0.4e-3, seed=1)
    path = tmp_path_factory.mktemp("docs_dent") / "dent.npy"
    np.save(path, z * 1e6)  # um
    return path


def test_the_docs_quick_start_runs(
    rod: Any, tmp_path: Path, dent_npy: Path, cli_main: Callable[..., tuple[int, str, str]]
) -> None:
    """``impactlab analyze drop.csv dent.npy --pixel-size "2 um" --height-unit um --up +y``:
    with the markers of the docs' layout, it runs with --geometry, and without it says to give
    one (exit status 2, the scan still measured)."""
    tracks, _ = _tracks(rod, 45, S.DEFAULT_MARKERS, 3, up="+y")
    write_csv_markers(tracks, tmp_path / "drop.csv")
    (tmp_path / "markers.toml").write_text(GEOMETRY_TOML)
    args = ("analyze", str(tmp_path / "drop.csv"), str(dent_npy), "--pixel-size",
            "2 um", "--height-unit", "um", "--up", "+y", "--json")  # fmt: skip
    code, out, err = cli_main(*args, "--geometry", str(tmp_path / "markers.toml"))
    assert code == 0, err
    data = json.loads(out)
    assert abs(data["summary"]["angle"]["value"] - math.radians(45)) < 0.01
    assert data["summary"]["duration"]["value"] > 0 and not data["errors"]
    code, out, err = cli_main(*args)
    assert code == 2
    assert "markers: " in err and "--geometry" in err and "not laid out along the rod" in err
    assert "sliding_length" in json.loads(out)["summary"]


def test_a_result_in_doubt_is_not_ok_in_the_api_the_json_and_the_table(
    rod: Any, tmp_path: Path, dent_npy: Path, cli_main: Callable[..., tuple[int, str, str]]
) -> None:
    """The docs' layout at 20 deg and 250 fps was a plain success (exit status 0, no sign)."""
    from impactlab.experiment import analyze

    markers = write_csv_markers(
        _drop(rod, 20, S.DEFAULT_MARKERS, 1, 250, 0.15e-3), tmp_path / "drop.csv"
    )
    res = analyze(markers, None, out_dir=tmp_path / "out")
    assert not res.errors and not res.ok and res.kinematics is not None
    assert not res.kinematics.ok
    assert any("marker geometry is in doubt" in w for w in res.warnings)
    saved = json.loads((tmp_path / "out" / "results.json").read_text())
    assert saved["ok"] is False and saved["kinematics"]["ok"] is False
    args = ("analyze", str(markers), str(dent_npy), "--pixel-size", "2 um",
            "--height-unit", "um")  # fmt: skip
    code, out, _ = cli_main(*args, "--json")
    data = json.loads(out)
    assert code == 0 and data["ok"] is False
    assert any("the marker geometry is in doubt" in w for w in data["warnings"])
    code, out, err = cli_main(*args)
    assert code == 0 and "no: the marker geometry is in doubt" in out
    assert "the marker geometry is in doubt" in err and "--geometry" in err
