"""The environment ``tasks.py`` runs its tasks in."""

from __future__ import annotations

import importlib.util
from pathlib import Path
from types import ModuleType

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _tasks_module() -> ModuleType:
    spec = importlib.util.spec_from_file_location("impactlab_tasks", ROOT / "tasks.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_bytecode_caches_are_written_even_where_the_shell_turns_them_off(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    """Without them each test worker rewrites every test module's asserts and each of the
    suite's subprocesses compiles impactlab from source again."""
    monkeypatch.setenv("PYTHONDONTWRITEBYTECODE", "1")
    monkeypatch.delenv("MPLBACKEND", raising=False)
    env = _tasks_module()._env()
    assert "PYTHONDONTWRITEBYTECODE" not in env
    assert env["MPLBACKEND"] == "Agg"
    monkeypatch.setenv("MPLBACKEND", "pdf")  # a user's own choice is kept
    assert _tasks_module()._env()["MPLBACKEND"] == "pdf"
