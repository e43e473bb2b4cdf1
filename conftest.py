"""Settings shared by the whole test suite.

Hypothesis runs without wall-clock deadlines: the suite runs on busy machines (CI shares its
cores), and a test that fails because the machine was slow is a flaky test. Its examples are
still bounded by each test's ``max_examples``.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from hypothesis import settings

settings.register_profile("impactlab", deadline=None, print_blob=True)
settings.load_profile("impactlab")

# The parallel batch engine's OpenMP threads (numba's "omp" threading layer) sleep when they
# run out of work instead of spinning: with two test workers on two cores, a worker's spinning
# threads take the core the other worker needs, and the suite's many small batches spend most
# of their CPU time waiting. Set before the first parallel call loads the OpenMP library; the
# numbers are the same either way.
os.environ.setdefault("OMP_WAIT_POLICY", "PASSIVE")


#: The compiled parts (``impactlab.dynamics.warm.PARTS``) each test folder uses: the one warm-up
#: of the suite compiles them (or loads them from numba's disk cache) once per session, before
#: the folder's first test, so that no test's own run includes a compile.
WARM_PARTS = {
    "contact": ("contact laws", "flexible rod", "flexible batch"),
    "core": ("rigid impact", "batch"),
    # the examples run as subprocesses: the reproduction needs the flexible rod and the laws'
    # kernels as well, which the subprocess then loads instead of compiling under a time limit
    "docs": ("contact laws", "rigid impact", "batch", "flexible rod"),
    "dynamics": ("rigid impact", "batch"),
    "flexible": ("flexible rod", "flexible batch"),
}
_WARMED: set[str] = set()


#: Test files that share an expensive session fixture, run by one worker under
#: ``pytest -n N --dist loadfile`` (each worker would otherwise make the fixture itself):
#: file -> the name of the group it runs in.
SAME_WORKER = {
    # the documentation site, ``mkdocs build --strict`` (tests/docs/conftest.py: ``site``)
    "tests/docs/test_docs_build.py": "docs site",
    "tests/docs/test_browser.py": "docs site",
}

#: The same for whole folders: folder (with its trailing slash) -> the name of the group.
SAME_WORKER_FOLDERS = {
    # the synthetic drops and dents and the analysed example (tests/experiment/conftest.py)
    "tests/experiment/": "experiment data",
    # ``reproduce`` with its simulations (tests/paper/conftest.py: ``full_reproduction``)
    "tests/paper/": "paper reproduction",
}


def same_worker_group(path: str) -> str:
    """The group that the test file ``path`` (relative to the root, '/'-separated) runs in:
    its ``SAME_WORKER`` or ``SAME_WORKER_FOLDERS`` group, else the file itself."""
    if path in SAME_WORKER:
        return SAME_WORKER[path]
    for folder, group in SAME_WORKER_FOLDERS.items():
        if path.startswith(folder):
            return group
    return path


@pytest.hookimpl(optionalhook=True)
def pytest_xdist_make_scheduler(config: pytest.Config, log: Any) -> Any:
    """``--dist loadfile`` with the files of ``SAME_WORKER`` and ``SAME_WORKER_FOLDERS``
    grouped; other modes as xdist's."""
    if config.getvalue("dist") != "loadfile":
        return None
    from xdist.scheduler import LoadFileScheduling

    class SharedFixtureFileScheduling(LoadFileScheduling):
        def _split_scope(self, nodeid: str) -> str:
            return same_worker_group(super()._split_scope(nodeid))

    return SharedFixtureFileScheduling(config, log)


@pytest.fixture(autouse=True)
def warm_engine(request: pytest.FixtureRequest) -> None:
    """Compile or load the engine parts the test's folder uses, each once per session."""
    folder = Path(str(request.node.path)).parent.name
    todo = [p for p in WARM_PARTS.get(folder, ()) if p not in _WARMED]
    if todo:
        from impactlab.dynamics.warm import warm

        warm(tuple(todo))
        _WARMED.update(todo)


@pytest.fixture
def cli_main(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> Callable[..., tuple[int, str, str]]:
    """``impactlab ARGS`` in this process, through the installed command's ``main`` (its
    one-line errors, exit statuses and warnings): ``cli_main(*args)`` gives (exit status,
    stdout, stderr). Without the interpreter start and the package import of a subprocess
    (1-2 s each); ``tests/core/test_cli_main.py`` runs the command itself."""
    from impactlab.cli import main

    monkeypatch.delenv("IMPACTLAB_DEBUG", raising=False)

    def run(*args: str) -> tuple[int, str, str]:
        capsys.readouterr()  # only this command's output
        monkeypatch.setattr(sys, "argv", ["impactlab", *args])
        try:
            main()
            code = 0
        except SystemExit as exc:  # as the interpreter ends: None is 0, a message is 1
            if exc.code is None or isinstance(exc.code, int):
                code = exc.code or 0
            else:
                print(exc.code, file=sys.stderr)
                code = 1
        out, err = capsys.readouterr()
        return code, out, err

    return run
