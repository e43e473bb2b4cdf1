"""The environment ``tasks.py`` runs its tasks in."""

from __future__ import annotations

import runpy
from collections.abc import Callable
from pathlib import Path

import pytest

TASKS = Path(__file__).resolve().parents[2] / "tasks.py"


def _task_env() -> Callable[[], dict[str, str]]:
    """``tasks._env``, from the script's own namespace (its main guard does not run)."""
    return runpy.run_path(str(TASKS))["_env"]


def test_bytecode_caches_are_written_even_where_the_shell_turns_them_off(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Without them each test worker rewrites every test module's asserts and each of the
    suite's subprocesses compiles impactlab from source again."""
    monkeypatch.setenv("PYTHONDONTWRITEBYTECODE", "1")
    monkeypatch.delenv("MPLBACKEND", raising=False)
    env = _task_env()()
    assert "PYTHONDONTWRITEBYTECODE" not in env
    assert env["MPLBACKEND"] == "Agg"
    monkeypatch.setenv("MPLBACKEND", "pdf")  # a user's own choice is kept
    assert _task_env()()["MPLBACKEND"] == "pdf"
