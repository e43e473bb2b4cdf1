"""Shared fixtures of the documentation tests: the site built once per session
(``mkdocs build --strict``, about 5 s). The suite's one warm-up (``warm_engine``, root
conftest) loads or compiles the engine once per session, so that the verification functions
and the example scripts (subprocesses with this process's NUMBA_CACHE_DIR) load it."""

from __future__ import annotations

import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: why the documentation build cannot run here, or None
DOCS_DEPS_MISSING = next(
    (
        f"{name} is not installed (the docs extra of pyproject.toml)"
        for name, module in (
            ("mkdocs", "mkdocs"),
            ("mkdocstrings[python]", "mkdocstrings_handlers"),
            ("latex2mathml", "latex2mathml"),
        )
        if importlib.util.find_spec(module) is None
    ),
    None,
)


@pytest.fixture(scope="session")
def site(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The documentation site, built once with ``mkdocs build --strict``."""
    if DOCS_DEPS_MISSING:
        pytest.skip(DOCS_DEPS_MISSING)
    out = tmp_path_factory.mktemp("site")
    env = dict(os.environ, NO_MKDOCS_2_WARNING="1")
    cmd = [sys.executable, "-m", "mkdocs", "build", "--strict", "-f", str(ROOT / "mkdocs.yml")]
    proc = subprocess.run(
        [*cmd, "-d", str(out)], cwd=ROOT, env=env, capture_output=True, text=True, timeout=600
    )
    assert proc.returncode == 0, proc.stdout[-4000:] + proc.stderr[-4000:]
    return out
