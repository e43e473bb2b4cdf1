"""The installed entry point: user errors give one line and a non-zero exit, never a traceback.
The command itself runs in a subprocess for the user errors, the help and the start-up
imports; the other checks run its ``main`` in this process (the ``cli_main`` fixture)."""

from __future__ import annotations

import functools
import os
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import pytest

CliMain = Callable[..., tuple[int, str, str]]


@functools.cache
def _run(*args: str) -> subprocess.CompletedProcess[str]:
    """``impactlab ARGS`` in a subprocess; run once for the same ``args`` (two tests check
    ``materials --bogus``)."""
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("IMPACTLAB_DEBUG", None)
    return subprocess.run(
        [sys.executable, "-m", "impactlab", *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=600,  # stops a hung command only; a busy machine is slow
    )


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("laws", "nope"), "known laws"),
        (
            (
                "invert",
                "--angle",
                "20 deg",
                "--vi",
                "-1.41 m/s",
                "--e",
                "0.5",
                "--mu",
                "0.2",
                "--delta-p",
                "3 kg",
                "--ls",
                "1400 um",
            ),
            "delta",
        ),
        (("materials", "--bogus"), "No such option"),
    ],
)
def test_user_errors_are_one_line(args: tuple[str, ...], needle: str) -> None:
    res = _run(*args)
    assert res.returncode != 0
    assert "Traceback" not in res.stderr
    assert needle in res.stderr


def test_help_lists_every_command() -> None:
    res = _run("--help")
    assert res.returncode == 0
    for cmd in ("reproduce", "simulate", "invert", "analyze", "sweep", "laws", "materials"):
        assert cmd in res.stdout


@pytest.mark.parametrize(
    "command",
    [
        ("analyze", "drop.c3d", "dent.x3p"),
        ("reproduce", "--no-simulate"),
        ("simulate", "rod", "--angle", "20 deg", "--vy", "-1 m/s", "--plot"),
    ],
)
def test_out_naming_a_file_is_one_line(
    cli_main: CliMain, tmp_path: Path, command: tuple[str, ...]
) -> None:
    """--out naming an existing file, or a folder below one: one line naming it, no traceback."""
    taken = tmp_path / "taken"
    taken.write_text("a file")
    for out in (taken, taken / "below"):
        code, _, err = cli_main(*command, "--out", str(out))
        assert code == 2, err
        assert "Traceback" not in err
        lines = err.strip().splitlines()
        assert len(lines) == 1 and str(out) in lines[0] and "--out" in lines[0], lines


def test_bare_angle_is_refused_with_a_hint(cli_main: CliMain) -> None:
    """``--angle 0.35`` once ran at 0.35 degrees without a word."""
    for cmd in (("simulate", "rod", "--vy", "-1 m/s"), ("invert", "--case", "paper-20")):
        code, _, err = cli_main(*cmd, "--angle", "0.35")
        assert code == 2 and "Traceback" not in err
        assert "--angle 0.35 has no unit: give a unit, e.g. '20 deg' or '0.35 rad'" in err


def test_cli_starts_without_the_heavy_packages() -> None:
    """The command line imports the sweep, experiment and paper packages (Zarr, xarray, pandas,
    scipy.stats, matplotlib, pint: about 1.3 s) only in the commands that use them."""
    heavy = (
        "impactlab.sweep",
        "impactlab.experiment",
        "impactlab.paper",
        "zarr",
        "xarray",
        "pandas",
        "matplotlib",
        "scipy.stats",
        "pint",
    )
    code = (
        "import sys, impactlab.cli\n"
        f"loaded = [m for m in {heavy!r} if m in sys.modules]\n"
        "assert not loaded, f'imported by impactlab.cli: {loaded}'\n"
    )
    res = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr


def test_worker_timeout_help_states_the_sweeps_default(cli_main: CliMain) -> None:
    from impactlab.cli.sweep import WORKER_TIMEOUT_HELP_DEFAULT
    from impactlab.sweep.backends import DEFAULT_WORKER_TIMEOUT

    assert WORKER_TIMEOUT_HELP_DEFAULT == DEFAULT_WORKER_TIMEOUT
    code, out, err = cli_main("sweep", "run", "--help")
    assert code == 0, err
    assert f"(default: {WORKER_TIMEOUT_HELP_DEFAULT})" in " ".join(out.split())


@pytest.mark.parametrize(
    ("args", "needle"),
    [
        (("simulate", "rod", "--modes-axial", "abc"), "Invalid value for '--modes-axial'"),
        (("materials", "--bogus"), "No such option: --bogus"),
        (("simulate", "--radus", "1 mm"), "Possible options: --radius"),
    ],
)
def test_usage_errors_are_one_line_too(args: tuple[str, ...], needle: str) -> None:
    """A wrong option or value (caught by the command-line parser) is one ``error:`` line
    naming the command's help, as every other error (not click's Usage/Try/Error block)."""
    res = _run(*args)
    assert res.returncode == 2
    lines = res.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and needle in lines[0], res.stderr
    assert f"impactlab {args[0]} --help')" in lines[0]  # the program name as invoked


def _command_paths() -> list[tuple[str, ...]]:
    """Every command and sub-command of ``impactlab``, as the words that name it."""
    import typer.main

    from impactlab.cli import app

    root = typer.main.get_command(app)
    paths: list[tuple[str, ...]] = []

    def walk(command: object, path: tuple[str, ...]) -> None:
        paths.append(path)
        for name, sub in getattr(command, "commands", {}).items():
            walk(sub, (*path, name))

    walk(root, ())
    return paths


def test_every_command_takes_h_for_its_help(cli_main: CliMain) -> None:
    """``-h`` is ``--help`` for the program and for every command and sub-command."""
    paths = _command_paths()
    assert ("sweep", "run") in paths and ("fe", "indent") in paths
    for path in paths:
        code_long, out_long, _ = cli_main(*path, "--help")
        code_short, out_short, err = cli_main(*path, "-h")
        assert code_short == code_long == 0, (path, err)
        assert out_short == out_long and out_short.startswith("Usage: "), path


def test_the_body_material_is_material_everywhere(cli_main: CliMain) -> None:
    """``--material`` names the body's material in ``laws`` and ``fe indent`` as in
    ``simulate`` and ``drop`` (``--body`` still works there)."""
    args = ("laws", "ghaednia", "--json")
    code, by_material, err = cli_main(*args, "--material", "aisi-52100")
    assert code == 0, err
    assert by_material == cli_main(*args, "--body", "aisi-52100")[1]
    assert by_material != cli_main(*args)[1]
    code, out, _ = cli_main("fe", "indent", "--help")
    assert code == 0 and "--body, --material" in out
