"""Keep numba's on-disk cache of the compiled core consistent with every source it depends on.

numba invalidates a cached function only when *its own* source file changes, but the core
inlines functions of other files (its own modules, the contact-law kernels) and freezes the
constants it imports (state and output layout, ``impactlab.schema``, the body-vector layout)
into its machine code. We fingerprint every ``.py`` file below ``dynamics/core``, ``contact``
and ``bodies`` (a glob: a new file is covered without a list to maintain), plus ``schema.py``,
``flags.py`` and ``_floatbits.py``, and flush the caches of the compiled functions when the
fingerprint changes.
"""

from __future__ import annotations

import hashlib
import os
import sys
from collections.abc import Iterable
from pathlib import Path
from typing import Any

from numba.core.registry import CPUDispatcher

#: The package root (``src/impactlab``).
PACKAGE = Path(__file__).resolve().parents[2]
#: Folders (relative to the package) whose every ``.py`` file enters the fingerprint.
SOURCE_DIRS = ("dynamics/core", "contact", "bodies")
#: Single modules that enter the fingerprint.
SOURCE_FILES = ("schema.py", "flags.py", "_floatbits.py")
#: Modules whose compiled functions are flushed together (by name prefix).
MODULE_PREFIXES = ("impactlab.dynamics.core.", "impactlab.contact.")


def source_files(root: Path = PACKAGE) -> list[Path]:
    """Every source file the compiled core depends on, sorted."""
    files: set[Path] = set()
    for d in SOURCE_DIRS:
        files.update((root / d).rglob("*.py"))
    files.update(root / f for f in SOURCE_FILES if (root / f).is_file())
    return sorted(files)


def fingerprint(root: Path = PACKAGE) -> str:
    """SHA-256 over the relative path and content of every file of ``source_files``."""
    h = hashlib.sha256()
    for f in source_files(root):
        try:
            data = f.read_bytes()
        except OSError:
            continue
        h.update(f.relative_to(root).as_posix().encode())
        h.update(data)
    return h.hexdigest()


def dispatchers(prefixes: Iterable[str] = MODULE_PREFIXES) -> list[Any]:
    """The compiled functions defined in the loaded modules whose names start with
    ``prefixes`` (each once, in the order of ``prefixes``)."""
    found: dict[int, Any] = {}
    modules = sorted(sys.modules.items())
    for pre in prefixes:  # in this order: the first dispatcher's folder holds the stamp
        for name, mod in modules:
            if mod is None or not name.startswith(pre):
                continue
            for v in list(vars(mod).values()):
                if isinstance(v, CPUDispatcher) and v.py_func.__module__.startswith(pre):
                    found.setdefault(id(v), v)
    return list(found.values())


def refresh(disps: Iterable[Any], tag: str, fp: str | None = None) -> bool:
    """Flush the cache index of ``disps`` if the dependency fingerprint changed since the last
    call (recorded in a stamp file next to the cache). Returns True when it flushed."""
    disps = list(disps)
    if not disps:
        return False
    try:
        path = Path(disps[0]._cache.cache_path)
    except AttributeError:  # caching disabled
        return False
    stamp = path / f"impactlab-{tag}.stamp"
    fp = fingerprint() if fp is None else fp
    try:
        if stamp.is_file() and stamp.read_text() == fp:
            return False
    except OSError:
        pass
    for d in disps:
        try:
            d._cache.flush()
        except (AttributeError, OSError):
            continue
    try:
        path.mkdir(parents=True, exist_ok=True)
        tmp = stamp.with_suffix(f".{os.getpid()}.tmp")
        tmp.write_text(fp)
        os.replace(tmp, stamp)
    except OSError:
        pass
    return True
