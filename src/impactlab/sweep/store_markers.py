"""The completion markers of a store's chunks (``.sweep/done/<k>``): made atomically, listed,
checked against their files' sizes and CRC-32s, removed; and the temporary files a killed
writer leaves."""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from impactlab.sweep.integrity import check_marker
from impactlab.sweep.storebuild import META


def done_dir(path: Path) -> Path:
    """The folder of the completion markers of the store at ``path``."""
    return path / META / "done"


def done_chunks(path: Path) -> set[int]:
    """Indices of the chunks whose completion marker exists (intact or not)."""
    folder = done_dir(path)
    if not folder.is_dir():
        return set()
    return {int(p.name) for p in folder.iterdir() if p.name.isdigit()}


def mark_done(path: Path, index: int, text: str) -> None:
    """Create chunk ``index``'s completion marker (content ``text``) atomically, its folder
    made again where it was deleted."""
    folder = done_dir(path)
    final = folder / str(index)
    tmp = folder / f".{index}.{os.getpid()}.tmp"
    folder.mkdir(exist_ok=True)
    tmp.write_text(text)
    os.replace(tmp, final)


def damaged_chunks(path: Path, indices: Iterable[int]) -> dict[int, str]:
    """The chunks among ``indices`` whose files no longer match their marker, each with what
    is wrong with it."""
    damaged = {}
    for k in sorted(indices):
        try:
            text = (done_dir(path) / str(k)).read_text()
        except (OSError, UnicodeDecodeError):
            text = ""
        why = check_marker(path, text)
        if why is not None:
            damaged[k] = why
    return damaged


def discard(path: Path, indices: Iterable[int]) -> None:
    """Remove the completion markers of chunks ``indices``."""
    for k in indices:
        (done_dir(path) / str(k)).unlink(missing_ok=True)


def clean_partial(path: Path) -> int:
    """Remove the temporary files left by a killed writer (Zarr's ``*.partial``, our
    ``*.tmp``) under ``path``; their number."""
    count = 0
    for root, _, files in os.walk(path):
        for f in files:
            if f.endswith(".partial") or (f.endswith(".tmp") and f.startswith(".")):
                os.unlink(os.path.join(root, f))
                count += 1
    return count
