"""The on-disk cache of indentation results, keyed by a SHA-256 of every input.

The key hashes the problem's inputs (``Problem.key_data``), the ccx and gmsh versions and
:data:`SCHEMA_VERSION`; a result is stored as one ``.npz`` file (arrays and a JSON header).
Location: the ``cache_dir`` argument, else ``$IMPACTLAB_FE_CACHE``, else
``$XDG_CACHE_HOME/impactlab/fe``, else ``~/.cache/impactlab/fe``.
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
from importlib import metadata
from pathlib import Path
from typing import Any

import numpy as np

from impactlab._compiled_cache import default_cache_root
from impactlab.fe.result import IndentationResult

#: Bumped whenever the model (mesh, deck, post-processing) or the stored format changes.
SCHEMA_VERSION = 2

#: The array fields of an ``IndentationResult`` (stored as arrays; the rest is the header).
ARRAYS = (
    "loading_delta",
    "loading_force",
    "contact_radius",
    "unloading_delta",
    "unloading_force",
    "dent_r",
    "dent_z",
)


def default_cache_dir() -> Path:
    """``$IMPACTLAB_FE_CACHE``, else ``fe`` in impactlab's cache folder
    (``impactlab._compiled_cache.default_cache_root``: ``$IMPACTLAB_CACHE_DIR``, else
    ``$XDG_CACHE_HOME/impactlab``, else ``~/.cache/impactlab``)."""
    env = os.environ.get("IMPACTLAB_FE_CACHE")
    if env:
        return Path(env)
    return default_cache_root() / "fe"


def gmsh_version() -> str:
    """The installed gmsh package's version (without importing it), or "none"."""
    try:
        return metadata.version("gmsh")
    except metadata.PackageNotFoundError:
        return "none"


def cache_key(data: dict[str, Any], ccx_version: str) -> str:
    """SHA-256 (hex) of the inputs, the engine versions and the schema version."""
    blob = json.dumps(
        {"inputs": data, "ccx": ccx_version, "gmsh": gmsh_version(), "schema": SCHEMA_VERSION},
        sort_keys=True,
        separators=(",", ":"),
    )
    return hashlib.sha256(blob.encode()).hexdigest()


def load(directory: Path, key: str) -> IndentationResult | None:
    """The cached result for ``key``, or None (also for an unreadable file)."""
    path = directory / f"{key}.npz"
    if not path.is_file():
        return None
    try:
        with np.load(path, allow_pickle=False) as z:
            header = json.loads(str(z["header"]))
            arrays: dict[str, Any] = {name: np.array(z[name]) for name in ARRAYS}
    except (OSError, ValueError, KeyError):
        return None
    return IndentationResult(**header, **arrays)


def store(directory: Path, key: str, result: IndentationResult) -> None:
    """Write ``result`` under ``key`` (atomically: a temporary file, then a rename)."""
    directory.mkdir(parents=True, exist_ok=True)
    values = result.arrays()
    header = {k: v for k, v in values.items() if k not in ARRAYS}
    fd, tmp = tempfile.mkstemp(dir=directory, suffix=".npz.tmp")
    os.close(fd)
    try:
        with open(tmp, "wb") as fh:
            np.savez(fh, header=np.array(json.dumps(header)), **{k: values[k] for k in ARRAYS})
        os.replace(tmp, directory / f"{key}.npz")
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)
