"""What :func:`analyze` refuses or reports besides the stages' own errors: a sticking impact,
option values and a contact law checked at once, the output folder (stale figures, files that
cannot be written), the units named in messages, and the command line's options and errors."""

from __future__ import annotations

import json
import math
import shutil
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from impactlab import testing as S
from impactlab.experiment import MarkerGeometry, analyze

from .conftest import GEOMETRY_TOML

CliMain = Callable[..., tuple[int, str, str]]


@pytest.fixture(scope="module")
def sticking_drop(tmp_path_factory: pytest.TempPathFactory, rod: Any) -> tuple[Path, Any]:
    """A 20 deg drop with mu = 1 > mu_c = 0.76: the tip sticks; the measured mu comes out just
    under mu_c (0.7577 +- 0.006 for this seed), the tip's tangential exit velocity ~0."""
    truth = S.rigid_impulse_impact(rod, math.radians(20), (0.0, -1.41), e=0.5, mu=1.0)
    assert truth.regime == "stick"
    tracks, info = S.marker_tracks(rod, truth, noise=0.15e-3, seed=3)
    path = S.write_c3d(tracks, tmp_path_factory.mktemp("stick") / "stick.c3d")
    return path, MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])


def test_a_sticking_impact_gives_no_duration(
    sticking_drop: tuple[Path, Any], scans: dict, rod: Any
) -> None:
    """mu within 3 sigma of mu_c (the point value below it): the inversion stage refuses with
    the sticking regime's reason; the measurements stay."""
    path, geo = sticking_drop
    res = analyze(path, scans[20].files["x3p"], rod, geometry=geo)
    assert res.kinematics is not None and res.kinematics.mu.value < 0.7614
    assert set(res.errors) == {"inversion"} and res.inversion is None
    message = res.errors["inversion"]
    assert message.startswith("sticking regime: mu = 0.75")
    assert "mu_c = 0.76" in message and "zero within 3 sigma" in message
    summary = res.summary()
    assert "duration" not in summary and "mean_force" not in summary
    assert {"e", "mu", "sliding_length"} <= set(summary)


def test_a_sliding_impact_is_still_inverted(drops: dict, scans: dict, rod: Any) -> None:
    d = drops[20]
    res = analyze(d.c3d, scans[20].files["x3p"], rod, geometry=d.geometry)
    assert res.ok and res.inversion is not None


# -- arguments checked at once -------------------------------------------------------------------


@pytest.mark.parametrize(
    ("kwargs", "error", "needle"),
    [
        ({"kinematics_options": {"window": 2.7}}, TypeError, "kinematics_options: window"),
        ({"kinematics_options": {"guard": 0}}, ValueError, "kinematics_options: guard must be"),
        (
            {"kinematics_options": {"rigidity_tolerance": "1 mm"}},
            TypeError,
            "kinematics_options: rigidity_tolerance must be a finite number > 0 in m",
        ),
        ({"kinematics_options": {"g": 0.0}}, ValueError, "kinematics_options: g must be"),
        (
            {"kinematics_options": {"rigidity_tolerance": -1e-3}},
            ValueError,
            "rigidity_tolerance must be a finite number > 0",
        ),
        ({"law": "nope"}, ValueError, "law: unknown contact law 'nope'"),
    ],
)
def test_bad_values_raise_before_any_work(
    tmp_path: Path, drops: dict, kwargs: dict[str, Any], error: type, needle: str
) -> None:
    """Raised at once (not recorded as the markers stage's error), nothing written."""
    out = tmp_path / "never"
    with pytest.raises(error, match=needle):
        analyze(drops[20].c3d, None, out_dir=out, **kwargs)
    assert not out.exists()


# -- the output folder ---------------------------------------------------------------------------


