"""The installed entry point: user errors give one line and a non-zero exit, never a traceback."""

from __future__ import annotations

import os
import subprocess
import sys

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
