#!/usr/bin/env python3
"""Set-up and task runner for impactlab: needs only python3 (with venv and pip).

    python3 tasks.py TASK [ARGS...]       # e.g. python3 tasks.py test -k sweep
    python3 tasks.py help                 # every task, one line each (also -h, --help)

The virtual environment is built from the pinned ``requirements.lock`` and re-built whenever the
lock file or ``pyproject.toml`` changes (their SHA-256 is kept in ``.venv/.impactlab-stamp``).
The import layers (``[tool.importlinter]`` in pyproject.toml) are checked by
``tests/core/test_layers.py``, so ``test`` runs them too.
"""

from __future__ import annotations

import hashlib
import os
import shlex
import subprocess
import sys
import venv
from pathlib import Path

ROOT = Path(__file__).resolve().parent
VENV = ROOT / ".venv"
BIN = VENV / ("Scripts" if os.name == "nt" else "bin")
PY = BIN / "python"
STAMP = VENV / ".impactlab-stamp"
LOCK = ROOT / "requirements.lock"


def _fingerprint() -> str:
    h = hashlib.sha256()
    for name in ("requirements.lock", "pyproject.toml"):
        h.update((ROOT / name).read_bytes())
    return h.hexdigest()


def _run(*cmd: str | Path, env: dict[str, str] | None = None) -> int:
    print(
        "+", shlex.join(str(c) for c in cmd), file=sys.stderr, flush=True
    )  # stdout: the command's
    return subprocess.call([str(c) for c in cmd], cwd=ROOT, env=env)


def ensure_env() -> None:
    """Create or refresh .venv from requirements.lock and install impactlab in editable mode."""
    fp = _fingerprint()
    if STAMP.exists() and STAMP.read_text() == fp and PY.exists():
        return
    if not PY.exists():
        print(f"creating virtual environment in {VENV}", flush=True)
        venv.EnvBuilder(with_pip=True, clear=True).create(VENV)
    pip: list[str | Path] = [PY, "-m", "pip", "install", "--disable-pip-version-check", "-q"]
    for cmd in ([*pip, "-r", LOCK], [*pip, "--no-deps", "-e", "."]):
        if _run(*cmd) != 0:
            sys.exit("impactlab set-up failed while installing dependencies (see above)")
    STAMP.write_text(fp)


_CHECKED = (
    "src",
    "tests",
    "benchmarks",
    "examples",
    "notebooks",
    "tools",
    "tasks.py",
    "conftest.py",
)
_RUFF: list[str | Path] = [PY, "-m", "ruff", "check", *_CHECKED]
_RUFF_FORMAT: list[str | Path] = [PY, "-m", "ruff", "format", "--check", *_CHECKED]
_MYPY: list[str | Path] = [PY, "-m", "mypy"]
_LOCK: list[str | Path] = [
    *("-m", "uv", "pip", "compile", "pyproject.toml"),
    *("--extra", "profilometry", "--extra", "netcdf", "--extra", "dev", "--extra", "docs"),
    *("--extra", "fe"),
    *("--python-version", "3.11", "-o", "requirements.lock"),
]


def _env() -> dict[str, str]:
    env = dict(os.environ)
    env.setdefault("MPLBACKEND", "Agg")
    # Python's bytecode caches (__pycache__, ignored by git) are written even where
    # PYTHONDONTWRITEBYTECODE is set: without them every test worker rewrites the asserts of
    # all ~750 test modules (about 20 s of CPU each) and every subprocess of the suite
    # compiles impactlab's modules from source again
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


#: every task and what it does, one line each (``python3 tasks.py help`` prints this table)
TASKS: dict[str, str] = {
    "reproduce": "create .venv if needed, then reproduce the paper into ./reproduction/ [ARGS]",
    "test": "create .venv if needed, then ruff, mypy and pytest [--fast] [PYTEST ARGS]",
    "warm": "compile the engine into its cache ahead of the first run (impactlab warm) [ARGS]",
    "lint": "ruff check, ruff format --check, mypy, lint-imports",
    "bench": "run the benchmarks (benchmarks/run_all.py) [ARGS]",
    "docs": "build the documentation site (mkdocs build --strict) [ARGS]",
    "lock": "regenerate requirements.lock with uv (developers only)",
    "fe-reference": "run the CalculiX reference curves into src/impactlab/fe/data/ [CASES]",
    "calibrate-paper": "calibrate the paper's three drops into src/impactlab/paper/data/ [STEPS]",
    "fe-impact": "run the dynamic CalculiX impacts into src/impactlab/fe/data/ [CASES]",
    "help": "this list (also -h, --help, or no task)",
}


def usage() -> str:
    """The help text: how to call, then every task with its one-line description."""
    w = max(map(len, TASKS))
    lines = ["usage: python3 tasks.py TASK [ARGS...]", "", "tasks:"]
    lines += [f"  {name:<{w}}  {text}" for name, text in TASKS.items()]
    return "\n".join(lines)


def _test(rest: list[str], env: dict[str, str]) -> int:
    """ruff, mypy, the engine's warm-up, then pytest; ``--fast``: without the slow and perf
    marks (the local lane; CI runs everything)."""
    for cmd in (_RUFF, _RUFF_FORMAT):
        if _run(*cmd, env=env) != 0:
            return 1
    # the engine is compiled once here (its two halves side by side), then loaded from the
    # cache by both test workers (each would otherwise compile it at the same time); mypy
    # runs meanwhile
    warm_cmd = [str(PY), "-m", "impactlab", "warm"]
    print("+", " ".join(warm_cmd), "(beside mypy)", flush=True)
    warming = subprocess.Popen(warm_cmd, cwd=ROOT, env=env)
    typed = _run(*_MYPY, env=env)
    if warming.wait() != 0 or typed != 0:
        return 1
    if "--fast" in rest:
        rest = ["-m", "not slow and not perf", *(a for a in rest if a != "--fast")]
    return _run(PY, "-m", "pytest", "-n", "2", "--dist", "loadfile", *rest, env=env)


def main(argv: list[str]) -> int:
    if not argv or argv[0] in {"-h", "--help", "help"}:
        print(usage())
        return 0
    task, rest = argv[0], argv[1:]
    if task not in TASKS:
        print(f"unknown task {task!r}\n\n{usage()}", file=sys.stderr)
        return 2
    if task == "lock":
        _run(sys.executable, "-m", "pip", "install", "-q", "uv")
        return _run(sys.executable, *_LOCK)
    ensure_env()
    env = _env()
    if task == "reproduce":
        return _run(PY, "-m", "impactlab", "reproduce", *rest, env=env)
    if task == "warm":
        return _run(PY, "-m", "impactlab", "warm", *rest, env=env)
    if task == "test":
        return _test(rest, env)
    if task == "lint":
        cmds = (_RUFF, _RUFF_FORMAT, _MYPY, [BIN / "lint-imports", "--no-cache"])
        return max(_run(*cmd, env=env) for cmd in cmds)
    if task == "fe-reference":
        return _run(PY, "-m", "impactlab.fe.reference", *rest, env=env)
    if task == "calibrate-paper":
        return _run(PY, "-m", "impactlab.paper.calibration_report", "--shipped", *rest, env=env)
    if task == "fe-impact":
        return _run(PY, "-m", "impactlab.fe.impact_reference", *rest, env=env)
    if task == "bench":
        return _run(PY, "benchmarks/run_all.py", *rest, env=env)
    return _run(PY, "-m", "mkdocs", "build", "--strict", *rest, env=env)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
