"""The examples in every command's ``--help`` are commands the command line takes: each names an
existing command and only options of that command, with no more arguments than it has; the
cheap ones run as written (from the repository's root, whose examples/ they name)."""

from __future__ import annotations

import re
import shlex
from pathlib import Path
from typing import Any

import pytest
import typer

from impactlab.cli import app

ROOT = Path(__file__).parents[2]


def _commands() -> dict[str, Any]:
    """Every command of ``impactlab`` by its words ("sweep run"), groups included."""
    found: dict[str, Any] = {}

    def walk(cmd: Any, words: tuple[str, ...]) -> None:
        found[" ".join(words)] = cmd
        if hasattr(cmd, "commands"):  # a group
            for name, sub in cmd.commands.items():
                walk(sub, (*words, name))

    walk(typer.main.get_command(app), ())
    return found


COMMANDS = _commands()


def _help(words: str) -> str:
    cmd = COMMANDS[words]
    with typer.Context(cmd, info_name=f"impactlab {words}".strip()) as ctx:
        return cmd.get_help(ctx)


def _examples(text: str) -> list[str]:
    """The commands in a help's Example(s) part: from "Example" to the options, lines starting
    with "impactlab" (with their backslash continuations; "; " between two on one line)."""
    part = text.split("Example", 1)[1] if "Example" in text else ""
    part = part.split("\nOptions:")[0].split("\nArguments:")[0]
    lines: list[str] = []
    joined = ""
    for raw in part.splitlines():
        line = raw.strip().removeprefix("s").removeprefix(":").strip()
        if joined:
            joined += " " + line
        elif line.startswith("impactlab "):
            joined = line
        else:
            continue
        if joined.endswith("\\"):
            joined = joined[:-1].rstrip()
            continue
        lines.extend(c.strip() for c in joined.split("; "))
        joined = ""
    return lines


def _resolve(args: list[str]) -> tuple[str, Any, list[str]]:
    """The command that ``impactlab ARGS`` runs and the arguments left for it (``impactlab
    sweep STUDY.toml`` is ``sweep run``)."""
    words: list[str] = []
    while args and " ".join([*words, args[0]]) in COMMANDS:
        words.append(args.pop(0))
    if words == ["sweep"] and args and args[0].endswith(".toml"):
        words.append("run")
    name = " ".join(words)
    return name, COMMANDS[name], args


ALL = [(words, ex) for words in COMMANDS for ex in _examples(_help(words))]


def test_every_command_that_runs_something_shows_an_example() -> None:
    bare = [w for w, cmd in COMMANDS.items() if not hasattr(cmd, "commands")]
    assert sorted(w for w in bare if not _examples(_help(w))) == []


@pytest.mark.parametrize(("words", "example"), ALL, ids=[e for _, e in ALL])
def test_each_example_names_options_the_command_has(words: str, example: str) -> None:
    args = shlex.split(example)[1:]
    name, cmd, rest = _resolve(args)
    assert name, example
    options = {o for p in cmd.params for o in (*p.opts, *p.secondary_opts)}
    arguments = [p for p in cmd.params if p.param_type_name == "argument"]
    values = [p for p in cmd.params if p.param_type_name == "option" and not p.is_flag]
    takes_value = {o for p in values for o in p.opts}
    positional, i = [], 0
    while i < len(rest):
        token = rest[i]
        if token.startswith("-") and not token.lstrip("-")[:1].isdigit():
            assert token.split("=")[0] in options, f"{example}: {name} has no option {token}"
            i += 2 if token in takes_value else 1
            continue
        positional.append(token)
        i += 1
    assert len(positional) <= len(arguments), f"{example}: too many arguments {positional}"


CHEAP = [
    'impactlab laws jackson-green --radius "8.8 mm" --json',
    "impactlab materials --json",
    "impactlab materials 6061-t6",
    'impactlab invert --angle "20 deg" --vi "-1.41 m/s" --e 0.5 --mu 0.2 --delta-p "22 um" '
    '--ls "1400 um" --sigma-ls "50 um"',
    'impactlab simulate sphere --radius "5 mm" --vy "-1 m/s" --material aisi-1010',
]


@pytest.mark.parametrize("example", CHEAP)
def test_the_cheap_examples_run_as_written(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, example: str
) -> None:
    assert example in [e for _, e in ALL]  # still an example of the help
    monkeypatch.chdir(ROOT)
    code, _, err = cli_main(*shlex.split(example)[1:])
    assert code == 0, err


def test_calibrate_s_first_example_gives_what_the_file_lacks(
    cli_main: Any, monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """examples/data/drops.csv has no mu column: the first example makes mu a free parameter
    (run short here: the options appended only shorten the sampling)."""
    first = _examples(_help("calibrate"))[0]
    assert '-p "mu=uniform(0, 0.6)"' in first
    monkeypatch.chdir(ROOT)
    args = [*shlex.split(first)[1:], "--steps", "20", "--walkers", "8", "--quiet", "--json"]
    code, _, err = cli_main(*args)
    assert code == 0, err


@pytest.mark.parametrize("words", sorted(COMMANDS))
def test_every_help_line_fits_an_80_column_terminal(words: str) -> None:
    """An example wider than the terminal would be broken by it mid-token ("30" / "deg"), and
    a line broken after a hyphen splits what a user types (``--constant-`` / ``angle``)."""
    from typer.testing import CliRunner

    result = CliRunner().invoke(app, [*words.split(), "--help"], terminal_width=80)
    assert result.exit_code == 0, result.output
    assert [line for line in result.output.splitlines() if len(line) > 80] == []
    # no line broken after a hyphen: an option's name, a path or a default stays whole
    assert [line for line in result.output.splitlines() if re.search(r"\w-$", line)] == []
    assert "\u2011" not in result.output
