"""``impactlab drop --config FILE``: the drop's option keys from a TOML file, at the top level or
in a ``[drop]`` table, under the command line's options; errors name a value read from the
file as ``key (in FILE)``, as ``impactlab simulate --config`` does (``cli.config_file``)."""

from __future__ import annotations

import json
import math
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

#: A short drop: the rigid rod (no modes), the paper's 20 deg case.
CASE = 'angle = "20 deg"\nvy = "-1.41 m/s"\nmu = 0.2\nrigid = true\n'


def _input(cli_main: CliMain, *args: str) -> dict:
    code, out, err = cli_main("drop", *args, "--json")
    assert code == 0, err
    return json.loads(out)["input"]


def _error(cli_main: CliMain, *args: str) -> str:
    code, out, err = cli_main("drop", *args)
    assert code == 2 and out == "", err
    assert len(err.strip().splitlines()) == 1 and err.startswith("error: "), err
    return err.strip()


def test_the_files_values_are_used_and_the_command_line_wins(
    tmp_path: Path, cli_main: CliMain
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(CASE + 'tip_radius = "5 mm"\nflat = "al-6061-t6"\n')
    given = _input(cli_main, "--config", str(cfg))
    assert given["body"]["type"] == "Rod"  # rigid = true
    assert given["body"]["tip_radius"]["value"] == 0.005  # tip_radius: the option's radius
    assert given["angle"]["value"] == pytest.approx(math.radians(20), rel=1e-15)
    assert given["velocity"]["value"] == [0.0, -1.41] and given["mu"]["value"] == 0.2
    assert given["flat"]["name"].startswith("aluminium 6061-T6")
    over = _input(
        cli_main, "--config", str(cfg), "--mu", "0.1", "--vy", "-2 m/s", "--radius", "6 mm"
    )
    assert over["mu"]["value"] == 0.1 and over["velocity"]["value"] == [0.0, -2.0]
    assert over["body"]["tip_radius"]["value"] == 0.006
    assert over["angle"] == given["angle"] and over["flat"] == given["flat"]  # kept from the file
    record = tmp_path / "drop.json"
    record.write_text(json.dumps({"input": given}))
    err = _error(cli_main, "--from", str(record), "--config", str(cfg))
    assert "--config and --from" in err and "leave out --config" in err


def test_a_drop_table_beside_a_simulate_table(tmp_path: Path, cli_main: CliMain) -> None:
    """One file for both commands: each reads its own table."""
    cfg = tmp_path / "both.toml"
    cfg.write_text(f'[drop]\n{CASE}\n[simulate]\nangle = "30 deg"\nvy = "-1 m/s"\n')
    assert _input(cli_main, "--config", str(cfg))["angle"]["value"] == pytest.approx(
        math.radians(20), rel=1e-15
    )
    code, out, err = cli_main("simulate", "--config", str(cfg), "--json")
    assert code == 0, err
    assert json.loads(out)["input"]["angle"]["value"] == pytest.approx(math.radians(30), rel=1e-15)


@pytest.mark.parametrize(
    ("text", "said"),
    [
        # simulate's table alone: its keys describe simulate's body, never the drop's
        (
            '[simulate]\nangle = "20 deg"\nvy = "-1 m/s"\n',
            "[simulate] in {cfg} is impactlab simulate's table; give impactlab drop's keys in a "
            "[drop] table (a file may hold both) or at the top level",
        ),
        (
            'mu = 0.2\n[drop]\nangle = "20 deg"\nvy = "-1 m/s"\n',
            "mu in {cfg}: beside a [drop] table the top level is not read; move it into [drop]",
        ),
        ("drop = 3\n", "drop in {cfg} must be a table, [drop], got 3"),
        ("angle = \n", "--config '{cfg}' is not valid TOML: Invalid value (at line 1, column 9)"),
    ],
)
def test_the_files_form_is_checked(tmp_path: Path, cli_main: CliMain, text: str, said: str) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(text)
    assert said.format(cfg=cfg) in _error(cli_main, "--config", str(cfg))


def test_an_unknown_key_gets_the_nearest_or_why(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(CASE + "muu = 0.2\nflexible = true\n")
    err = _error(cli_main, "--config", str(cfg))
    said = (
        "unknown key(s) in the config file: flexible (impactlab simulate's: the drop's rod is "
        "flexible unless rigid = true), muu (did you mean 'mu'?); known: angle, "
    )
    assert said in err
    cfg.write_text(CASE + 'flat_E = "69 GPa"\n')
    err = _error(cli_main, "--config", str(cfg))
    assert "flat_E in the config file: give a material whole" in err


@pytest.mark.parametrize(
    ("line", "said"),
    [
        ('mass = "0 kg"', "mass (in {cfg}) must be > 0, got '0 kg'"),
        ("angle = 20", "angle (in {cfg}) 20 has no unit"),
        ('rigid = "true"', "rigid in {cfg} must be true or false (a TOML boolean"),
        (
            "modes_axial = 4",
            "modes_axial (in {cfg}): a rigid rod has no modes; leave out rigid (in {cfg})",
        ),
        ("law = 3", "law (in {cfg}) must be text, a name in quotes, got 3"),
        ('mu = "x"', "mu (in {cfg}) must be a number, got 'x'"),
        ("mu = -1.0", "mu (in {cfg}) must be >= 0"),  # the engine's words, the key's name
        ('t_max = "1 us"', "raise t_max (in {cfg})"),  # a drop's error: the key's name
        (
            'rate = "cowper-symonds"\nflat = "al-6061-t6"',
            "rate (in {cfg}) cowper-symonds: its constants are fitted for",
        ),
    ],
)
def test_a_bad_value_names_the_key_and_the_file(
    tmp_path: Path, cli_main: CliMain, line: str, said: str
) -> None:
    cfg = tmp_path / "case.toml"
    keys = {x.split(" = ")[0] for x in line.splitlines()}  # in place of the case's
    lines = [x for x in CASE.splitlines() if x.split(" = ")[0] not in keys]
    cfg.write_text("\n".join([*lines, line]) + "\n")
    assert said.format(cfg=cfg) in _error(cli_main, "--config", str(cfg))


def test_a_flexible_rods_option_in_the_file_is_its_key(tmp_path: Path, cli_main: CliMain) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text('angle = "20 deg"\nvy = "-1.41 m/s"\ninertia = "0.004 kg*m^2"\n')
    err = _error(cli_main, "--config", str(cfg))
    assert err.startswith(f"error: inertia (in {cfg}): the flexible rod's inertia follows")


def test_the_help_says_the_tables(cli_main: CliMain) -> None:
    code, out, _ = cli_main("drop", "--help")
    flat = " ".join(out.replace("│", " ").split())
    assert code == 0 and "in a [drop] table; options given here win" in flat
    assert "a [simulate] table alone is refused" in flat


@pytest.mark.parametrize(
    ("text", "said"),
    [
        ("simulate = 3\n", "simulate in {cfg} must be a table, [simulate], got 3"),
        (
            'mu = 0.2\n[simulate]\nangle = "20 deg"\n',
            "mu in {cfg}: beside a [simulate] table the top level is not read; move it into "
            "[simulate]",
        ),
        (
            '[drop]\nangle = "20 deg"\n',
            "[drop] in {cfg} is impactlab drop's table; give impactlab simulate's keys in a "
            "[simulate] table (a file may hold both) or at the top level",
        ),
    ],
    ids=["not-a-table", "keys-beside", "drop-table-alone"],
)
def test_simulate_reads_its_table_by_the_same_rule(
    tmp_path: Path, cli_main: CliMain, text: str, said: str
) -> None:
    cfg = tmp_path / "case.toml"
    cfg.write_text(text)
    code, out, err = cli_main("simulate", "--config", str(cfg), "--vy", "-1 m/s")
    assert (code, out) == (2, "")
    assert err == f"error: {said.format(cfg=cfg)}\n"
