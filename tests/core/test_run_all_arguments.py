"""``benchmarks/run_all.py`` (``python3 tasks.py bench``) reads its arguments with argparse:
``--help`` prints the usage and runs nothing, an unknown argument is refused with exit status
2, and ``--dry-run`` lists the benchmarks it runs, as its docstring names them; the scripts it
leaves out are named there with the reason. Nothing here runs a benchmark."""

from __future__ import annotations

import importlib.util
import re
import subprocess
from pathlib import Path
from types import ModuleType

import pytest

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def _run_all() -> ModuleType:
    spec = importlib.util.spec_from_file_location("run_all", BENCH / "run_all.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


@pytest.fixture
def run_all(monkeypatch: pytest.MonkeyPatch) -> ModuleType:
    module = _run_all()

    def refuse(cmd: list[str]) -> int:
        raise AssertionError(f"a benchmark was started: {cmd}")

    monkeypatch.setattr(subprocess, "call", refuse)
    return module


def test_help_prints_the_usage_and_runs_nothing(
    run_all: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as stop:
        run_all.main(["--help"])
    assert stop.value.code == 0
    out = capsys.readouterr().out
    assert out.startswith("usage: run_all.py") and "--full" in out and "--dry-run" in out
    assert "+ " not in out


@pytest.mark.parametrize("args", [["--bogus"], ["full"], ["--full", "--quick"]])
def test_an_unknown_argument_is_refused(
    run_all: ModuleType, args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    with pytest.raises(SystemExit) as stop:
        run_all.main(args)
    assert stop.value.code == 2
    assert "unrecognized arguments" in capsys.readouterr().err


def test_dry_run_lists_what_the_docstring_says_it_runs(
    run_all: ModuleType, capsys: pytest.CaptureFixture[str]
) -> None:
    assert run_all.main(["--dry-run"]) == 0
    out = capsys.readouterr().out
    ran = re.findall(r"benchmarks/(\w+\.py)", out)
    doc = run_all.__doc__
    assert doc is not None
    runs, left = doc.split("Not run here")
    assert ran == re.findall(r"``(\w+\.py)``", runs)
    assert "--markdown" in out and "bench_sweep.py --quick" in out
    assert run_all.main(["--dry-run", "--full"]) == 0
    assert "bench_sweep.py --quick" not in capsys.readouterr().out
    # every script of benchmarks/ is run or named as left out
    scripts = {p.name for p in BENCH.glob("*.py")} - {"run_all.py"}
    named_out = set(re.findall(r"``(\w+\.py)", left))
    assert scripts == set(ran) | named_out and not set(ran) & named_out
