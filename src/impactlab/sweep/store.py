"""The Zarr store of a sweep: creation, per-chunk writes, completion markers with checksums,
one writer at a time, and the study hash.

- The store is built in a temporary sibling directory (``.<name>.creating-<host>-<pid>``) and
  renamed into place (:mod:`~impactlab.sweep.storebuild`), so a store exists complete or not at
  all; a killed creator leaves only its temporary sibling, removed by the next run.
- ``.sweep/done/<k>``: chunk ``k``'s completion marker, made atomically (temporary name, then
  rename) after all its arrays are written, with the size and CRC-32 of each of its files
  (:mod:`~impactlab.sweep.integrity`). A chunk without a marker reads as not computed (status
  -1, :mod:`~impactlab.sweep.status`) and is computed on resume, as is one whose files no
  longer match its marker (*damaged*); an intact one is never touched again.
- The root attributes hold the study hash; opening a store with a different study is refused
  unless the caller asks to start it fresh (the old store is moved aside atomically, then
  deleted).

The markers' files: :mod:`~impactlab.sweep.store_markers`; the temporary siblings and what
says a directory is a store: :mod:`~impactlab.sweep.store_siblings`.
"""

from __future__ import annotations

import json
import os
import shutil
import warnings
from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import xarray as xr
import zarr

from impactlab.sweep import store_markers as markers
from impactlab.sweep.chunkfiles import ChunkWriter, no_result_where_failed
from impactlab.sweep.defined_arrays import (
    damaged_defined_arrays,
    defined_arrays_error,
    rewrite_defined_arrays,
)
from impactlab.sweep.hooks import checkpoint
from impactlab.sweep.integrity import (
    CorruptStoreError,
    DamagedStoreError,
    RepairableStoreError,
    check_metadata,
    damaged_error,
    marker_text,
    recorded_engine,
)
from impactlab.sweep.locking import acquire_lock, release_lock, write_lock
from impactlab.sweep.repair import (
    mismatch_message,
    record_presentation,
    repair_metadata,
    restore_study_record,
    root_mismatch,
)
from impactlab.sweep.status import mask_undone
from impactlab.sweep.store_siblings import clean_siblings, evidence, occupied, sibling
from impactlab.sweep.storebuild import META, StoreMeta, build_store, rewrite_root
from impactlab.sweep.study import Study

__all__ = [
    "ChunkWriter",
    "CorruptStoreError",
    "DamagedStoreError",
    "RepairableStoreError",
    "StoreMeta",
    "StudyMismatchError",
    "SweepStore",
    "check_metadata",
    "open_sweep",
]


class StudyMismatchError(ValueError):
    """The store was written by a different study."""