def test_a_figure_of_an_earlier_run_is_removed(
    tmp_path: Path, drops: dict, scans: dict, analysed_drop: Callable[[int], tuple[Any, Path]]
) -> None:
    d = drops[20]
    first, folder = analysed_drop(20)  # conftest.py: the earlier run, copied into tmp_path
    assert set(first.figures) == {"kinematics", "dent"}
    shutil.copytree(folder, tmp_path, dirs_exist_ok=True)
    bad = tmp_path / "cut.x3p"
    bad.write_bytes(scans[20].files["x3p"].read_bytes()[:200])
    second = analyze(d.c3d, bad, geometry=d.geometry, out_dir=tmp_path)
    assert set(second.errors) == {"scan"} and set(second.figures) == {"kinematics"}
    assert not (tmp_path / "dent.png").exists()
    assert any("removed" in w and "dent.png" in w and "earlier run" in w for w in second.warnings)
    saved = json.loads((tmp_path / "results.json").read_text())
    assert "dent" not in saved["figures"] and "scan" in saved["errors"]


def test_a_folder_in_the_way_of_results_json_is_named(
    tmp_path: Path, drops: dict, cli_main: CliMain, junk: dict[str, Path]
) -> None:
    """results.json that cannot be written: the stage's error naming the file, and nothing
    written into the folder (the figures go with it); the command line prints the measured
    table first, then the error, exit status 2. A figure that cannot be written is named."""
    (tmp_path / "results.json").mkdir()
    d = drops[20]
    res = analyze(d.c3d, None, geometry=d.geometry, out_dir=tmp_path)
    assert res.kinematics is not None and "results" not in res.files
    message = res.errors["results"]
    assert "results.json" in message and "a folder of that name is in the way" in message
    assert "results.json" in res.errors["figures"] and not res.figures
    assert not (tmp_path / "kinematics.png").exists()
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    code, out, err = cli_main("analyze", str(d.c3d), str(junk["x3p"]), "--geometry", str(geo),
                              "--out", str(tmp_path))  # fmt: skip
    assert code == 2 and "│ e " in out and "│ mu " in out
    (line,) = [ln for ln in err.splitlines() if ln.startswith("error:")]
    assert "results: cannot write" in line and "results.json" in line and "Errno" not in line
    (tmp_path / "results.json").rmdir()
    (tmp_path / "kinematics.png").mkdir()
    res = analyze(d.c3d, None, geometry=d.geometry, out_dir=tmp_path)
    assert "kinematics.png" in res.errors["figures"] and "results" in res.files


# -- units named in messages ---------------------------------------------------------------------


@pytest.mark.parametrize(("unit", "factor"), [("nm", "1e+09"), ("um", "1e+06")])
def test_a_dent_read_in_a_too_small_unit_names_that_unit(
    tmp_path: Path, scans: dict, unit: str, factor: str
) -> None:
    sc = scans[20]
    path = tmp_path / "dent_m.npy"
    np.save(path, sc.z)
    res = analyze(None, path, pixel_size=sc.dx, height_unit=unit)
    assert (
        f"heights stored in metres and read as '{unit}' come out {factor} times"
        in (res.errors["scan"])
    )


def test_a_geometry_without_units_is_said_to_be_read_in_metres(
    tmp_path: Path, drops: dict, cli_main: CliMain, junk: dict[str, Path]
) -> None:
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML.replace('units = "mm"\n', ""))
    code, _, err = cli_main("analyze", str(drops[20].c3d), str(junk["x3p"]), "--geometry", str(geo))
    assert code == 2
    assert "does not match the markers" in err
    assert "the geometry was read in m (no units key)" in err


def test_a_geometry_entry_that_is_not_three_numbers_is_named(
    tmp_path: Path, drops: dict, cli_main: CliMain
) -> None:
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML.replace("[-30.0, 18.0, 0.0]", '"a"'))
    code, _, err = cli_main("analyze", str(drops[20].c3d), "missing.x3p", "--geometry", str(geo))
    assert code == 2  # (the geometry file is read before the paths are looked at)
    assert err.strip() == (
        f"error: --geometry {str(geo)!r}: markers.M1 must be [x, y, z], three numbers (in the "
        "table's units), got 'a'"
    )


def test_marker_units_help_says_what_it_does_to_each_format(cli_main: CliMain) -> None:
    code, out, _ = cli_main("analyze", "--help")
    text = " ".join(out.replace("│", " ").split())
    assert code == 0
    assert "for a C3D file it replaces the POINT:UNITS parameter" in text
    assert "'# units:' line, which it must agree with" in text
