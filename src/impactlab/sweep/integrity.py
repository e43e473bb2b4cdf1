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

from impactlab.sweep.node_meta import mismatch, root_attrs_problem

#: How many damaged chunks an error message names before "and N more".
_NAMED = 5


class DamagedStoreError(ValueError):
    """Chunks of the store are damaged (their files differ from their completion markers)."""


class CorruptStoreError(ValueError):
    """A store's Zarr metadata (a ``zarr.json``) cannot be read: junk, cut short, not JSON or
    not Zarr's. The message names the store, the file and what is wrong with it."""


class RepairableStoreError(CorruptStoreError):
    """Metadata that a resume of the same study rewrites: arrays whose ``zarr.json`` is gone,
    unreadable or no longer matches the study (``node_meta.mismatch``) (``missing_arrays``: a
    kept output, ``status``, or an array the store was built with, named in the root's
    consolidated metadata: a coordinate, an input, the ``.sweep`` group; their metadata follows
    from the study), a ``.sweep/study.json`` that is not a JSON object (``study_record``: what
    is wrong with it, or None), or the root's ``zarr.json``, also one without the study's
    attributes (``root``: what is wrong with it, or None; rewritten from the study record and
    the engine identity kept in ``.sweep/zarr.json``). The intact chunks are kept; those whose
    files are gone are computed again."""

    def __init__(
        self,
        message: str,
        missing_arrays: tuple[str, ...],
        study_record: str | None,
        root: str | None = None,
    ) -> None:
        super().__init__(message)
        self.missing_arrays = missing_arrays
        self.study_record = study_record
        self.root = root


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
        try:
            got = file_digest(root / key)
        except IsADirectoryError:
            return f"{key}: a folder, not a file"
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


def _read_json(f: Path) -> tuple[object, str | None]:
    """(the JSON value of the file ``f``, None), or (None, what is wrong with it)."""
    try:
        return json.loads(f.read_bytes().decode("utf-8")), None
    except OSError as exc:
        return None, f"cannot be read ({exc.strerror or exc})"
    except UnicodeDecodeError:
        return None, "is not text (binary junk)"
    except json.JSONDecodeError as exc:
        what = exc.msg.removesuffix(" at")  # "Invalid control character at": the position follows
        return None, f"is not valid JSON ({what} at line {exc.lineno}, column {exc.colno})"


def _json_object(f: Path) -> dict[str, Any]:
    """The JSON object of the file ``f`` ({} where it is not one)."""
    value = _read_json(f)[0]
    return value if isinstance(value, dict) else {}


def _node_problem(f: Path) -> str | None:
    """What is wrong with the Zarr metadata file ``f``, or None when Zarr reads it."""
    meta, problem = _read_json(f)
    if problem is not None:
        return problem
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


def _result_arrays(root: Path) -> tuple[str, ...]:
    """The arrays written chunk by chunk (the kept outputs and ``status``) that the root
    attributes of the store at ``root`` name (its ``zarr.json`` already checked)."""
    attrs = json.loads((root / "zarr.json").read_bytes()).get("attributes")
    outputs = attrs.get("outputs") if isinstance(attrs, dict) else None
    if not isinstance(outputs, list) or not attrs.get("study_hash"):
        return ()
    return (*(str(o) for o in outputs), "status")


def _study_record_problem(root: Path) -> str | None:
    """What is wrong with ``.sweep/study.json`` (not JSON, not an object), or None (also when
    there is none: a store cut short while being created, see ``SweepStore.prepare``)."""
    f = root / ".sweep" / "study.json"
    if not f.is_file():
        return None
    record, problem = _read_json(f)
    if problem is not None:
        return problem
    return None if isinstance(record, dict) else "is not a JSON object"


def recorded_engine(root: Path) -> str | None:
    """The engine identity a store keeps beside its study record (the attribute ``engine`` of
    ``.sweep/zarr.json``), where that and a readable ``.sweep/study.json`` are there; else None
    (a store written before the identity was kept there, or its bookkeeping damaged too)."""
    if _study_record_problem(root) is not None or not (root / ".sweep" / "study.json").is_file():
        return None
    meta, problem = _read_json(root / ".sweep" / "zarr.json")
    attrs = meta.get("attributes") if problem is None and isinstance(meta, dict) else None
    engine = attrs.get("engine") if isinstance(attrs, dict) else None
    return engine if isinstance(engine, str) else None


