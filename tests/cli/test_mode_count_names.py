"""The flexible rod's mode counts under FlexibleRod's names too: ``n_axial`` / ``n_bending`` in a
``--config`` file (as in a study file), ``--n-axial`` / ``--n-bending`` on the command line,
each the same drop as ``modes_axial`` / ``--modes-axial``; a count given under both names in
one file is refused, and an error names the key as the file spells it."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

KINEMATICS = 'angle = "20 deg"\nvy = "-1.41 m/s"\nmu = 0.2\n'
FLEX = ("simulate", "rod", "--flexible")


def _modes(cli_main: CliMain, *args: str) -> tuple[int, int]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    body = json.loads(out)["input"]["body"]
    return body["n_axial"], body["n_bending"]


@pytest.mark.parametrize("command", [("drop",), FLEX])
def test_a_config_file_takes_flexible_rods_names(
    cli_main: CliMain, tmp_path: Path, command: tuple[str, ...]
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + "n_axial = 1\nn_bending = 2\n")
    assert _modes(cli_main, *command, "--config", str(cfg)) == (1, 2)
    cfg.write_text(KINEMATICS + "modes_axial = 1\nn_bending = 3\n")  # the names mixed
    assert _modes(cli_main, *command, "--config", str(cfg)) == (1, 3)
    # the command line wins over the file's key, whatever its name
    assert _modes(cli_main, *command, "--config", str(cfg), "--modes-bending", "2") == (1, 2)


@pytest.mark.parametrize("command", [("drop",), FLEX])
def test_the_options_other_spelling(cli_main: CliMain, command: tuple[str, ...]) -> None:
    args = (*command, "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")
    assert _modes(cli_main, *args, "--n-axial", "1", "--n-bending", "2") == (1, 2)
    assert _modes(cli_main, *args, "--n-axial", "2", "--modes-bending", "3") == (2, 3)


def test_both_names_in_one_file_are_refused(cli_main: CliMain, tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + "n_axial = 1\nmodes_axial = 2\n")
    code, out, err = cli_main("drop", "--config", str(cfg))
    assert code == 2 and out == ""
    assert err.strip() == (
        f"error: modes_axial and n_axial in {cfg}: they are one (n_axial is the other name of "
        "modes_axial); give one"
    )


def test_an_error_names_the_key_as_the_file_spells_it(cli_main: CliMain, tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + "n_bending = 2.5\n")
    code, _, err = cli_main("drop", "--config", str(cfg))
    assert code == 2
    assert err.strip() == f"error: n_bending (in {cfg}) must be an integer >= 0, got 2.5"
    cfg.write_text(KINEMATICS + "rigid = true\nn_axial = 3\n")
    code, _, err = cli_main("drop", "--config", str(cfg))
    assert code == 2 and f"n_axial (in {cfg}): a rigid rod has no modes" in err, err


def test_the_tip_radius_alias_still_reads_as_radius(cli_main: CliMain, tmp_path: Path) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(KINEMATICS + 'rigid = true\ntip_radius = "5 mm"\nmass = "0.1 kg"\n')
    code, out, err = cli_main("drop", "--config", str(cfg), "--json")
    assert code == 0, err
    assert json.loads(out)["input"]["body"]["tip_radius"]["value"] == pytest.approx(0.005)
    cfg.write_text(KINEMATICS + 'radius = "5 mm"\ntip_radius = "5 mm"\n')
    code, _, err = cli_main("drop", "--config", str(cfg))
    assert code == 2 and "radius and tip_radius in" in err and "give one" in err, err


@pytest.mark.parametrize("command", ["drop", "simulate"])
def test_the_help_shows_both_spellings(cli_main: CliMain, command: str) -> None:
    code, out, _ = cli_main(command, "--help")
    assert code == 0
    flat = " ".join(out.split())
    assert "--modes-axial, --n-axial" in flat and "--modes-bending, --n-bending" in flat
    assert "n_axial" in flat and "n_bending" in flat
