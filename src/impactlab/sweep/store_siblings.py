"""A store's temporary siblings (``.<name>.creating-<host>-<pid>``, ``.<name>.removing-...``),
those of killed processes removed, and what says that a directory is a sweep store (checked
before one is removed or taken over)."""

from __future__ import annotations

import json
import os
import shutil
import socket
from pathlib import Path

from impactlab.sweep.inputs import INPUTS, OUTPUTS
from impactlab.sweep.locking import stale
from impactlab.sweep.options import STUDY_FORMAT
from impactlab.sweep.storebuild import META


def sibling(path: Path, kind: str) -> Path:
    """This process's temporary sibling of the store at ``path``:
    ``.<name>.<kind>-<host>-<pid>``."""
    return path.parent / f".{path.name}.{kind}-{socket.gethostname()}-{os.getpid()}"


def clean_siblings(path: Path) -> None:
    """Remove the temporary siblings (creating, removing) left by killed processes."""
    for kind in ("creating", "removing"):
        prefix = f".{path.name}.{kind}-"
        if not path.parent.is_dir():
            return
        for p in path.parent.iterdir():
            if not p.name.startswith(prefix):
                continue
            host, _, pid = p.name[len(prefix) :].rpartition("-")
            if pid.isdigit() and stale(host, int(pid)):
                shutil.rmtree(p, ignore_errors=True)


def occupied(path: Path) -> bool:
    """Something is at ``path``: a file, or a directory that is not empty."""
    return path.exists() and (not path.is_dir() or any(path.iterdir()))


def evidence(path: Path) -> str:
    """What says that impactlab made the directory ``path``: ``"store"`` (a ``.sweep`` folder
    or the root attributes of a sweep: a store, possibly cut short by an older impactlab),
    ``"group"`` (a Zarr group holding nothing but arrays named like a sweep's: an older
    impactlab killed before it wrote the attributes), or ``""`` (nothing: not ours)."""
    if (path / META).is_dir():
        return "store"
    try:
        root = json.loads((path / "zarr.json").read_text())
    except (OSError, ValueError):
        return ""
    if not isinstance(root, dict) or root.get("node_type") not in (None, "group"):
        return ""
    attrs = root.get("attributes")
    if isinstance(attrs, dict) and attrs.get("sweep_format") == STUDY_FORMAT:
        return "store"
    names = {*INPUTS, *OUTPUTS, "status", "zarr.json"}
    ours = all(p.name in names for p in path.iterdir())
    return "group" if ours and root.get("node_type") == "group" else ""
