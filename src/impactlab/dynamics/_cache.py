"""Keep numba's on-disk cache of the engine consistent with the contact-law sources.

numba invalidates a cached function only when *its own* source file changes; the engine inlines
the contact-law kernels (``impactlab.contact``), so an edited law would otherwise run with stale
machine code. We fingerprint the sources the engine depends on and flush the engine's cache
index when the fingerprint changes.
"""

from __future__ import annotations

import hashlib
import os
from collections.abc import Iterable
from pathlib import Path
from typing import Any

_PKG = Path(__file__).resolve().parent.parent


def _fingerprint() -> str:
    h = hashlib.sha256()
    # the engine inlines the law kernels and freezes the constants it imports (contact
    # kernels, the body-vector layout) into its machine code
    files = sorted((_PKG / "contact").glob("*.py"))
    files += [_PKG / "bodies.py", _PKG / "dynamics" / "engine.py"]
    for f in files:
        try:
            h.update(f.name.encode())
            h.update(f.read_bytes())
        except OSError:
            continue
    return h.hexdigest()


def refresh(dispatchers: Iterable[Any], tag: str) -> None:
    """Flush the cache index of ``dispatchers`` if the dependency fingerprint changed."""
    disps = list(dispatchers)
    if not disps:
        return
    try:
        cache = disps[0]._cache
        path = Path(cache.cache_path)
    except AttributeError:  # caching disabled
        return
    stamp = path / f"impactlab-{tag}.stamp"
    fp = _fingerprint()
    try:
        if stamp.is_file() and stamp.read_text() == fp:
            return
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
