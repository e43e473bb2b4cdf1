"""``impactlab simulate``: summary, JSON, config file, plots, one-line errors."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import pytest
from typer.testing import CliRunner

from impactlab.bodies import PAPER_ROD, Rod
from impactlab.cli import app, main
from impactlab.dynamics import simulate
from impactlab.flags import ResultFlag, messages
from impactlab.friction import DEFAULT_MU

runner = CliRunner()
ROD = ["simulate", "rod", "--angle", "20 deg"]


def test_json_matches_the_api() -> None:
    res = runner.invoke(
        app, ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--json"]
    )
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    r = simulate(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    assert data["e"]["value"] == pytest.approx(r.e, rel=1e-12)
    assert data["delta_p"] == {"value": pytest.approx(r.delta_p, rel=1e-12), "unit": "m"}
    assert data["regime"] == "slip"


def test_default_mu_is_the_api_default_and_is_printed() -> None:
    args = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s"]
    res = runner.invoke(app, [*args, "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    r = simulate(PAPER_ROD, angle=math.radians(20), velocity=(0.0, -1.41))
    assert data["mu"]["value"] == DEFAULT_MU == r.mu
    assert data["e"]["value"] == r.e
    text = runner.invoke(app, args).output
    assert "mu" in text


def test_angle_units_parse() -> None:
    a = runner.invoke(app, ["simulate", "rod", "--angle", "20 deg", "--vy", "-1410 mm/s", "--json"])
    b = runner.invoke(
        app, ["simulate", "rod", "--angle", "0.3490658503988659 rad", "--vy", "-1.41", "--json"]
    )
    assert a.exit_code == 0 and b.exit_code == 0, (a.output, b.output)
    e_a, e_b = (json.loads(x.stdout)["e"]["value"] for x in (a, b))
    assert e_a == pytest.approx(e_b, rel=1e-9)


def test_config_file_and_plots(tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(
        '[simulate]\nbody = "sphere"\nradius = "5 mm"\nvy = "-1 m/s"\n'
        'vx = "0.2 m/s"\nfriction = "mindlin"\nmu = 0.3\nlaw = "hertz"\n'
    )
    res = runner.invoke(
        app, ["simulate", "--config", str(cfg), "--plot", "--out", str(tmp_path / "figs")]
    )
    assert res.exit_code == 0, res.output
    assert "e_energy" in res.output
    for name in ("force_time", "force_penetration", "contact_path"):
        for ext in ("png", "pdf"):
            f = tmp_path / "figs" / f"impact_{name}.{ext}"
            assert f.is_file() and f.stat().st_size > 1000
    assert not list((tmp_path / "figs").glob("impact_dent.*"))  # hertz leaves no dent
    assert json.loads((tmp_path / "figs" / "impact_result.json").read_text())["law"] == "hertz"


@pytest.mark.parametrize(
    ("args", "match"),
    [
        ([*ROD, "--vy", "1.0"], "does not approach"),
        ([*ROD, "--vy", "-1", "--friction", "foo"], "unknown friction model"),
        ([*ROD, "--vy", "-1", "--mu", "-0.5"], "mu must be >= 0"),
        (["simulate", "cube", "--vy", "-1"], "body must be 'rod' or 'sphere'"),
        (ROD, "--vy is required"),
        ([*ROD, "--vy", "-1 kg"], "wrong dimension"),
        # a given value is used, never replaced by the paper's
        ([*ROD, "--vy", "-1", "--mass", "0 kg"], "--mass must be > 0, got '0 kg'"),
        ([*ROD, "--vy", "-1", "--radius", "0"], "--radius must be > 0"),
        ([*ROD, "--vy", "-1", "--length", "0 m"], "--length must be > 0"),
        ([*ROD, "--vy", "-1", "--inertia", "-1 kg*m^2"], "--inertia must be > 0"),
        (["simulate", "sphere", "--vy", "-1", "--mass", "0 kg"], "--mass must be > 0"),
        # a rod needs its angle, with a unit
        (["simulate", "rod", "--vy", "-1"], "a rod needs its angle to the flat: give --angle"),
        (["simulate", "rod", "--angle", "0.35", "--vy", "-1"], "--angle 0.35 has no unit"),
        (["simulate", "rod", "--angle", "20", "--vy", "-1"], "'20 deg' or '0.35 rad'"),
        # options that do not apply are refused
        (["simulate", "sphere", "--angle", "30 deg", "--vy", "-1"], "a sphere has no angle"),
        (["simulate", "sphere", "--length", "1 m", "--vy", "-1"], "--length: a sphere has no"),
        (["simulate", "sphere", "--constant-angle", "--vy", "-1"], "--constant-angle: a sphere"),
        ([*ROD, "--vy", "-1", "--out", "figs"], "--out applies only with --plot"),
    ],
)
def test_user_errors_are_one_line(
    args: list[str], match: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = _main(args, capsys)
    assert code == 2
    lines = err.strip().splitlines()
    assert len(lines) == 1 and match in lines[0], lines


def _main(args: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str, str]:
    """(exit status, stdout, stderr) of the installed entry point's ``main`` on ``args``."""
    old = sys.argv
    sys.argv = ["impactlab", *args]
    code = 0
    try:
        main()
    except SystemExit as exc:
        code = int(exc.code or 0)
    finally:
        sys.argv = old
    out = capsys.readouterr()
    return code, out.out, out.err


