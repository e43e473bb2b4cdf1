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
``NUMBA_CACHE_DIR`` (the ``engine-<hash>`` folder, as an absolute path) so that child processes
(sweep workers, Dask workers started from here) share the folder; a child whose source differs
(an ``engine-`` folder of another hash) takes its own folder beside it. A folder that cannot be
written is replaced by one under the system's temporary folder, with one line on stderr (numba
would otherwise cache into the package's own ``__pycache__``, unhashed, or fail at import). A
damaged cache entry (a truncated index or data file) is compiled again instead of failing in
numba's unpickling (``repair_damaged_entries``).
"""

from __future__ import annotations

import atexit
import contextlib
import getpass
import hashlib
import os
import pickle
import shutil
import stat
import sys
import tempfile
from functools import cache
from pathlib import Path
from typing import Any

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
        return Path(own).expanduser().absolute()
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
    this module exports it to child processes, is used as it is where it is this source's;
    an engine folder of another source gives its parent folder)."""
    numba_dir = os.environ.get("NUMBA_CACHE_DIR", "").strip()
    if numba_dir:
        base = Path(numba_dir).expanduser().absolute()
        if base.name.startswith(ENGINE_PREFIX):
            if base.name == f"{ENGINE_PREFIX}{engine_source_hash()}":
                return base
            base = base.parent
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


def _writable(folder: Path) -> str:
    """Why numba could not cache into ``folder`` (created if missing; the test numba makes):
    empty when it can."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.TemporaryFile(dir=folder):
            pass
    except OSError as exc:
        return exc.strerror or type(exc).__name__
    return ""


def fallback_cache_dir() -> Path:
    """The engine folder under the system's temporary folder, in a root private to the user
    (``impactlab-<uid>``, mode 0700), for a cache folder that cannot be written. numba's cache
    files are unpickled, so a root that another user owns or may write (a planted folder in the
    shared temporary folder) is never used: a private folder of this process's own replaces it."""
    root = _user_root()
    with contextlib.suppress(OSError):
        root.mkdir(mode=0o700)
    if not _private(root):
        root = _process_root()
    return root / "numba" / f"{ENGINE_PREFIX}{engine_source_hash()}"


def _user_root() -> Path:
    """``impactlab-<uid>`` in the system's temporary folder."""
    uid = os.getuid() if hasattr(os, "getuid") else getpass.getuser()
    return Path(tempfile.gettempdir()) / f"impactlab-{uid}"


def _private(root: Path) -> bool:
    """Whether ``root`` is a real folder (not a link) owned by this user that no one else may
    write; always true where the system has no user ids."""
    if not hasattr(os, "getuid"):
        return root.is_dir()
    try:
        st = root.lstat()
    except OSError:
        return False
    return stat.S_ISDIR(st.st_mode) and st.st_uid == os.getuid() and not st.st_mode & 0o022


@cache
def _process_root() -> Path:
    """A private temporary folder of this process (``mkdtemp``: mode 0700, unguessable),
    removed when the process exits (no later process could use it)."""
    root = Path(tempfile.mkdtemp(prefix="impactlab-"))
    atexit.register(shutil.rmtree, root, True)
    return root


def use_cache_dir() -> Path:
    """Point numba's cache at ``compiled_cache_dir()`` (environment and, if numba is already
    imported, its live configuration), or at ``fallback_cache_dir()`` with one line on stderr
    where that cannot be written; returns the folder."""
    own = not os.environ.get("NUMBA_CACHE_DIR", "").strip()
    folder = compiled_cache_dir()
    if folder.exists():
        with contextlib.suppress(OSError):  # in use: the pruning keeps the most recently used
            os.utime(folder)
    else:
        prune_engine_folders(folder, legacy=own)
    why = _writable(folder)
    if why:
        wanted, folder = folder, fallback_cache_dir()
        if not folder.exists():
            prune_engine_folders(folder)
        if _writable(folder):
            folder = wanted  # nothing writable: numba says so where it compiles
        else:
            private = (
                ""
                if folder.is_relative_to(_user_root())
                else (f", for this process only ({_user_root()} is not the user's own folder)")
            )
            print(
                f"impactlab: the compile cache folder {wanted} cannot be written ({why}); "
                f"caching in {folder} instead{private} (set IMPACTLAB_CACHE_DIR to a writable "
                "folder)",
                file=sys.stderr,
            )
    os.environ["NUMBA_CACHE_DIR"] = str(folder)
    config = sys.modules.get("numba.core.config")
    if config is not None:
        config.CACHE_DIR = str(folder)  # type: ignore[attr-defined]
    return folder


#: What numba's unpickling of a truncated or damaged cache file raises.
_DAMAGED = (EOFError, pickle.UnpicklingError, ValueError, TypeError, AttributeError, IndexError)


def repair_damaged_entries() -> None:
    """Make numba treat a damaged cache entry as missing: its index read as empty, its data
    file as gone, so the function is compiled again and the entry rewritten, with one line on
    stderr (numba 0.68 raises ``UnpicklingError`` or ``EOFError`` on every run instead; a disk
    that filled, a crash during a write, a partial copy of a shared cache); and an entry that
    cannot be written (a full disk) as not kept, with one line, instead of failing the run that
    compiled it. Idempotent."""
    from numba.core import caching

    cls: Any = getattr(caching, "IndexDataCacheFile", None)
    if cls is None or getattr(cls, "_impactlab_repairs", False):
        return
    load_index, load_data, save = cls._load_index, cls._load_data, cls.save

    def _load_index(self: Any) -> Any:
        try:
            return load_index(self)
        except _DAMAGED:
            _say_damaged(self._index_path)
            return {}

    def _load_data(self: Any, name: str) -> Any:
        try:
            return load_data(self, name)
        except _DAMAGED:
            _say_damaged(self._data_path(name))
            raise OSError(f"damaged cache file {name}") from None  # numba's load: a miss

    def _save(self: Any, key: Any, data: Any) -> None:
        try:
            save(self, key, data)
        except OSError as exc:  # a full disk: the code compiled runs, it is only not kept
            print(
                f"impactlab: the compiled code could not be written to the cache folder "
                f"{self._cache_path} ({exc.strerror or exc}); it is compiled again next time",
                file=sys.stderr,
            )

    cls._load_index, cls._load_data, cls.save = _load_index, _load_data, _save
    cls._impactlab_repairs = True


_SAID: set[str] = set()


def _say_damaged(path: str) -> None:
    """One line per damaged file (numba reads an index again before it rewrites it)."""
    if path in _SAID:
        return
    _SAID.add(path)
    print(f"impactlab: a damaged compile-cache file ({path}) is compiled again", file=sys.stderr)
