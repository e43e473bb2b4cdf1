"""Where numba keeps impactlab's compiled engine: one folder for every entry point.

The engine is compiled on its first use and cached on disk (numba's ``cache=True``). Every way
of running impactlab (``python3 tasks.py``, the ``impactlab`` command, ``python -c``, notebooks,
sweep workers) must find the same cache, or each compiles the engine again. The folder is

1. ``NUMBA_CACHE_DIR`` when it is set (numba's own variable, for every numba program);
2. otherwise ``IMPACTLAB_CACHE_DIR/numba`` when that is set;
3. otherwise ``$XDG_CACHE_HOME/impactlab/numba`` (``~/.cache/impactlab/numba``).

``use_cache_dir`` runs when ``impactlab`` is imported, before any compiled function is defined:
numba chooses a function's cache folder when the function is decorated. It also exports
``NUMBA_CACHE_DIR`` so that child processes (sweep workers, Dask workers started from here)
share the folder.
"""

from __future__ import annotations

import os
from pathlib import Path


def default_cache_root() -> Path:
    """impactlab's cache folder: ``IMPACTLAB_CACHE_DIR``, else ``$XDG_CACHE_HOME/impactlab``,
    else ``~/.cache/impactlab``."""
    own = os.environ.get("IMPACTLAB_CACHE_DIR", "").strip()
    if own:
        return Path(own).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME", "").strip()
    base = Path(xdg).expanduser() if xdg else Path.home() / ".cache"
    return base / "impactlab"


def compiled_cache_dir() -> Path:
    """The folder of numba's cache for impactlab (see the module docstring for the order)."""
    numba_dir = os.environ.get("NUMBA_CACHE_DIR", "").strip()
    if numba_dir:
        return Path(numba_dir).expanduser()
    return default_cache_root() / "numba"


def use_cache_dir() -> Path:
    """Point numba's cache at ``compiled_cache_dir()`` (environment and, if numba is already
    imported, its live configuration); returns the folder."""
    folder = compiled_cache_dir()
    os.environ["NUMBA_CACHE_DIR"] = str(folder)
    import sys

    config = sys.modules.get("numba.core.config")
    if config is not None:
        config.CACHE_DIR = str(folder)  # type: ignore[attr-defined]
    return folder