class SweepStore:
    """A sweep's Zarr store on the local file system."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        #: the store's metadata was checked (``check_metadata``) or built by this object: the
        #: check (every array opened, ~45 ms for a sweep's 31 arrays) runs once, not per read
        self._metadata_checked = False

    # -- paths / markers -------------------------------------------------------------------------

    @property
    def _meta(self) -> Path:
        return self.path / META

    @property
    def _lock(self) -> Path:
        return self._meta / "lock"

    def exists(self) -> bool:
        """A store, built to its study record (written after the root's ``zarr.json``)."""
        return (self._meta / "study.json").is_file() and (
            (self.path / "zarr.json").is_file() or recorded_engine(self.path) is not None
        )

    def done_chunks(self) -> set[int]:
        """Indices of the chunks whose completion marker exists (intact or not: ``verify``),
        among the store's chunks (a stray marker such as ``done/99`` of a 3-chunk store is
        not one of them)."""
        marked = markers.done_chunks(self.path)
        total = self._n_chunks()
        return marked if total is None else {k for k in marked if k < total}

    def _n_chunks(self) -> int | None:
        """The number of chunks the root attributes give (None where they cannot be read)."""
        try:
            total = json.loads((self.path / "zarr.json").read_bytes())["attributes"]["n_chunks"]
        except (OSError, ValueError, KeyError, TypeError):
            return None
        return total if isinstance(total, int) and not isinstance(total, bool) else None

    def mark_done(self, index: int, text: str) -> None:
        """Create chunk ``index``'s completion marker (content ``text``) atomically (the markers'
        folder made again where it was deleted: its chunks are computed again, not lost)."""
        markers.mark_done(self.path, index, text)

    def verify(self, indices: Iterable[int] | None = None) -> dict[int, str]:
        """The damaged chunks among ``indices`` (default: every chunk marked done), each with
        what is wrong with it (e.g. ``"e/c.3.0: missing"``)."""
        return markers.damaged_chunks(self.path, self.done_chunks() if indices is None else indices)

    def discard(self, indices: Iterable[int]) -> None:
        """Forget chunks (remove their markers): the next run computes them again."""
        markers.discard(self.path, indices)

    def attrs(self) -> dict[str, Any]:
        """The root attributes; CorruptStoreError where the metadata is damaged (checked at the
        first read of a store this object did not build)."""
        if not self._metadata_checked:
            check_metadata(self.path)
            self._metadata_checked = True
        return dict(zarr.open_group(str(self.path), mode="r").attrs)

    def study_hash(self) -> str | None:
        if not self.exists():
            return None
        h = self.attrs().get("study_hash")
        return None if h is None else str(h)

    def clean_partial(self) -> int:
        """Remove temporary files left by a killed writer (Zarr's ``*.partial``, our ``*.tmp``)."""
        return markers.clean_partial(self.path)

    # -- creation and removal --------------------------------------------------------------------

    def create(self, study: Study, meta: StoreMeta) -> bool:
        """Build the store for ``study`` in a temporary sibling, locked by this process, and
        rename it into place. False when another process put a store there first."""
        tmp = sibling(self.path, "creating")
        shutil.rmtree(tmp, ignore_errors=True)
        tmp.mkdir(parents=True)
        checkpoint("create:tempdir")
        build_store(tmp, study, meta)
        write_lock(tmp / META / "lock")
        checkpoint("create:built")
        try:
            os.rename(tmp, self.path)  # replaces an empty directory, never a full one
        except OSError:
            if not occupied(self.path):
                raise
            shutil.rmtree(tmp, ignore_errors=True)
            return False
        checkpoint("create:renamed")
        self._metadata_checked = True  # built here, under this process's lock
        return True

    def remove(self) -> None:
        """Delete the store (to start a changed study fresh, on explicit request): moved aside
        atomically, then deleted, so a kill midway leaves no half-deleted store."""
        if not self.path.exists():
            return
        if occupied(self.path) and not evidence(self.path):
            raise ValueError(f"refusing to remove {str(self.path)!r}: not a sweep store")
        trash = sibling(self.path, "removing")
        shutil.rmtree(trash, ignore_errors=True)
        self._metadata_checked = False
        os.rename(self.path, trash)
        checkpoint("restart:moved")
        shutil.rmtree(trash)

    def prepare(self, study: Study, meta: StoreMeta, *, restart: bool = False) -> set[int]:
        """Create the store, or reopen it for the same study, and take its lock; returns the
        chunks marked done (``verify`` tells which of them are damaged).

        A store written by another study (different hash) is refused with StudyMismatchError
        unless ``restart=True``, which deletes it and starts fresh. A store whose creation was
        interrupted holds no results and is started afresh.
        """
        clean_siblings(self.path)
        if not self.exists():
            restore_study_record(self.path, study, meta)
        if occupied(self.path) and not self.exists():
            found = evidence(self.path)
            if not found:
                raise ValueError(f"{str(self.path)!r} is not a sweep store; choose another --out")
            if (found == "group" or self.done_chunks()) and not restart:
                raise ValueError(
                    f"store {str(self.path)!r} lacks its study record (.sweep/study.json): its "
                    f"creation was cut short; run with --restart (restart=True in Python) to "
                    f"discard it and start fresh"
                )
            self.remove()  # cut short while being created: nothing to keep
        if self.exists():
            self.acquire()
            try:
                old = self.study_hash()
            except RepairableStoreError as problem:
                old = self._repaired_hash(problem, study, meta, restart)
            except CorruptStoreError:
                if not restart:
                    self.release()
                    raise
                old = None  # damaged metadata: nothing to keep
            if old == meta.study_hash and not restart:
                self.clean_partial()
                rewrite_defined_arrays(self.path, study)  # a coordinate's file gone or cut
                record_presentation(self.path, study)  # an edited description: this one's
                return self.done_chunks()
            if not restart:
                self.release()
                raise StudyMismatchError(
                    mismatch_message(self.path, old, self._root_attrs(), study, meta)
                )
            self.remove()
        if not self.create(study, meta):
            return self.prepare(study, meta)  # another process put a store there first
        return set()

    def _root_attrs(self) -> dict[str, Any]:
        """The root group's attributes as stored, unchecked ({} where they cannot be read)."""
        try:
            return dict(zarr.open_group(str(self.path), mode="r").attrs)
        except Exception:  # a damaged store: nothing to explain from
            return {}

    def _repaired_hash(
        self, problem: RepairableStoreError, study: Study, meta: StoreMeta, restart: bool
    ) -> str | None:
        """The study hash of a store whose result arrays or study record need rewriting
        (``repair_metadata``): repaired when it holds this study (not on ``restart``, which
        starts it fresh); another study's store is left as it is."""
        if problem.root is not None:  # rewritten from the study record, for this study only
            if restart:
                return None
            why = root_mismatch(self.path, study, meta)
            if why is not None:
                self.release()
                raise StudyMismatchError(why)
            rewrite_root(self.path, study, meta)
            self._metadata_checked = False
            try:
                return self.study_hash()
            except RepairableStoreError as more:
                return self._repaired_hash(more, study, meta, restart)
        raw = zarr.open_group(str(self.path), mode="r").attrs.get("study_hash")
        old = None if raw is None else str(raw)
        if restart or old != meta.study_hash:
            return old
        repair_metadata(self.path, problem, study, meta)
        self._metadata_checked = False
        return self.study_hash()

    # -- one writer at a time --------------------------------------------------------------------

    def acquire(self) -> None:
        """Mark the store as being written by this process; refuse if another live process on
        this host holds it (a lock left by a killed process is taken over)."""
        acquire_lock(self._lock, self.path)

    def release(self) -> None:
        """Remove this process's lock."""
        release_lock(self._lock)

    # -- writes ----------------------------------------------------------------------------------

    def writer(self, names: Sequence[str]) -> ChunkWriter:
        """The arrays ``names`` opened for ``write_chunk`` (close the writer when done)."""
        return ChunkWriter(self.path, names)

    def write_chunk(
        self,
        writer: ChunkWriter,
        study: Study,
        index: int,
        outputs: Mapping[str, np.ndarray],
        status: np.ndarray,
    ) -> None:
        """Write chunk ``index``'s outputs and status (1-D, C order over the block), the sampled
        inputs of its cases (every chunk of a sample block writes them, the same bytes: the
        chunks finish in any order, and a store interrupted with some done holds the inputs of
        each), then its completion marker with the files' checksums.
        Every output of a case with status != 0 is stored as "no result" (NaN, the fill value
        -1 of an integer output such as ``regime`` or ``flags``), whatever the engine left."""
        lay = study.layout
        block = lay.block(index)
        bshape = tuple(s.stop - s.start for s in block)
        codes = np.asarray(status, dtype=np.int32).reshape(bshape)
        items: list[tuple[str, Any, np.ndarray]] = []
        for name, values in outputs.items():
            items.append((name, block, no_result_where_failed(values, codes, writer.arrays[name])))
        items.append(("status", block, codes))
        if study.sample is not None:
            sl = block[-1]
            draw = study.sample.draw
            items.extend((n, sl, draw(n, sl.start, sl.stop)) for n in study.sample.inputs)
        digests = writer.write(items)
        checkpoint(f"chunk:{index}:data")
        self.mark_done(index, marker_text(index, self.path, list(digests), digests))
        checkpoint(f"chunk:{index}:done")

    # -- reading ---------------------------------------------------------------------------------

    def dataset(self) -> xr.Dataset:
        """The store as a lazy xarray Dataset."""
        return open_sweep(self.path)


def open_dataset(path: Path) -> xr.Dataset:
    """The store at ``path`` as xarray opens it, unchecked and unmasked; a folder that is not a
    Zarr node (``check_metadata`` ignores it) is passed over without Zarr's warning."""
    with warnings.catch_warnings():
        warnings.filterwarnings("ignore", "Object at .* is not recognized as a component")
        return xr.open_zarr(str(path), consolidated=False)


def _node_type(path: Path) -> str | None:
    """The ``node_type`` of the Zarr node at ``path`` ("group", "array"; None when unreadable)."""
    try:
        meta = json.loads((path / "zarr.json").read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return None
    return meta.get("node_type") if isinstance(meta, dict) else None


def open_sweep(path: str | Path, *, verify: bool = True) -> xr.Dataset:
    """Open a sweep store (lazy, dask-backed). Status messages: ``ds.attrs['status_messages']``.

    verify : check every finished chunk's files against its checksums first and refuse a
        damaged store (``DamagedStoreError`` naming the chunks; a resume recomputes them).
    """
    p = Path(path)
    if not (p / "zarr.json").is_file() and not SweepStore(p).exists():
        raise ValueError(f"{str(p)!r} is not a sweep store (no zarr.json)")
    if (p.parent / "zarr.json").is_file() and _node_type(p) == "array":
        raise ValueError(
            f"{str(p)!r} is an array inside the sweep store {str(p.parent)!r}: give the store's "
            "folder"
        )
    check_metadata(p)
    damaged = SweepStore(p).verify() if verify else {}
    if damaged:
        raise damaged_error(p, damaged)
    broken = damaged_defined_arrays(p)  # no marker covers them: read NaN or not at all
    if broken:
        raise defined_arrays_error(p, broken)
    try:
        ds = open_dataset(p)
    except Exception as exc:  # what check_metadata cannot see; named, not a deep traceback
        raise CorruptStoreError(
            f"cannot open sweep store {str(p)!r}: {type(exc).__name__}: {exc}"
        ) from exc
    order = [*ds.attrs.get("outputs", []), "status"]
    names = [v for v in order if v in ds.data_vars] + [v for v in ds.data_vars if v not in order]
    return mask_undone(ds[names], SweepStore(p).done_chunks())
