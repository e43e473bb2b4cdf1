"""A switch in a TOML input file is a TOML boolean: a quoted "false" is refused (Python would
read the non-empty string as true). Through the ``cli_main`` fixture."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]


@pytest.mark.parametrize(
    ("line", "key"),
    [('flexible = "false"', "flexible"), ('gravity = "no"', "gravity"),
     ('constant_angle = "no"', "constant_angle"), ("gravity = 0", "gravity")],
)  # fmt: skip
def test_simulate_refuses_a_switch_that_is_not_a_boolean(
    tmp_path: Path, cli_main: CliMain, line: str, key: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(f'angle = "30 deg"\nvy = "-2 m/s"\n{line}\n')
    code, _, err = cli_main("simulate", "rod", "--config", str(cfg))
    assert code == 2 and f"{key} in {cfg} must be true or false (a TOML boolean" in err


def test_invert_refuses_a_gravity_that_is_not_a_boolean(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "drop.toml"
    cfg.write_text(
        'angle = "20 deg"\nv_i = "-1.41 m/s"\ne = 0.5\nmu = 0.2\ndelta_p = "22 um"\n'
        'L_s = "1400 um"\ngravity = "false"\n'
    )
    code, _, err = cli_main("invert", "--file", str(cfg))
    assert code == 2 and "gravity in the measurement file must be true or false" in err
    cfg.write_text(cfg.read_text().replace('"false"', "false"))
    code, out, _ = cli_main("invert", "--file", str(cfg))
    assert code == 0 and "neglected" in out


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ('modes_axial = "x"', "modes_axial (in {cfg}) must be an integer >= 0, got 'x'"),
        ("modes_bending = 2.5", "modes_bending (in {cfg}) must be an integer >= 0, got 2.5"),
        ('damping = "x"', "damping (in {cfg}) must be a number in [0, 1), got 'x'"),
        ("vx = true", "vx (in {cfg}) must be a quantity in m/s, got True"),
    ],
)
def test_a_config_value_of_the_wrong_kind_is_named(
    tmp_path: Path, cli_main: CliMain, line: str, message: str
) -> None:
    """A mode count, a damping ratio or a quantity of the wrong TOML kind is one line naming
    the key and the file (not a TypeError traceback, nor a boolean read as 1 m/s)."""
    cfg = tmp_path / "case.toml"
    flexible = "flexible = true\n" if "vx" not in line else ""
    cfg.write_text(f'angle = "20 deg"\nvy = "-1.41 m/s"\n{flexible}{line}\n')
    code, _, err = cli_main("simulate", "--config", str(cfg))
    assert code == 2 and message.format(cfg=cfg) in err, err


def test_the_tip_radius_reads_under_either_name(tmp_path: Path, cli_main: CliMain) -> None:
    """The rod's tip radius is --radius or --tip-radius, radius or tip_radius in a config file
    (the name study files and [rod] tables use); a misspelt key gets the nearest known one."""
    cfg = tmp_path / "case.toml"
    for text in ('tip_radius = "5 mm"\n', ""):
        cfg.write_text(f'angle = "20 deg"\nvy = "-1 m/s"\nmass = "0.1 kg"\n{text}')
        extra = () if text else ("--tip-radius", "5 mm")
        code, out, err = cli_main("simulate", "--config", str(cfg), *extra, "--json")
        assert code == 0, err
        body = json.loads(out)["input"]["body"]
        assert body["tip_radius"] == {"value": 0.005, "unit": "m"}
    cfg.write_text('angle = "20 deg"\nvy = "-1 m/s"\nmuu = 0.2\n')
    code, _, err = cli_main("simulate", "--config", str(cfg))
    assert code == 2 and "unknown key(s) in the config file: muu (did you mean 'mu'?)" in err


def test_an_api_error_names_the_option_or_the_config_key(tmp_path: Path, cli_main: CliMain) -> None:
    """The engine's message names its parameter (``mu must be >= 0``); the command says how the
    user gave it: ``--mu`` on the command line, ``mu (in FILE)`` in a config file."""
    code, _, err = cli_main("simulate", "rod", "--angle", "20 deg", "--vy", "-1", "--mu", "-1")
    assert code == 2 and err.strip() == "error: --mu must be >= 0, got -1.0"
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1 m/s"\nmu = -1.0\n')
    code, _, err = cli_main("simulate", "--config", str(cfg))
    assert code == 2 and f"error: mu (in {cfg}) must be >= 0" in err


def test_simulate_takes_rtol_for_a_rigid_and_a_flexible_rod(cli_main: CliMain) -> None:
    """--rtol (as `drop --rtol`): recorded in the result's input, for either body."""
    for extra in ((), ("--flexible",)):
        code, out, err = cli_main("simulate", "rod", *extra, "--angle", "20 deg", "--vy", "-1.41",
                                  "--mu", "0.2", "--rtol", "1e-8", "--json")  # fmt: skip
        assert code == 0, err
        assert json.loads(out)["input"]["rtol"] == {"value": 1e-8, "unit": "1"}
