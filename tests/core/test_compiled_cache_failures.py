"""The compile cache when its folder or its files fail: an engine folder of another source
inherited from a parent, a relative path, a folder that cannot be written, a truncated entry."""

from __future__ import annotations

import os
import stat
import subprocess
import sys
import tempfile
from collections.abc import Iterator
from pathlib import Path

import pytest

from impactlab._compiled_cache import (
    _process_root,
    compiled_cache_dir,
    default_cache_root,
    engine_source_hash,
    fallback_cache_dir,
    use_cache_dir,
)

ENGINE = f"engine-{engine_source_hash()}"


def test_an_inherited_engine_folder_of_another_source_is_not_used(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """A child of a process that imported another source kept that engine: stale code."""
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path / "n" / "engine-0123456789abcdef"))
    assert compiled_cache_dir() == tmp_path / "n" / ENGINE


def test_a_relative_cache_folder_is_made_absolute(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path
) -> None:
    """Exported relative, it moved with a process's working folder (tasks.py runs in the
    repository's root)."""
    monkeypatch.delenv("NUMBA_CACHE_DIR", raising=False)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("IMPACTLAB_CACHE_DIR", "rel")
    assert default_cache_root() == tmp_path / "rel"
    monkeypatch.setenv("NUMBA_CACHE_DIR", "relnumba")
    assert compiled_cache_dir() == tmp_path / "relnumba" / ENGINE


def test_a_folder_that_cannot_be_written_falls_back_with_one_line(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """numba cached into the package's __pycache__ (unhashed) while the notice named the
    folder, or failed at import where the package could not be written either."""
    import numba.core.config as config

    blocked = tmp_path / "a-file"
    blocked.write_text("not a folder")
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(blocked / "numba"))
    monkeypatch.setattr(config, "CACHE_DIR", config.CACHE_DIR)
    folder = use_cache_dir()
    assert folder == fallback_cache_dir() and os.environ["NUMBA_CACHE_DIR"] == str(folder)
    assert config.CACHE_DIR == str(folder) and compiled_cache_dir() == folder
    err = capsys.readouterr().err
    assert f"the compile cache folder {blocked / 'numba' / ENGINE} cannot be written" in err
    assert f"caching in {folder} instead (set IMPACTLAB_CACHE_DIR" in err


_MODULE = """
import impactlab  # noqa: F401  (its cache folder and the repair)
from numba import njit


@njit(cache=True)
def plus_one(x):
    return x + 1.0


@njit(cache=True)
def plus_two(x):
    return x + 2.0


print(plus_one(1.0), plus_two(1.0))
"""


@pytest.fixture
def fresh_process_root() -> Iterator[None]:
    """The process's fallback root found anew, and forgotten after the test whatever its end
    (a root kept in a finished test's tmp_path would follow later tests)."""
    _process_root.cache_clear()
    yield
    _process_root.cache_clear()


def test_the_temporary_fallback_is_private_to_the_user(
    monkeypatch: pytest.MonkeyPatch, tmp_path: Path, fresh_process_root: None
) -> None:
    """numba unpickles its cache files: a fallback root in the shared temporary folder that
    another user could write would run their code."""
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))
    folder = fallback_cache_dir()
    root = tmp_path / f"impactlab-{os.getuid()}"
    assert folder.is_relative_to(root) and stat.S_IMODE(root.stat().st_mode) == 0o700
    root.chmod(0o777)  # as a planted folder would be: not used
    planted = fallback_cache_dir()
    assert not planted.is_relative_to(root) and planted.is_relative_to(tmp_path)
    private = planted.parents[1]
    assert stat.S_IMODE(private.stat().st_mode) == 0o700 and private.name.startswith("impactlab-")
    root.rmdir()
    root.symlink_to(private)  # a link is not the user's own folder either
    assert fallback_cache_dir() == planted


def test_a_truncated_cache_file_is_compiled_again(tmp_path: Path) -> None:
    """numba raised UnpicklingError (a truncated data file) or EOFError (an emptied index,
    which the command line printed as 'aborted') on every run. One run damages both: the index
    of ``plus_one`` and the data file of ``plus_two``."""
    (tmp_path / "cached_mod.py").write_text(_MODULE)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "cache"), "PYTHONPATH": str(tmp_path)}

    def run() -> subprocess.CompletedProcess[str]:
        cmd = [sys.executable, "-c", "import cached_mod"]
        return subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)

    assert run().stdout.strip() == "2.0 3.0"
    (index,) = (tmp_path / "cache").rglob("cached_mod.plus_one-*.nbi")
    (data,) = (tmp_path / "cache").rglob("cached_mod.plus_two-*.nbc")
    index.write_bytes(index.read_bytes()[:1])
    data.write_bytes(data.read_bytes()[:40])
    again = run()
    assert again.returncode == 0, again.stderr
    assert again.stdout.strip() == "2.0 3.0"
    assert again.stderr.count("a damaged compile-cache file") == 2, again.stderr
    for entry in (index, data):  # one line for each
        assert again.stderr.count(f"a damaged compile-cache file ({entry})") == 1, again.stderr
    assert "compiled again" in again.stderr
    third = run()  # rewritten: loaded silently
    assert third.stdout.strip() == "2.0 3.0" and "damaged" not in third.stderr


def test_impactlab_runs_as_plain_python_under_numba_disable_jit() -> None:
    """``NUMBA_DISABLE_JIT=1`` (numba's debugging switch, and the engine profile's counting
    run) failed at import: a compiled function's ``py_func`` read at module level."""
    code = (
        "import impactlab as il; "
        "print(il.simulate(il.PAPER_ROD, angle=0.35, velocity=(0, -1.41), mu=0.2).e)"
    )
    env = {**os.environ, "NUMBA_DISABLE_JIT": "1"}
    cmd = [sys.executable, "-c", code]
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert 0.0 < float(done.stdout) < 1.0


def test_a_cache_that_cannot_be_written_leaves_the_run_going(tmp_path: Path) -> None:
    """A full disk failed the run that compiled ("no space left ... writing a file")."""
    code = """
import errno
import impactlab  # noqa: F401
from numba.core import caching

def full(self, name, data):
    raise OSError(errno.ENOSPC, "No space left on device")

caching.IndexDataCacheFile._save_data = full
from numba import njit

@njit(cache=True)
def plus_two(x):
    return x + 2.0

print(plus_two(1.0))
"""
    (tmp_path / "full_mod.py").write_text(code)
    env = {**os.environ, "NUMBA_CACHE_DIR": str(tmp_path / "cache"), "PYTHONPATH": str(tmp_path)}
    cmd = [sys.executable, "-c", "import full_mod"]
    done = subprocess.run(cmd, env=env, capture_output=True, text=True, check=False)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "3.0"
    assert "could not be written to the cache folder" in done.stderr
    assert "No space left on device" in done.stderr