def _corrupt(root: Path, node: Path, why: str) -> CorruptStoreError:
    return CorruptStoreError(
        f"sweep store {str(root)!r} is damaged: {node.relative_to(root).as_posix()} {why}; "
        f"run the study into it again with --restart (restart=True in Python) to start it "
        f"fresh"
    )


def _built_nodes(root: Path) -> dict[str, Any]:
    """The nodes the store at ``root`` was built with: their names and metadata as its root
    ``zarr.json`` (already checked) lists them in its consolidated metadata (none without it)."""
    meta = json.loads((root / "zarr.json").read_bytes()).get("consolidated_metadata")
    nodes = meta.get("metadata") if isinstance(meta, dict) else None
    items = nodes.items() if isinstance(nodes, dict) else ()
    return {str(k): v for k, v in items if "/" not in str(k)}


def _array_problem(name: str, why: str, results: tuple[str, ...]) -> str:
    """``"result array 'e' is gone: e/zarr.json is missing"``, ``"array 'mu': mu/zarr.json is
    not valid JSON (...)"``."""
    if name in results:
        gone = why == "is missing"
        return (
            f"result array {name!r} {'is gone' if gone else 'is damaged'}: {name}/zarr.json {why}"
        )
    return f"{'group' if name.startswith('.') else 'array'} {name!r}: {name}/zarr.json {why}"


def check_metadata(path: str | Path) -> None:
    """CorruptStoreError unless the root and every sub-folder (an array, ``.sweep``) of the
    store at ``path`` have a ``zarr.json`` that reads as Zarr v3 metadata (the chunks' data is
    checked by ``SweepStore.verify``; a folder that is none of the store's nodes and holds no
    ``zarr.json``, such as ``.ipynb_checkpoints``, is ignored, as a plain file is).
    RepairableStoreError (a CorruptStoreError) when only
    metadata that follows from the study is gone, unreadable or no longer matches the study
    (that of a result array, or of an array or group the store was built with: its data type,
    shape, chunks, fill value, dimension names, ...; a root without the study's attributes) or
    ``.sweep/study.json`` is not JSON: a resume repairs those, keeping the chunks."""
    root = Path(path)
    f = root / "zarr.json"
    why = _node_problem(f) if f.exists() else "is missing"
    if why is None and (root / ".sweep").is_dir():  # a sweep store's root: its attributes
        why = root_attrs_problem(_json_object(f))
    if why is not None and recorded_engine(root) is not None:
        raise RepairableStoreError(
            f"sweep store {str(root)!r} is damaged: zarr.json {why}; run the same study into it "
            f"again (impactlab sweep run STUDY.toml --out {root}) to rewrite it from the study "
            "record (.sweep/study.json): the chunks are kept (--restart would discard them all)",
            (),
            None,
            why,
        )
    if why is not None:
        raise _corrupt(root, f, why)
    results = _result_arrays(root)
    built = _built_nodes(root) if results else {}
    attrs = _json_object(root / "zarr.json").get("attributes") or {}
    damaged = {n: "is missing" for n in results if not (root / n / "zarr.json").exists()}
    for node in sorted(d for d in root.iterdir() if d.is_dir() and d.name not in damaged):
        f = node / "zarr.json"
        part = node.name in results or node.name in built or node.name == ".sweep"
        if not part and not f.exists():
            continue  # not a Zarr node of the store (.ipynb_checkpoints, plots/): ignored
        why = _node_problem(f) if f.exists() else "is missing"
        if why is None and (node.name in results or node.name in built):
            why = mismatch(node.name, _json_object(f), built.get(node.name), attrs, results)
        if why is not None and (node.name in results or node.name in built):
            damaged[node.name] = why  # follows from the study: written again by a resume
        elif why is not None:
            raise _corrupt(root, f, why)
    record = _study_record_problem(root)
    if not damaged and record is None:
        return
    problems = [_array_problem(n, why, results) for n, why in sorted(damaged.items())]
    problems += [f".sweep/study.json {record}"] if record is not None else []
    raise RepairableStoreError(
        f"sweep store {str(root)!r} is damaged: {'; '.join(problems)}; run the same study into "
        f"it again (impactlab sweep run STUDY.toml --out {root}) to rewrite it: the intact "
        "chunks are kept and those that lack data are computed again (--restart would discard "
        "them all)",
        tuple(sorted(damaged)),
        record,
    )
