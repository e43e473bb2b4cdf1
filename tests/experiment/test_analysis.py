"""One call (API and command line) from the raw files to e, mu, delta_p, L_s, T and F."""

from __future__ import annotations

import json
import math
import re
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

import impactlab.analytic as analytic
from impactlab import ImplausibleInputWarning
from impactlab.analytic import invert
from impactlab.bodies import PAPER_ROD
from impactlab.cli import app
from impactlab.experiment import (
    ExperimentError,
    MarkerGeometry,
    analyze,
    check_rigidity,
    fit_poses,
    level_plane,
    measure_dent,
    measure_impact,
    read_markers,
    read_scan,
    rod_properties,
)

from .conftest import GEOMETRY_TOML


@pytest.mark.parametrize("case", [20, 45])
def test_analyze_end_to_end(
    analysed_drop: Callable[[int], tuple[Any, Path]], drops: dict, scans: dict, rod: Any, case: int
) -> None:
    d, sc = drops[case], scans[case]
    res, out = analysed_drop(case)  # conftest.py: the X3P dent, 2000 samples, a new folder
    assert res.ok, res.errors
    s = res.summary()
    assert abs(s["e"].value - d.truth.e) < 0.02
    assert abs(s["mu"].value - d.truth.mu) < 0.02
    g = sc.truth.groove
    assert s["delta_p"].value == pytest.approx(g.depth, rel=0.02)
    assert s["sliding_length"].value == pytest.approx(g.sliding_length, rel=0.05)
    # T and F agree with the inversion of the true values within the propagated uncertainty
    tr = d.truth
    ref = invert(
        angle=tr.angle,
        v_i=tr.v_tip_in[1],
        mu=tr.mu,
        e=tr.e,
        dv_cy=tr.v_out[1] - tr.v_in[1],
        delta_p=g.depth,
        sliding_length=g.sliding_length,
        rod=rod_properties(rod),
        n_samples=2000,
    )
    T, F = s["duration"], s["mean_force"]
    assert abs(T.value - ref.duration) < 3.0 * T.sigma + 0.02 * ref.duration
    assert abs(F.value - ref.mean_force) < 3.0 * F.sigma + 0.02 * ref.mean_force
    saved = json.loads((out / "results.json").read_text())
    assert saved["summary"]["duration"]["value"] == pytest.approx(s["duration"].value)
    assert saved["errors"] == {}
    for name in ("dent.png", "kinematics.png"):
        assert (out / name).stat().st_size > 10_000


def test_bad_scan_keeps_the_marker_results(tmp_path: Path, drops: dict, rod: Any) -> None:
    d = drops[45]
    bad = tmp_path / "dent.x3p"
    bad.write_bytes(b"PK\x03\x04 truncated zip")
    res = analyze(d.c3d, bad, rod, geometry=d.geometry, out_dir=tmp_path / "out")
    assert not res.ok and set(res.errors) == {"scan"}
    assert "dent.x3p" in res.errors["scan"]
    assert res.kinematics is not None and abs(res.kinematics.e.value - d.truth.e) < 0.02
    saved = json.loads((tmp_path / "out" / "results.json").read_text())
    assert "e" in saved["summary"] and "scan" in saved["errors"]
    assert (tmp_path / "out" / "kinematics.png").exists()
    with pytest.raises(ExperimentError, match=r"scan: .*dent.x3p"):
        analyze(d.c3d, bad, rod, geometry=d.geometry, strict=True)


def test_bad_markers_keep_the_dent(tmp_path: Path, scans: dict, rod: Any) -> None:
    c3d = tmp_path / "drop.c3d"
    c3d.write_bytes(b"\x02P" + b"\x00" * 50)
    res = analyze(c3d, scans[20].files["gwy"], rod)
    assert set(res.errors) == {"markers"} and "drop.c3d" in res.errors["markers"]
    assert res.dent is not None and res.inversion is None


def test_inversion_failure_is_reported(
    monkeypatch: pytest.MonkeyPatch, drops: dict, scans: dict, rod: Any
) -> None:
    """An inversion that cannot be done (e.g. the sticking regime, mu >= mu_c) is reported with
    its reason; the measurements stay."""

    def refuse(**_: Any) -> Any:
        raise ValueError("sticking regime: mu = 0.9 >= mu_c = 0.35")

    monkeypatch.setattr(analytic, "invert", refuse)
    d = drops[70]
    res = analyze(d.c3d, scans[70].files["sdf"], rod, geometry=d.geometry)
    assert set(res.errors) == {"inversion"} and "sticking" in res.errors["inversion"]
    assert res.kinematics is not None and res.dent is not None
    assert "duration" not in res.summary() and "sliding_length" in res.summary()


