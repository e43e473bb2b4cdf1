"""A refusal's hint leads to a command that runs: ``impactlab simulate`` refuses a sphere's drop
options as a sphere's (never "add --flexible", which a sphere refuses too), points the modes
and their damping to ``--flexible`` only (``drop --rigid`` has none), and the rate, stop rule
and time limit to ``--flexible`` or ``impactlab drop --rigid``; each suggested command is run."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

ROD = ("simulate", "rod", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")
SPHERE = ("simulate", "sphere", "--radius", "5 mm", "--vy", "-1 m/s")
#: A short drop of the flexible rod (few modes).
FEW_MODES = ("--modes-axial", "1", "--modes-bending", "2")


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main(*args)
    assert code == 2 and out == "", err
    assert len(err.strip().splitlines()) == 1 and err.startswith("error: "), err
    return err.strip()


@pytest.mark.parametrize(
    "option",
    [
        ("--flexible",),
        ("--modes-axial", "3"),
        ("--damping", "0.01"),
        ("--rate", "cowper-symonds"),
        ("--stop", "flight"),
        ("--time-limit", "1 s"),
    ],
)
def test_a_spheres_drop_option_is_refused_as_a_spheres(
    cli_main: CliMain, option: tuple[str, ...]
) -> None:
    err = _error(cli_main, *SPHERE, *option)
    assert f"{option[0]}: a sphere has no drop options" in err, err
    assert "add --flexible" not in err and "drop --rigid" not in err, err


def test_a_spheres_rod_option_comes_first(cli_main: CliMain) -> None:
    err = _error(cli_main, *SPHERE, "--angle", "20 deg", "--stop", "flight")
    assert "--angle: a sphere has no angle, length or inertia (simulate a rod)" in err, err


@pytest.mark.parametrize("option", [("--modes-bending", "2"), ("--damping", "0.01")])
def test_modes_point_to_flexible_only_and_it_takes_them(
    cli_main: CliMain, option: tuple[str, ...]
) -> None:
    err = _error(cli_main, *ROD, *option)
    assert "add --flexible or leave it out" in err and "drop --rigid" not in err, err
    code, _, err = cli_main(*ROD, "--flexible", *FEW_MODES, *option, "--json")
    assert code == 0, err
    code, _, err = cli_main("drop", *ROD[2:], "--rigid", *option)
    assert code == 2 and "a rigid rod has no modes" in err, err  # why the hint omits it


@pytest.mark.parametrize(
    "option", [("--rate", "cowper-symonds"), ("--stop", "flight"), ("--time-limit", "1 s")]
)
def test_a_drops_options_point_to_both_and_both_take_them(
    cli_main: CliMain, option: tuple[str, ...]
) -> None:
    err = _error(cli_main, *ROD, *option)
    assert "add --flexible, run the rigid rod's drop (impactlab drop --rigid)" in err, err
    code, _, err = cli_main(*ROD, "--flexible", *FEW_MODES, *option, "--json")
    assert code == 0, err
    code, _, err = cli_main("drop", *ROD[2:], "--rigid", *option, "--json")
    assert code == 0, err


def test_a_config_files_key_points_to_the_files_switch(cli_main: CliMain, tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1.41 m/s"\nmodes_axial = 2\n')
    err = _error(cli_main, "simulate", "--config", str(cfg))
    assert f"modes_axial (in {cfg}): only a drop has modes" in err, err
    assert f"add flexible = true (in {cfg})" in err, err
