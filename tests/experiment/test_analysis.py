"""One call (API and command line) from the raw files to e, mu, delta_p, L_s, T and F."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest
from typer.testing import CliRunner

import impactlab.analytic as analytic
from impactlab.analytic import invert
from impactlab.cli import app
from impactlab.experiment import ExperimentError, analyze, rod_properties

GEOMETRY_TOML = """
[markers]
units = "mm"
M1 = [-30.0, 18.0, 0.0]
M2 = [-90.0, 0.0, 22.0]
M3 = [-130.0, -20.0, 4.0]
"""


@pytest.mark.parametrize("case", [20, 45])
def test_analyze_end_to_end(tmp_path: Path, drops: dict, scans: dict, rod: Any, case: int) -> None:
    d, sc = drops[case], scans[case]
    res = analyze(
        d.c3d, sc.files["x3p"], rod, geometry=d.geometry, out_dir=tmp_path / "out", n_samples=2000
    )
    assert res.ok, res.errors
    s = res.summary()
    assert abs(s["e"].value - d.truth.e) < 0.02
    assert abs(s["mu"].value - d.truth.mu) < 0.02
    g = sc.truth.groove
    assert s["delta_p"].value == pytest.approx(g.depth, rel=0.02)
    assert s["L_s"].value == pytest.approx(g.sliding_length, rel=0.05)
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
    assert abs(s["T"].value - ref.T) < 3.0 * s["T"].sigma + 0.02 * ref.T
    assert abs(s["F"].value - ref.F) < 3.0 * s["F"].sigma + 0.02 * ref.F
    saved = json.loads((tmp_path / "out" / "results.json").read_text())
    assert saved["summary"]["T"]["value"] == pytest.approx(s["T"].value)
    assert saved["errors"] == {}
    for name in ("dent.png", "kinematics.png"):
        assert (tmp_path / "out" / name).stat().st_size > 10_000


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
    assert "T" not in res.summary() and "L_s" in res.summary()


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
    assert data["summary"]["F"]["unit"] == "N"
    assert (out / "results.json").exists() and (out / "dent.png").exists()
    r2 = runner.invoke(app, ["analyze", str(d.c3d), str(sc.files["sdf"]), "--geometry", str(geo)])
    assert r2.exit_code == 0 and "delta_p" in r2.stdout and "T (Eq. 12)" in r2.stdout


def test_cli_bad_scan_exits_with_one_line(tmp_path: Path, drops: dict) -> None:
    geo = tmp_path / "geometry.toml"
    geo.write_text(GEOMETRY_TOML)
    bad = tmp_path / "dent.sdf"
    bad.write_text("aISO-1.0\nNumPoints = 10\n")
    out = tmp_path / "o"
    proc = subprocess.run(
        [
            sys.executable,
            "-m",
            "impactlab",
            "analyze",
            str(drops[20].c3d),
            str(bad),
            "--geometry",
            str(geo),
            "--out",
            str(out),
            "--json",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert proc.returncode == 2
    err = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(err) == 1 and err[0].startswith("error: scan:") and "dent.sdf" in err[0]
    assert "Traceback" not in proc.stderr
    data = json.loads(proc.stdout)  # the marker results are printed and saved
    assert "e" in data["summary"] and (out / "results.json").exists()


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