def test_cli_analyze(tmp_path: Path, drops: dict, scans: dict) -> None:
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    d, sc = drops[45], scans[45]
    runner = CliRunner()
    out = tmp_path / "cli"
    r = runner.invoke(
        app,
        [
            "analyze",
            str(d.c3d),
            str(sc.files["sdf"]),
            "--geometry",
            str(geo),
            "--out",
            str(out),
            "--json",
        ],
    )
    assert r.exit_code == 0, r.output
    data = json.loads(r.stdout)
    assert abs(data["summary"]["e"]["value"] - d.truth.e) < 0.02
    assert data["summary"]["mean_force"]["unit"] == "N"
    assert (out / "results.json").exists() and (out / "dent.png").exists()
    r2 = runner.invoke(app, ["analyze", str(d.c3d), str(sc.files["sdf"]), "--geometry", str(geo)])
    assert r2.exit_code == 0 and "delta_p" in r2.stdout
    assert "│ duration " in r2.stdout and "│ ms" in r2.stdout


def test_cli_bad_scan_exits_with_one_line(
    cli_main: Callable[..., tuple[int, str, str]], tmp_path: Path, drops: dict
) -> None:
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    bad = tmp_path / "dent.sdf"
    bad.write_text("aISO-1.0\nNumPoints = 10\n")
    out = tmp_path / "o"
    args = [str(drops[20].c3d), str(bad), "--geometry", str(geo), "--out", str(out), "--json"]
    code, stdout, stderr = cli_main("analyze", *args)
    assert code == 2
    err = [ln for ln in stderr.splitlines() if ln.strip()]
    assert len(err) == 1 and err[0].startswith("error: scan:") and "dent.sdf" in err[0]
    assert "Traceback" not in stderr
    data = json.loads(stdout)  # the marker results are printed and saved
    assert "e" in data["summary"] and (out / "results.json").exists()


@pytest.mark.parametrize("archive", ["x3p", "npz"])
def test_zip_archive_named_npy_keeps_the_marker_results(
    cli_main: Callable[..., tuple[int, str, str]],
    tmp_path: Path,
    drops: dict,
    scans: dict,
    archive: str,
) -> None:
    """An X3P or NPZ archive (zip content) saved under a ``.npy`` name is a bad scan file, not a
    crash: the error names the file and the kinematics are printed and saved."""
    bad = tmp_path / "dent.npy"
    if archive == "x3p":
        bad.write_bytes(scans[20].files["x3p"].read_bytes())
    else:
        with bad.open("wb") as fh:
            np.savez(fh, z=scans[20].z)
    res = analyze(None, bad, pixel_size="8 um", height_unit="m")
    assert set(res.errors) == {"scan"} and res.dent is None
    assert "dent.npy: not a readable NPY array (it is a zip/NPZ archive)" in res.errors["scan"]
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    out = tmp_path / "o"
    args = [str(drops[20].c3d), str(bad), "--geometry", str(geo), "--out", str(out), "--json"]
    code, stdout, stderr = cli_main("analyze", *args, "--pixel-size", "8 um", "--height-unit", "m")
    assert code == 2 and "Traceback" not in stderr and "zip/NPZ archive" in stderr
    assert "e" in json.loads(stdout)["summary"] and (out / "results.json").exists()


def test_engine_comparison(drops: dict, scans: dict, rod: Any) -> None:
    """With flat=, the engine runs with the measured initial state."""
    d = drops[45]
    res = analyze(
        d.c3d, scans[45].files["x3p"], rod, geometry=d.geometry, flat="aisi-1010", n_samples=1000
    )
    assert "model" not in res.errors, res.errors
    assert res.model is not None and res.model["law"] == "ghaednia"
    for key in ("e", "delta_p", "sliding_length", "duration"):
        assert math.isfinite(res.model[key])
    if d.truth.source == "engine":  # the same engine, the measured inputs: the same e
        assert res.model["e"] == pytest.approx(d.truth.e, abs=0.02)


# ---------------------------------------------------------------------------------------------
# plausibility of the dent, bad arguments, --out
# ---------------------------------------------------------------------------------------------


