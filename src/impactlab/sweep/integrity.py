"""Checksums of a chunk's files, recorded in its completion marker, and their verification.

A chunk's files are the Zarr chunk files it writes: one per kept output and ``status`` (and,
for the chunk that draws them, one per sampled input). When the chunk is written its marker
``.sweep/done/<k>`` records, for each of these files, its size and CRC-32 (``"<size>:<crc>"``),
or ``null`` when Zarr wrote no file (every value equal to the fill value). A chunk whose files no
longer match (deleted, truncated, changed) is *damaged*: ``info`` reports it, ``export`` and
``plot`` refuse the store, and a resume recomputes it. Markers written by impactlab before the
checksums (the text ``"<k>"``) are trusted as they are.
"""

from __future__ import annotations

import json
import zlib
from collections.abc import Iterable, Mapping
from pathlib import Path

#: How many damaged chunks an error message names before "and N more".
_NAMED = 5


class DamagedStoreError(ValueError):
    """Chunks of the store are damaged (their files differ from their completion markers)."""


def chunk_key(name: str, coords: Iterable[int]) -> str:
    """The file of array ``name`` at chunk coordinates ``coords`` (Zarr v3 default encoding)."""
    return "/".join([name, "c", *(str(int(c)) for c in coords)])


def file_digest(path: Path) -> str | None:
    """``"<size>:<crc32>"`` of a file, or None when it does not exist."""
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return None
    return f"{len(data)}:{zlib.crc32(data):08x}"


def marker_text(index: int, root: Path, keys: Iterable[str]) -> str:
    """The completion marker of chunk ``index``: the digests of its files under ``root``."""
    files = {k: file_digest(root / k) for k in keys}
    return json.dumps({"chunk": index, "files": files}, sort_keys=True) + "\n"


def check_marker(root: Path, text: str) -> str | None:
    """Why the chunk recorded by marker ``text`` is damaged (e.g. ``"e/c/3/0: missing"``), or
    None when all its files match (or the marker predates the checksums)."""
    try:
        record = json.loads(text)
    except json.JSONDecodeError:
        record = None
    if not isinstance(record, dict):
        return None if text.strip().isdigit() else "unreadable completion marker"
    files = record.get("files")
    if not isinstance(files, dict):
        return "unreadable completion marker"
    for key, want in sorted(files.items()):
        got = file_digest(root / key)
        if got == want:
            continue
        if got is None:
            return f"{key}: missing"
        return f"{key}: changed ({'unexpected file' if want is None else 'size or checksum'})"
    return None


def describe(damaged: Mapping[int, str]) -> str:
    """One line naming the damaged chunks: ``"chunk 3 (e/c/3/0: missing), chunk 7 (...)"``."""
    items = [f"chunk {k} ({why})" for k, why in sorted(damaged.items())]
    more = len(items) - _NAMED
    return ", ".join(items[:_NAMED]) + (f" and {more} more" if more > 0 else "")


def damaged_error(store: Path, damaged: Mapping[int, str]) -> DamagedStoreError:
    """The error for a damaged store: names the chunks and says how to repair it."""
    return DamagedStoreError(
        f"store {str(store)!r} has {len(damaged)} damaged chunk(s): {describe(damaged)}; run the "
        f"sweep again into this store (impactlab sweep run STUDY.toml --out {store}) to recompute "
        f"them"
    )
