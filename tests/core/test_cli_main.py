"""The installed entry point: user errors give one line and a non-zero exit, never a traceback."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest


def _run(*args: str) -> subprocess.CompletedProcess[str]:
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("IMPACTLAB_DEBUG", None)
    return subprocess.run(
        [sys.executable, "-m", "impactlab", *args],
        capture_output=True,
        text=True,
        env=env,
        timeout=120,
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
def test_out_naming_a_file_is_one_line(tmp_path: Path, command: tuple[str, ...]) -> None:
    """--out naming an existing file, or a folder below one: one line naming it, no traceback
    (issue 14, item 8)."""
    taken = tmp_path / "taken"
    taken.write_text("a file")
    for out in (taken, taken / "below"):
        res = _run(*command, "--out", str(out))
        assert res.returncode == 2, res.stderr
        assert "Traceback" not in res.stderr
        lines = res.stderr.strip().splitlines()
        assert len(lines) == 1 and str(out) in lines[0] and "--out" in lines[0], lines


def test_bare_angle_is_refused_with_a_hint() -> None:
    """``--angle 0.35`` once ran at 0.35 degrees without a word (issue 15)."""
    for cmd in (("simulate", "rod", "--vy", "-1 m/s"), ("invert", "--case", "paper-20")):
        res = _run(*cmd, "--angle", "0.35")
        assert res.returncode == 2 and "Traceback" not in res.stderr
        assert "--angle 0.35 has no unit: give a unit, e.g. '20 deg' or '0.35 rad'" in res.stderr