@pytest.fixture(scope="module")
def plain_scan(tmp_path_factory: pytest.TempPathFactory, scans: dict) -> tuple[Path, float, Any]:
    """The 20 deg dent as a plain .npy height map in metres (and its pixel size, truth)."""
    sc = scans[20]
    p = tmp_path_factory.mktemp("plain") / "dent_m.npy"
    np.save(p, sc.z)
    return p, sc.dx, sc.truth


@pytest.mark.parametrize(
    ("options", "needles"),
    [
        # a scan stored in metres read as um: 2.2e-11 m
        ({"height_unit": "um"}, ("below 1 nm", "height unit (read as 'um')")),
        # a pixel of 8 mm: the dent 1.2 m wide and 2.6 m long
        (
            {"pixel_size": "8 mm"},
            ("wider than the tip's diameter 2R = 17.6 mm", "longer than the rod", "pixel size"),
        ),
        # a pixel of 80 nm: the dent 12 um wide but 22 um deep
        ({"pixel_size": "80 nm"}, ("nm at that width", "pixel size (80 nm")),
    ],
)
def test_impossible_dents_are_refused(
    plain_scan: tuple[Path, float, Any], options: dict[str, Any], needles: tuple[str, ...]
) -> None:
    path, dx, _ = plain_scan
    res = analyze(None, path, **{"pixel_size": dx, "height_unit": "m", **options})
    assert set(res.errors) == {"scan"} and res.dent is None
    assert "impossible dent for this rod" in res.errors["scan"]
    for needle in needles:
        assert needle in res.errors["scan"]


def test_implausible_dents_are_doubted(plain_scan: tuple[Path, float, Any]) -> None:
    """A scan in metres read as mm: a dent of 22 nm, measured, but not ok: the doubt names the
    unit (the plain warnings it sums up are not repeated)."""
    path, dx, truth = plain_scan
    with pytest.warns(ImplausibleInputWarning, match="a height unit 1000 times too small"):
        res = analyze(None, path, pixel_size=dx, height_unit="mm")
    assert not res.ok and res.dent is not None
    assert res.dent.delta_p.value == pytest.approx(truth.groove.depth * 1e-3, rel=0.02)
    text = " ".join(res.doubts)
    assert "times shallower than the tip's cap there" in text
    assert "height unit (read as 'mm')" in text
    assert not any("shallower than 0.1 um" in w for w in res.warnings)
    good = analyze(None, path, pixel_size=dx, height_unit="m")
    assert good.ok and not good.warnings


def test_a_shallow_dent_is_said_once(
    plain_scan: tuple[Path, float, Any], drops: dict, rod: Any
) -> None:
    """A 22 nm dent with the markers: the scan stage's doubt names the height unit, and the
    inversion's warnings join the result's (``inversion: ...``) without repeating the shallow
    dent; the doubt is the one Python warning."""
    path, dx, _ = plain_scan
    d = drops[20]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        res = analyze(
            d.c3d, path, rod, geometry=d.geometry, pixel_size=dx, height_unit="mm", n_samples=500
        )
    assert res.inversion is not None, res.errors
    unit = [w for w in caught if "a height unit 1000 times too small" in str(w.message)]
    assert len(unit) == 1
    assert not any("shallower than 0.1 um" in w for w in res.warnings)
    assert sum("height unit (read as 'mm')" in x for x in res.doubts) == 1


def test_sign_flipped_scan_is_refused_then_read_over(
    tmp_path: Path, plain_scan: tuple[Path, float, Any]
) -> None:
    """Depths stored as heights once gave delta_p -93 % with only a warning."""
    path, dx, truth = plain_scan
    flipped = tmp_path / "flipped.npy"
    np.save(flipped, -np.load(path))
    res = analyze(None, flipped, pixel_size=dx, height_unit="m")
    assert set(res.errors) == {"scan"} and res.dent is None
    assert "bump 22 um high, not a dent" in res.errors["scan"]
    assert "sign-flipped" in res.errors["scan"] and "--flip-heights" in res.errors["scan"]
    over = analyze(None, flipped, pixel_size=dx, height_unit="m", flip_heights=True)
    assert over.ok and over.dent is not None
    assert over.dent.delta_p.value == pytest.approx(truth.groove.depth, rel=0.02)