def test_config_values_are_used_and_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A zero in the config file is an error naming the key and the file, not the paper's value."""
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1 m/s"\nmass = "0 kg"\n')
    code, _, err = _main(["simulate", "--config", str(cfg)], capsys)
    assert code == 2 and "mass (in " in err and "case.toml) must be > 0" in err
    cfg.write_text('vy = "-1 m/s"\nangle = 20\n')
    code, _, err = _main(["simulate", "--config", str(cfg)], capsys)
    assert code == 2 and "angle (in " in err and "has no unit" in err


def test_given_sizes_are_used() -> None:
    res = runner.invoke(app, [*ROD, "--vy", "-1.41 m/s", "--mass", "0.3 kg", "--json"])
    assert res.exit_code == 0, res.output
    light = simulate(
        Rod(length=PAPER_ROD.length, tip_radius=PAPER_ROD.tip_radius, mass=0.3),
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    assert json.loads(res.stdout)["e"]["value"] == light.e


def test_sphere_prints_no_angle() -> None:
    res = runner.invoke(app, ["simulate", "sphere", "--vy", "-1 m/s"], env={"COLUMNS": "200"})
    assert res.exit_code == 0, res.output
    assert "angle" not in res.stdout and "nan" not in res.stdout


def test_out_naming_a_file_is_one_line(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """--out naming an existing file (or a path below one): one line naming it."""
    f = tmp_path / "taken.txt"
    f.write_text("x")
    for out in (f, f / "figs"):
        code, _, err = _main([*ROD, "--vy", "-1", "--plot", "--out", str(out)], capsys)
        assert code == 2 and str(out) in err and "Traceback" not in err
        assert len(err.strip().splitlines()) == 1


def test_flags_are_printed_and_in_the_json(capsys: pytest.CaptureFixture[str]) -> None:
    """A gravity-dominated impact: each warning on one line of stderr; the JSON carries the flags
    and the warnings."""
    code, out, err = _main([*ROD, "--vy", "-1e-9 m/s", "--mu", "0.2", "--json"], capsys)
    assert code == 0
    data = json.loads(out)
    assert data["flags"] == int(ResultFlag.GRAVITY_DOMINATED)
    assert data["warnings"] == list(messages(ResultFlag.GRAVITY_DOMINATED))
    assert err.splitlines() == [f"warning: {w}" for w in data["warnings"]]
    code, out, err = _main([*ROD, "--vy", "-1e-9 m/s", "--mu", "0.2"], capsys)
    assert code == 0 and "gravity_dominated" in out and err.startswith("warning: gravity")
    code, out, err = _main([*ROD, "--vy", "-1.41 m/s", "--json"], capsys)
    data = json.loads(out)  # the paper's case: only the law's range was left
    assert data["flags"] == int(ResultFlag.LAW_EXTRAPOLATED) and len(data["warnings"]) == 1
    assert err.splitlines() == [f"warning: {data['warnings'][0]}"]
    assert err.startswith("warning: law extrapolated: ") and "max delta/delta_c = " in err
