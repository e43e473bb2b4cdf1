"""The help's layout says what to type: each command's whole summary in ``impactlab --help`` (and
in ``sweep --help``, ``fe --help``), a placeholder and "repeatable" for an option given once per
value (``--percentile PCT``, never ``<list[float]>``), and every option that takes a material
saying that it takes one by values or a TOML file, as each does."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
import typer
from typer.testing import CliRunner

from impactlab.cli import app

MATERIAL = "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3"


def _help(*command: str, width: int = 100) -> str:
    r = CliRunner().invoke(app, [*command, "--help"], terminal_width=width)
    assert r.exit_code == 0, r.output
    return r.output


def _commands(group: Any) -> dict[str, Any]:
    return group.commands  # type: ignore[no-any-return]


@pytest.mark.parametrize("group", [(), ("sweep",), ("fe",)])
def test_every_summary_is_whole_on_an_80_column_screen(group: tuple[str, ...]) -> None:
    root = typer.main.get_command(app)
    command = root
    for name in group:
        command = _commands(command)[name]
    listed = _help(*group, width=80).split("\nCommands:\n", 1)[1]
    for name, sub in _commands(command).items():
        assert sub.short_help, f"{' '.join((*group, name))} has no short_help"
        line = next(ln for ln in listed.splitlines() if ln.split()[:1] == [name])
        assert line.rstrip().endswith(f"  {sub.short_help}"), line  # whole, on its line
        assert not line.rstrip().endswith("..."), line


@pytest.mark.parametrize(
    ("command", "option", "metavar"),
    [
        ((), "--law-file", "FILE"),
        (("calibrate",), "-p, --param", "PARAM"),
        (("calibrate",), "-m, --model", "MODEL"),
        (("invert",), "--correlation", "PAIR"),
        (("sweep", "uncertainty"), "--percentile", "PCT"),
        (("sweep", "uncertainty"), "--output", "OUTPUT"),
        (("fe", "indent"), "--max", "DEPTH"),
        (("warm",), "--part", "PART"),
    ],
)
def test_a_repeatable_option_shows_a_placeholder(
    command: tuple[str, ...], option: str, metavar: str
) -> None:
    text = _help(*command)
    assert "<list[" not in text, text
    found = re.search(rf"^  {re.escape(option)} {metavar}\s+(.*?)(?=^  -|\Z)", text, re.M | re.S)
    assert found is not None, text
    assert "repeatable" in found.group(1).lower(), found.group(1)


def test_counts_show_a_placeholder_not_a_range_type() -> None:
    for command in (("invert",), ("sweep", "run"), ("sweep", "uncertainty")):
        assert " range>" not in _help(*command), command
    assert "--worker-timeout SECONDS" in _help("sweep", "run")


@pytest.mark.parametrize(
    ("command", "option"),
    [(("invert",), "--flat"), (("fe", "indent"), "--flat"), (("fe", "indent"), "--body")],
)
def test_a_material_option_says_it_takes_values_or_a_file(
    command: tuple[str, ...], option: str
) -> None:
    text = " ".join(_help(*command).split("\nOptions:\n", 1)[1].split())
    found = re.search(rf" {re.escape(option)}[ ,]", text)
    assert found is not None, text
    said = text[found.start() : found.start() + 400]
    assert "preset" not in said[:60], said
    assert "a library name" in said and "properties" in said and "a TOML file" in said, said


def test_invert_takes_a_flat_by_values_and_by_file(cli_main: Any, tmp_path: Path) -> None:
    mat = tmp_path / "mat.toml"
    mat.write_text('name = "mine"\nE = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = "2700 kg/m^3"\n')
    for flat in (MATERIAL, str(mat), "al-6061-t6"):
        code, out, err = cli_main("invert", "--case", "paper-20", "--flat", flat, "--json")
        assert code == 0, err
        assert json.loads(out)["duration"]["value"] > 0


def test_fe_takes_its_materials_by_values_and_by_file(tmp_path: Path) -> None:
    from impactlab.cli.fe import _material

    mat = tmp_path / "mat.toml"
    mat.write_text('name = "mine"\nE = "69 GPa"\nnu = 0.33\nSy = "276 MPa"\nrho = "2700 kg/m^3"\n')
    for label in ("flat", "body"):
        made = _material(MATERIAL, None, None, None, label)
        assert made.E == pytest.approx(69e9) and made.yield_strength == pytest.approx(276e6)
        assert _material(str(mat), None, None, None, label).name == "mine"


def test_materials_help_lists_the_optional_keys_as_simulate_does() -> None:
    optional = "HB=, n=, brittle=yes optional"
    assert optional in " ".join(_help("materials").split())
    assert optional in " ".join(_help("simulate").split())