def test_corrupt_heights_are_not_taken_for_a_flipped_scan(
    tmp_path: Path, plain_scan: tuple[Path, float, Any]
) -> None:
    """Damaged bytes in the middle of a scan give absurd heights (1e177 m, as 16 flipped bytes
    do): a corrupt file, not a bump to read the other way up."""
    path, dx, _ = plain_scan
    heights = np.load(path)
    heights.flat[heights.size // 2 : heights.size // 2 + 2] = (1.7e177, -4.4e182)
    damaged = tmp_path / "damaged.npy"
    np.save(damaged, heights)
    res = analyze(None, damaged, pixel_size=dx, height_unit="m")
    assert set(res.errors) == {"scan"} and res.dent is None
    message = res.errors["scan"]
    assert message.startswith(f"{damaged}: ") and "implausible height value(s)" in message
    assert "corrupt" in message and "sign-flipped" not in message


PLAIN_8MM = ("--pixel-size", "8 mm", "--height-unit", "m")


def test_cli_refuses_impossible_dent(
    cli_main: Callable[..., tuple[int, str, str]],
    plain_scan: tuple[Path, float, Any],
    junk: dict[str, Path],
) -> None:
    path, _, _ = plain_scan
    code, _, stderr = cli_main("analyze", str(junk["c3d"]), str(path), *PLAIN_8MM)
    assert code == 2 and "Traceback" not in stderr
    err = stderr.strip().splitlines()
    assert len(err) == 1 and "scan: " in err[0] and "wider than the tip's diameter" in err[0]


@pytest.mark.parametrize(
    ("kwargs", "error", "needle"),
    [
        ({"markers_path": 123, "scan_path": None}, TypeError, "markers_path must be a path"),
        ({"markers_path": None, "scan_path": 1.5}, TypeError, "scan_path must be a path"),
        ({"out_dir": 7}, TypeError, "out_dir must be a path"),
        ({"geometry": "M1"}, TypeError, "geometry must be a MarkerGeometry"),
        ({"n_samples": "many"}, ValueError, "n_samples must be an integer >= 100"),
        ({"strict": "yes"}, TypeError, "strict must be True or False"),
        ({"flip_heights": 1}, TypeError, "flip_heights must be True or False"),
        ({"law": 5}, TypeError, "law must be a contact law's name"),
        ({"height_unit": 6}, TypeError, "height_unit must be a unit name"),
        ({"pixel_size": []}, ValueError, "pixel_size"),
        ({"up": "sideways"}, ValueError, "up must be one of"),
        ({"kinematics_options": 3}, TypeError, "kinematics_options must be a mapping"),
        ({"dent_options": {"smoth": 2}}, ValueError, "dent_options: unknown option(s) ['smoth']"),
    ],
)
def test_bad_arguments_name_the_parameter(
    kwargs: dict[str, Any], error: type[Exception], needle: str
) -> None:
    """``analyze(123, None)`` once leaked pathlib's TypeError."""
    args = {"markers_path": None, "scan_path": None, **kwargs}
    with pytest.raises(error) as exc:
        analyze(**args)
    assert needle in str(exc.value)


def test_entry_points_name_a_wrong_argument() -> None:
    cases = [
        (lambda: read_markers(123), "path must be a path"),
        (lambda: read_scan(None), "path must be a path"),
        (lambda: measure_dent(np.zeros((9, 9))), "hm must be a HeightMap"),
        (lambda: level_plane(1), "hm must be a HeightMap"),
        (lambda: measure_impact(None, rod_properties(PAPER_ROD)), "tracks must be a MarkerTracks"),
        (lambda: check_rigidity(1), "tracks must be a MarkerTracks"),
        (lambda: fit_poses(1, np.zeros((3, 3))), "tracks must be a MarkerTracks"),
        (lambda: MarkerGeometry.from_mapping(1), "data must be a Mapping"),
    ]
    for call, needle in cases:
        with pytest.raises(TypeError, match=re.escape(needle)):
            call()


def test_out_dir_naming_a_file_is_refused_at_once(tmp_path: Path, scans: dict) -> None:
    taken = tmp_path / "taken"
    taken.write_text("x")
    for out in (taken, taken / "below"):
        with pytest.raises(ValueError, match=re.escape(f"out_dir {str(out)!r}")):
            analyze(None, scans[20].files["x3p"], out_dir=out)
    assert taken.read_text() == "x"


def test_the_papers_rod_by_name_as_on_the_command_line() -> None:
    """``rod="paper"`` is the paper's rod in Python too (``--rod paper`` is the CLI's default)."""
    from impactlab.experiment import analyze

    assert analyze(None, None, "paper").rod == analyze(None, None).rod
    assert analyze(None, None, " Paper ").rod["length"] == 0.3048
