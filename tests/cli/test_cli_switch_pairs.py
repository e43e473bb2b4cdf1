"""Every switch of ``simulate`` and ``drop`` has its opposite (``--gravity/--no-gravity``,
``--constant-angle/--no-constant-angle``, simulate's ``--flexible/--rigid``, drop's
``--rigid/--flexible``), so the command line undoes a ``--config`` file's ``true`` or ``false``
and a recorded input's (``--from``)."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

G = 9.80665
KINEMATICS = 'angle = "20 deg"\nvy = "-1.41 m/s"\nmu = 0.2\n'


def _input(cli_main: CliMain, *args: str) -> dict:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out)["input"]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", err
    assert err.startswith("error: "), err
    return err.strip()


def test_drop_undoes_the_files_switches(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + "rigid = true\ngravity = false\n")
    assert _input(cli_main, "drop", "--config", str(cfg))["gravity"]["value"] == 0.0
    on = _input(cli_main, "drop", "--config", str(cfg), "--gravity")
    assert on["gravity"]["value"] == G and on["body"]["type"] == "Rod"
    # --flexible over rigid = true: the flexible rod, whose inertia is not an option
    err = _error(cli_main, "drop", "--config", str(cfg), "--flexible", "--inertia", "0.003")
    assert "--inertia: the flexible rod's inertia" in err and "give --rigid" in err


def test_simulate_undoes_the_files_switches(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + "flexible = true\ngravity = false\nconstant_angle = true\n")
    err = _error(cli_main, "simulate", "rod", "--config", str(cfg))
    assert "constant_angle (in" in err  # the flexible rod's lever arms move
    rigid = _input(cli_main, "simulate", "rod", "--config", str(cfg), "--rigid")
    assert rigid["body"]["type"] == "Rod" and rigid["constant_angle"] is True
    assert rigid["gravity"]["value"] == 0.0
    args = ("simulate", "rod", "--config", str(cfg), "--rigid", "--gravity")
    undone = _input(cli_main, *args, "--no-constant-angle")
    assert undone["gravity"]["value"] == G and undone["constant_angle"] is False


def test_from_takes_either_switch_and_refuses_the_bodys(tmp_path: Path, cli_main: CliMain) -> None:
    code, out, err = cli_main(
        "simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--no-gravity", "--json"
    )
    assert code == 0, err
    record = tmp_path / "impact.json"
    record.write_text(out)
    again = _input(cli_main, "simulate", "--from", str(record), "--gravity", "--constant-angle")
    assert again["gravity"]["value"] == G and again["constant_angle"] is True
    record.write_text(json.dumps({"input": again}))
    back = _input(cli_main, "simulate", "--from", str(record), "--no-constant-angle")
    assert back["constant_angle"] is False and back["gravity"]["value"] == G
    for switch in ("--rigid", "--flexible"):
        err = _error(cli_main, "simulate", "--from", str(record), switch)
        assert err.startswith(f"error: {switch}: --from simulates the recorded body"), err


@pytest.mark.parametrize("command", ["simulate", "drop"])
def test_help_names_both_halves(cli_main: CliMain, command: str) -> None:
    code, out, _ = cli_main(command, "--help")
    assert code == 0
    for switch in ("--gravity", "--no-gravity"):
        assert switch in out
