"""A drop's time limit on the command line is ``--time-limit`` (the ``time_limit`` key of a
``--config`` file, ``input.time_limit`` of ``--json``); ``--t-max`` and the key ``t_max``, its
names before 0.3, are still read, with one line on stderr, to the same result; both given
are refused naming both; ``--help`` shows ``--time-limit`` only; a record of ``drop --json``
that says ``t_max`` runs again with ``--from``."""

from __future__ import annotations

import json
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]

#: A short drop: the rigid rod (no modes), the paper's 20 deg case.
DROP = ("drop", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2", "--rigid")
#: The flexible rod's drop through simulate, with few modes.
FLEX = ("simulate", "rod", "--flexible", "--angle", "20 deg", "--vy", "-1.41 m/s", "--mu", "0.2")
FLEX += ("--modes-axial", "1", "--modes-bending", "2")
#: The one line that says the option's new name.
SAID = "warning: --t-max is renamed --time-limit (impactlab 0.3); the old name goes in 0.4"


def _json(cli_main: CliMain, *args: str) -> tuple[dict, str]:
    code, out, err = cli_main(*args, "--json")
    assert code == 0, err
    return json.loads(out), err


def _error(cli_main: CliMain, *args: str, said: str | None = None) -> str:
    """The one-line error of ``args``, after the line ``said`` of an old name where given."""
    code, out, err = cli_main(*args)
    lines = err.strip().splitlines()
    if said is not None:
        assert lines[:1] == [said], err
        lines = lines[1:]
    assert code == 2 and out == "", err
    assert len(lines) == 1 and lines[0].startswith("error: "), err
    return lines[0]


@pytest.mark.parametrize("command", [DROP, FLEX], ids=["drop", "simulate"])
def test_t_max_is_read_as_time_limit_with_one_line(cli_main: CliMain, command: tuple) -> None:
    new, base = _json(cli_main, *command, "--time-limit", "2 s")  # base: the result's warnings
    assert new["input"]["time_limit"] == {"value": 2.0, "unit": "s"} and "--t-max" not in base
    old, err = _json(cli_main, *command, "--t-max", "2 s")
    assert err.splitlines() == [SAID, *base.splitlines()]
    assert old["input"] == new["input"] and "t_max" not in old["input"]
    assert old["e"] == new["e"] and old["dent_depth"] == new["dent_depth"]
    err = _error(cli_main, *command, "--t-max", "1 us", said=SAID)  # it names the new option
    assert err.endswith("raise --time-limit")


@pytest.mark.parametrize("command", [DROP, FLEX], ids=["drop", "simulate"])
def test_both_options_are_refused_naming_both(cli_main: CliMain, command: tuple) -> None:
    err = _error(cli_main, *command, "--time-limit", "1 s", "--t-max", "1 s")
    assert err == (
        "error: --time-limit and --t-max: --t-max is the name of --time-limit before impactlab "
        "0.3; give --time-limit only"
    )


@pytest.mark.parametrize("command", [("drop",), ("simulate",)])
def test_the_help_shows_the_new_name_only(cli_main: CliMain, command: tuple) -> None:
    code, out, _ = cli_main(*command, "--help")
    assert code == 0 and "--time-limit" in out and "--t-max" not in out


@pytest.mark.parametrize("command", ["drop", "simulate"])
def test_a_config_files_t_max_is_read_as_time_limit(
    tmp_path: Path, cli_main: CliMain, command: str
) -> None:
    cfg = tmp_path / "case.toml"
    case = 'angle = "20 deg"\nvy = "-1.41 m/s"\nmu = 0.2\n'
    case += "rigid = true\n" if command == "drop" else "flexible = true\nmodes_axial = 1\n"
    cfg.write_text(case + 'time_limit = "2 s"\n')
    new, base = _json(cli_main, command, "--config", str(cfg))
    assert new["input"]["time_limit"]["value"] == 2.0 and "t_max" not in base
    cfg.write_text(case + 't_max = "2 s"\n')
    old, err = _json(cli_main, command, "--config", str(cfg))
    said = f"warning: t_max (in {cfg}) is renamed time_limit (impactlab 0.3); the old name goes"
    assert err.splitlines() == [f"{said} in 0.4", *base.splitlines()]
    assert old["input"] == new["input"] and old["e"] == new["e"]
    cfg.write_text(case + 't_max = "1 us"\n')
    err = _error(cli_main, command, "--config", str(cfg), said=f"{said} in 0.4")
    assert err.endswith(f"raise t_max (in {cfg})")  # as the file says it
    cfg.write_text(case + 't_max = "1 s"\ntime_limit = "1 s"\n')
    err = _error(cli_main, command, "--config", str(cfg))
    assert err == (
        f"error: time_limit and t_max in {cfg}: t_max is the name of time_limit before "
        "impactlab 0.3; give time_limit only"
    )


def test_a_record_that_says_t_max_runs_again(tmp_path: Path, cli_main: CliMain) -> None:
    """drop --json of a version before 0.3 recorded input.t_max: --from reads it as time_limit,
    without a word, and --t-max on top of it is the new option's."""
    data, base = _json(cli_main, *DROP, "--time-limit", "2 s")
    data["input"]["t_max"] = data["input"].pop("time_limit")
    record = tmp_path / "drop.json"
    record.write_text(json.dumps(data))
    again, err = _json(cli_main, "drop", "--from", str(record))
    assert err == base and again["input"]["time_limit"]["value"] == 2.0
    assert again["e"] == data["e"] and "t_max" not in again["input"]
    over, err = _json(cli_main, "drop", "--from", str(record), "--t-max", "1 s")
    assert err.splitlines() == [SAID, *base.splitlines()]
    assert over["input"]["time_limit"]["value"] == 1.0
