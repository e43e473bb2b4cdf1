"""``impactlab simulate --from r.json`` with options on top of the recorded input: the recorded
input is the default of every option, the impact's options override it, the body's options are
refused (``impactlab.cli.simulate_from.FROM_RULE``)."""

from __future__ import annotations

import json
import math
import sys
from pathlib import Path

import pytest

import impactlab as il
from impactlab.cli import main
from impactlab.cli.simulate_from import FROM_RULE
from impactlab.materials import AL_6061_T6

ROD = ["simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2"]


def _cli(monkeypatch, capsys, *args: str) -> tuple[int, str, str]:
    monkeypatch.setattr(sys, "argv", ["impactlab", *args])
    try:
        main()
        code = 0
    except SystemExit as exc:
        code = int(exc.code or 0)
    out = capsys.readouterr()
    return code, out.out, out.err


def _json(monkeypatch, capsys, *args: str) -> dict:
    code, out, err = _cli(monkeypatch, capsys, *args, "--json")
    assert code == 0, err
    return json.loads(out)


@pytest.fixture
def saved(tmp_path: Path, monkeypatch, capsys) -> Path:
    path = tmp_path / "r.json"
    path.write_text(json.dumps(_json(monkeypatch, capsys, *ROD)))
    return path


def test_options_override_the_recorded_input(saved, monkeypatch, capsys) -> None:
    again = _json(monkeypatch, capsys, "simulate", "--from", str(saved), "--vy", "-2 m/s",
                  "--law", "brake")  # fmt: skip
    direct = _json(monkeypatch, capsys, *ROD[:4], "--vy", "-2 m/s", "--mu", "0.2",
                   "--law", "brake")  # fmt: skip
    assert again["input"] == direct["input"]
    assert again["e"] == direct["e"] and again["law"] == "brake"
    mu = _json(monkeypatch, capsys, "simulate", "--from", str(saved), "--mu", "0.3", "--vx",
               "0.1 m/s", "--no-gravity", "--flat", "al-6061-t6")  # fmt: skip
    rec = mu["input"]
    assert rec["mu"]["value"] == 0.3 and rec["gravity"]["value"] == 0.0
    assert rec["velocity"]["value"] == [0.1, -1.41]  # --vx replaced, the recorded vy kept
    assert rec["flat"]["name"] == AL_6061_T6.name
    assert rec["angle"]["value"] == pytest.approx(math.radians(20))
    turned = _json(monkeypatch, capsys, "simulate", "--from", str(saved), "--angle", "30 deg",
                   "--speed", "2 m/s", "--incidence", "10 deg")  # fmt: skip
    assert turned["input"]["angle"]["value"] == pytest.approx(math.radians(30))
    vx, vy = turned["input"]["velocity"]["value"]
    assert (vx, vy) == pytest.approx((2 * math.sin(math.radians(10)), -2 * math.cos(0.17453293)))


@pytest.mark.parametrize(
    ("extra", "says"),
    [
        (["sphere"], "the body: --from simulates the recorded body"),
        (["--material", "aisi-304"], "--material: --from simulates the recorded body"),
        (["--length", "200 mm", "--mass", "0.3 kg"], "--length, --mass: --from"),
        (["--flexible"], "--flexible: --from"),
        (["--rate", "johnson-cook"], "--rate: the recorded impact is not a drop"),
        (["--speed", "1 m/s"], "--speed and --incidence go together"),
        (["--vy", "-1 m/s", "--speed", "1 m/s", "--incidence", "5 deg"], "both given"),
        (["--angle", "100 deg"], "--angle must be in (0, 90] deg"),
    ],
)
def test_conflicting_options_are_refused(saved, monkeypatch, capsys, extra, says) -> None:
    args = ["simulate", *extra[:1], "--from", str(saved), *extra[1:]]
    if extra[0] != "sphere":
        args = ["simulate", "--from", str(saved), *extra]
    code, _, err = _cli(monkeypatch, capsys, *args)
    assert code != 0 and says in err and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1


def test_config_and_a_sphere_angle_are_refused(saved, tmp_path, monkeypatch, capsys) -> None:
    cfg = tmp_path / "c.toml"
    cfg.write_text("mu = 0.1\n")
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--from", str(saved), "--config",
                        str(cfg))  # fmt: skip
    assert code != 0 and "leave out --config" in err
    ball = il.simulate(il.Sphere(radius=0.003), velocity=(0.0, -1.0))
    path = tmp_path / "s.json"
    path.write_text(json.dumps(ball.to_dict()))
    code, _, err = _cli(monkeypatch, capsys, "simulate", "--from", str(path), "--angle", "9 deg")
    assert code != 0 and "the recorded body is a Sphere, which has no angle" in err


def test_a_new_law_drops_the_recorded_law_parameters(tmp_path, monkeypatch, capsys) -> None:
    ball = il.simulate(il.Sphere(radius=0.003), law="thornton", velocity=(0.0, -1.0),
                       law_params={"limit_pressure_ratio": 2.0})  # fmt: skip
    path = tmp_path / "s.json"
    path.write_text(json.dumps(ball.to_dict()))
    same = _json(monkeypatch, capsys, "simulate", "--from", str(path), "--vy", "-2 m/s")
    assert same["input"]["law_params"] == ball.input["law_params"]
    hertz = _json(monkeypatch, capsys, "simulate", "--from", str(path), "--law", "hertz")
    assert hertz["law"] == "hertz" and hertz["input"]["law_params"] is None


def test_the_rule_is_in_the_help(monkeypatch, capsys) -> None:
    code, out, _ = _cli(monkeypatch, capsys, "simulate", "--help")
    assert code == 0
    flat = " ".join(out.replace("│", " ").split())
    assert "the recorded input is the default of every option" in flat
    assert "the body is the recorded one" in FROM_RULE


def test_the_rule_names_every_drop_override() -> None:
    """Formerly the help named only --rate among a drop's overrides, while --stop, --time-limit and
    --rtol are taken too."""
    flat = " ".join(FROM_RULE.split())
    for option in ("--rtol", "--rate", "--stop", "--time-limit"):
        assert option in flat, option
