"""Checksums of a chunk's files, recorded in its completion marker, and their verification.

A chunk's files are the Zarr chunk files it writes: one per kept output and ``status`` (and,
for the chunk that draws them, one per sampled input). When the chunk is written its marker
``.sweep/done/<k>`` records, for each of these files, its size and CRC-32 (``"<size>:<crc>"``),
or ``null`` when Zarr wrote no file (every value equal to the fill value). A chunk whose files no
longer match (deleted, truncated, changed) is *damaged*: ``info`` reports it, ``export`` and
``plot`` refuse the store, and a resume recomputes it. Markers written by impactlab before the
checksums (the text ``"<k>"``) are trusted as they are.

The writer records the digests as it writes the files
(:class:`~impactlab.sweep.chunkfiles.ChunkWriter`), so a marker costs no second read of the
chunk's files. The store's Zarr metadata (its ``zarr.json`` files) is checked by
:func:`check_metadata`.
"""

from __future__ import annotations

import json
import zlib
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

import zarr

#: How many damaged chunks an error message names before "and N more".
_NAMED = 5


class DamagedStoreError(ValueError):
    """Chunks of the store are damaged (their files differ from their completion markers)."""


class CorruptStoreError(ValueError):
    """A store's Zarr metadata (a ``zarr.json``) cannot be read: junk, cut short, not JSON or
    not Zarr's. The message names the store, the file and what is wrong with it."""


def digest(data: Any) -> str:
    """``"<size>:<crc32>"`` of ``data`` (bytes or any contiguous buffer)."""
    view = memoryview(data)
    return f"{view.nbytes}:{zlib.crc32(view):08x}"


def file_digest(path: Path) -> str | None:
    """``"<size>:<crc32>"`` of a file, or None when it does not exist."""
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        return None
    return digest(data)


def marker_text(
    index: int,
    root: Path,
    keys: Iterable[str],
    digests: Mapping[str, str | None] | None = None,
) -> str:
    """The completion marker of chunk ``index``: the digests of its files under ``root``, taken
    from ``digests`` (recorded as the files were written) where it has the file, else read."""
    known = digests or {}
    files = {k: known[k] if k in known else file_digest(root / k) for k in keys}
    return json.dumps({"chunk": index, "files": files}, sort_keys=True) + "\n"


def check_marker(root: Path, text: str) -> str | None:
    """Why the chunk recorded by marker ``text`` is damaged (e.g. ``"e/c.3.0: missing"``), or
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
    """One line naming the damaged chunks: ``"chunk 3 (e/c.3.0: missing), chunk 7 (...)"``."""
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


def _node_problem(f: Path) -> str | None:
    """What is wrong with the Zarr metadata file ``f``, or None when Zarr reads it."""
    try:
        meta = json.loads(f.read_bytes().decode("utf-8"))
    except OSError as exc:
        return f"cannot be read ({exc.strerror or exc})"
    except UnicodeDecodeError:
        return "is not text (binary junk)"
    except json.JSONDecodeError as exc:
        return f"is not valid JSON ({exc.msg} at line {exc.lineno}, column {exc.colno})"
    if not isinstance(meta, dict):
        return f"is not a JSON object (it holds a {type(meta).__name__})"
    if meta.get("zarr_format") != 3 or meta.get("node_type") not in ("group", "array"):
        return "is not Zarr v3 metadata (zarr_format 3, node_type 'group' or 'array')"
    try:  # one node at a time: a failure names its file, and no read is left pending
        opener = zarr.open_array if meta["node_type"] == "array" else zarr.open_group
        opener(str(f.parent), mode="r")
    except Exception as exc:  # zarr raises many unrelated types for malformed metadata
        return f"is not valid Zarr metadata ({type(exc).__name__}: {exc})"
    return None


def check_metadata(path: str | Path) -> None:
    """CorruptStoreError unless the root and every sub-folder (an array, ``.sweep``) of the
    store at ``path`` have a ``zarr.json`` that reads as Zarr v3 metadata (the chunks' data is
    checked by ``SweepStore.verify``)."""
    root = Path(path)
    for node in [root, *sorted(d for d in root.iterdir() if d.is_dir())]:
        f = node / "zarr.json"
        why = _node_problem(f) if f.exists() else "is missing"
        if why is not None:
            raise CorruptStoreError(
                f"sweep store {str(root)!r} is damaged: {f.relative_to(root).as_posix()} {why}; "
                f"run the study into it again with --restart to start it fresh"
            )
