"""Where numba keeps impactlab's compiled engine: one folder for every entry point.

The engine is compiled on its first use and cached on disk (numba's ``cache=True``). Every way
of running impactlab (``python3 tasks.py``, the ``impactlab`` command, ``python -c``, notebooks,
sweep workers) must find the same cache, or each compiles the engine again. The folder is

1. ``NUMBA_CACHE_DIR`` when it is set (numba's own variable, for every numba program);
2. otherwise ``IMPACTLAB_CACHE_DIR/numba`` when that is set;
3. otherwise ``$XDG_CACHE_HOME/impactlab/numba`` (``~/.cache/impactlab/numba``).

Inside it, the engine is kept in ``engine-<hash>``, the hash of the engine's source files
(``ENGINE_SOURCES``). numba checks a cached function only against the time stamp of its own
file: a changed constant or callee in another file (a layout index, a contact-law kernel, a
status code) would be linked from the stale cache without a word. A new source gets a new
folder, so the engine is always compiled from the code that is installed; the ``KEEP`` most
recently used folders are kept, older ones removed.

``use_cache_dir`` runs when ``impactlab`` is imported, before any compiled function is defined:
numba chooses a function's cache folder when the function is decorated. It also exports
``NUMBA_CACHE_DIR`` (the ``engine-<hash>`` folder) so that child processes (sweep workers,
Dask workers started from here) share the folder.
"""

from __future__ import annotations

import hashlib
import os
import shutil
from functools import cache
from pathlib import Path

#: The engine's source, relative to the package: every folder and file whose code is compiled,
#: or whose constants and functions compiled code reads (``tests/core/test_compiled_cache.py``
#: checks that every compiled function and every impactlab module it imports is covered).
ENGINE_SOURCES = (
    "dynamics/kernels",
    "dynamics/core",
    "dynamics/flexcore",
    "dynamics/slipcore",
    "dynamics/slip_batch.py",
    "contact",
    "bodies/layout.py",
    "schema",
    "_floatbits.py",
    "flags.py",
    "_input_limits.py",
)
#: Prefix of a compiled-engine folder; the folders kept (most recently used first).
ENGINE_PREFIX = "engine-"
KEEP = 3


def default_cache_root() -> Path:
    """impactlab's cache folder: ``IMPACTLAB_CACHE_DIR``, else ``$XDG_CACHE_HOME/impactlab``,
    else ``~/.cache/impactlab``."""
    own = os.environ.get("IMPACTLAB_CACHE_DIR", "").strip()
    if own:
        return Path(own).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME", "").strip()
    base = Path(xdg).expanduser() if xdg else Path.home() / ".cache"
    return base / "impactlab"


def source_hash(package: Path, sources: tuple[str, ...]) -> str:
    """The first 16 hex digits of the SHA-256 of ``sources`` (relative to ``package``): the
    ``.py`` files of a folder, a file as named; their paths and bytes, in sorted order."""
    files: list[Path] = []
    for name in sources:
        path = package / name
        files.extend(sorted(path.rglob("*.py")) if path.is_dir() else [path])
    digest = hashlib.sha256()
    for f in files:
        digest.update(f.relative_to(package).as_posix().encode())
        digest.update(b"\0")
        digest.update(f.read_bytes())
        digest.update(b"\0")
    return digest.hexdigest()[:16]


@cache
def engine_source_hash() -> str:
    """``source_hash`` of the installed engine (``ENGINE_SOURCES``), computed once."""
    return source_hash(Path(__file__).resolve().parent, ENGINE_SOURCES)


def compiled_cache_dir() -> Path:
    """The folder of numba's cache for impactlab: ``engine-<hash>`` inside the folder of the
    module docstring's order (a ``NUMBA_CACHE_DIR`` that already names an engine folder, as
    this module exports it to child processes, is used as it is)."""
    numba_dir = os.environ.get("NUMBA_CACHE_DIR", "").strip()
    if numba_dir:
        base = Path(numba_dir).expanduser()
        if base.name.startswith(ENGINE_PREFIX):
            return base
    else:
        base = default_cache_root() / "numba"
    return base / f"{ENGINE_PREFIX}{engine_source_hash()}"


def prune_engine_folders(folder: Path, keep: int = KEEP, legacy: bool = False) -> list[Path]:
    """Remove the ``engine-*`` siblings of ``folder`` beyond the ``keep`` most recently used
    (``folder`` itself is always kept), and with ``legacy`` every other entry beside them (the
    unhashed cache of earlier versions: only in impactlab's own folder); returns what was
    removed. Errors are ignored: a folder another process still uses is only recompiled there."""
    try:
        entries = [p for p in folder.parent.iterdir() if p != folder]
        siblings = [p for p in entries if p.name.startswith(ENGINE_PREFIX)]
        siblings.sort(key=lambda p: p.stat().st_mtime, reverse=True)
    except OSError:
        return []
    removed = siblings[max(keep - 1, 0) :]
    if legacy:
        removed += [p for p in entries if not p.name.startswith(ENGINE_PREFIX) and p.is_dir()]
    for p in removed:
        shutil.rmtree(p, ignore_errors=True)
    return removed


def use_cache_dir() -> Path:
    """Point numba's cache at ``compiled_cache_dir()`` (environment and, if numba is already
    imported, its live configuration); returns the folder."""
    own = not os.environ.get("NUMBA_CACHE_DIR", "").strip()
    folder = compiled_cache_dir()
    if not folder.exists():
        prune_engine_folders(folder, legacy=own)
    os.environ["NUMBA_CACHE_DIR"] = str(folder)
    import sys

    config = sys.modules.get("numba.core.config")
    if config is not None:
        config.CACHE_DIR = str(folder)  # type: ignore[attr-defined]
    return folder
