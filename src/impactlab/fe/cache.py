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
import warnings
import zipfile
from collections.abc import Callable
from importlib import metadata
from pathlib import Path
from typing import Any, TypeVar

import numpy as np

from impactlab._compiled_cache import default_cache_root
from impactlab.fe.result import IndentationResult

T = TypeVar("T")

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


class DamagedCacheWarning(UserWarning):
    """A cache file that cannot be read back (cut short, empty, or not a result): treated as
    a cache miss; the run is made again and its result written over the file."""


#: What reading a damaged ``.npz`` file raises: numpy's and zipfile's errors for a cut or
#: empty file (``zipfile.BadZipFile``, ``EOFError``), ``KeyError`` for a missing array,
#: ``TypeError`` for a header that does not make a result (a field missing or unknown).
DAMAGED = (OSError, ValueError, KeyError, EOFError, TypeError, AttributeError, zipfile.BadZipFile)


def read_npz(
    path: Path,
    arrays: tuple[str, ...],
    build: Callable[..., T],
    upgrade: Callable[[dict[str, Any]], dict[str, Any]] | None = None,
) -> T | None:
    """``build(**header, **arrays)`` from the ``.npz`` file ``path``; None when there is none,
    and, with a :class:`DamagedCacheWarning` naming the file, when it is damaged. ``upgrade``
    maps a record in older names (the header and every array the file holds) to the current
    ones before ``arrays`` are looked up in it."""
    if not path.is_file():
        return None
    try:
        with open(path, "rb") as fh, np.load(fh, allow_pickle=False) as z:  # closed if cut
            header = json.loads(str(z["header"]))
            if not isinstance(header, dict):
                raise TypeError(f"its header is a {type(header).__name__}, not a record")
            names = [n for n in z.files if n != "header"] if upgrade else list(arrays)
            values: dict[str, Any] = {name: np.array(z[name]) for name in names}
        if upgrade is None:
            return build(**header, **values)
        record = upgrade({**header, **values})
        missing = [name for name in arrays if name not in record]
        if missing:
            raise KeyError(f"{missing[0]} is not a file in the archive")
        return build(**record)
    except DAMAGED as exc:
        warnings.warn(
            f"FE cache file {path} is damaged ({type(exc).__name__}: {exc}): treated as missing; "
            "the run is made again and its result written over the file",
            DamagedCacheWarning,
            stacklevel=3,
        )
        return None


def load(directory: Path, key: str) -> IndentationResult | None:
    """The cached result for ``key``, or None: none cached, or a damaged file (cut short,
    empty, not a result: a :class:`DamagedCacheWarning` naming it; the caller runs again and
    :func:`store` writes over it). A run that did not converge is cached too (ccx stops there
    again on the same inputs), read back as it was stored."""
    return read_npz(directory / f"{key}.npz", ARRAYS, IndentationResult)


def from_cache_note(directory: Path, key: str) -> str:
    """What the warning of a cached run that did not converge adds: where it was read."""
    return (
        f"read from the FE cache ({directory / f'{key}.npz'}), not run again: ccx stops there "
        "again on the same inputs; use_cache=False (impactlab fe indent --no-cache) runs it again"
    )


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
