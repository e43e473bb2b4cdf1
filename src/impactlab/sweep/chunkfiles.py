"""The writer of a sweep's chunks: each chunk of each array encoded with the array's own Zarr
codecs, called through Zarr's synchronous codec protocol (``zarr.abc.codec.SupportsSyncCodec``),
and written as one file, with the file's digest recorded for the completion marker.

A sweep chunk is always whole Zarr chunks (the store is chunked exactly like the work), so no
chunk is ever read back, merged or shared. Zarr's own ``array[block] = values`` does the same
encoding but, per array, through its async indexing and batching machinery: measured on the
sweep benchmark's 28 arrays of 65 536 values, 46 ms of CPU per chunk against 15 ms here
(docs/sweep.md, "Benchmark"), which is what the engine's other core loses when all cores
compute. The bytes are Zarr's (tested equal to ``array[block] = values``, edge chunks and empty
chunks included: a chunk left all fill value gets no file, as with Zarr's default
``write_empty_chunks=False``).

Files are atomic: a ``*.partial`` name first, then a rename (a writer killed midway leaves the
``*.partial`` file, removed on resume). An array whose codecs cannot encode synchronously
(none that a sweep creates) is written by Zarr itself and its digest read back from the file.
"""

from __future__ import annotations

import os
import shutil
from collections.abc import Callable, Sequence
from contextlib import suppress
from pathlib import Path
from typing import Any, cast

import numpy as np
import zarr
from zarr.abc.codec import SupportsSyncCodec
from zarr.core.buffer import default_buffer_prototype
from zarr.core.codec_pipeline import codecs_from_list

from impactlab.sweep.integrity import digest, file_digest

#: (name, selection, values): one array's part of a chunk; the selection is the chunk's block
#: (a tuple of slices, or one slice for a 1-D array).
Item = tuple[str, Any, np.ndarray]


def no_result_where_failed(values: Any, status: np.ndarray, array: ArrayChunks) -> np.ndarray:
    """One output's ``values`` for ``array``, shaped as ``status``: the fill value (NaN; -1 for
    an integer output such as ``regime`` or ``flags``) where the case has no result (a status
    != 0, or a NaN given for an integer output)."""
    v = np.asarray(values).reshape(status.shape)
    failed = status != 0
    if array.dtype.kind in "iu":
        keep = ~failed & np.isfinite(v) if v.dtype.kind == "f" else ~failed
        return np.where(keep, v, array.fill)
    return np.where(failed, np.nan, v) if failed.any() else v


class ArrayChunks:
    """One array of a store, opened for whole-chunk writes through its own codecs."""

    def __init__(self, array: Any) -> None:
        md = array.metadata
        self.array = array
        self.shape: tuple[int, ...] = tuple(md.shape)
        self.chunks: tuple[int, ...] = tuple(md.chunks)
        self.key = md.encode_chunk_key
        proto = default_buffer_prototype()
        self._nd = proto.nd_buffer
        spec = md.get_chunk_spec((0,) * len(self.shape), array.config, proto)
        self.fill = spec.fill_value
        self.dtype = spec.dtype.to_native_dtype()
        self.skip_empty = not spec.config.write_empty_chunks
        aa, ab, bb = codecs_from_list(md.codecs)
        self.stages: list[tuple[Any, Any]] = []
        codecs: tuple[Any, ...] = (*aa, ab, *bb)
        for codec in codecs:
            self.stages.append((codec, spec))
            spec = codec.resolve_metadata(spec)
        self.direct = all(isinstance(c, SupportsSyncCodec) for c, _ in self.stages)

    def coords(self, selection: Any) -> tuple[int, ...]:
        """The chunk coordinates of a chunk-aligned ``selection`` (ValueError otherwise)."""
        sel = selection if isinstance(selection, tuple) else (selection,)
        if any(s.start % c for s, c in zip(sel, self.chunks, strict=True)):
            raise ValueError(
                f"array {self.array.basename!r}: block {sel} does not start on a chunk "
                f"boundary (chunks {self.chunks})"
            )
        return tuple(s.start // c for s, c in zip(sel, self.chunks, strict=True))

    def chunk(self, selection: Any, values: np.ndarray) -> np.ndarray:
        """The whole chunk holding ``values`` at ``selection`` (an edge chunk padded with the
        fill value, as Zarr stores it), in the array's dtype."""
        v = np.asarray(values).astype(self.dtype, copy=False)
        sel = selection if isinstance(selection, tuple) else (selection,)
        want = tuple(min(s.stop, n) - s.start for s, n in zip(sel, self.shape, strict=True))
        if v.shape != want:
            raise ValueError(
                f"array {self.array.basename!r}: values of shape {v.shape} for a chunk block of "
                f"shape {want}"
            )
        if v.shape == self.chunks:
            return np.ascontiguousarray(v)
        full = np.full(self.chunks, self.fill, dtype=self.dtype)
        full[tuple(slice(0, n) for n in v.shape)] = v
        return full

    def _maybe_empty(self, chunk: np.ndarray) -> bool:
        """False when the chunk's first value already differs from the fill value (the usual
        case: Zarr's full comparison is then skipped)."""
        first = chunk.flat[0]
        fill = self.fill
        return bool(first == fill or (first != first and fill != fill))

    def encode(self, chunk: np.ndarray) -> Any:
        """The bytes of ``chunk`` as Zarr writes them, or None for a chunk Zarr does not write
        (all fill value)."""
        buf: Any = self._nd.from_ndarray_like(cast(Any, chunk))
        if self.skip_empty and self._maybe_empty(chunk) and buf.all_equal(self.fill):
            return None
        for codec, spec in self.stages:
            buf = codec._encode_sync(buf, spec)
        return buf.as_buffer_like()


def _write_file(path: str, data: Any) -> None:
    tmp = f"{path}.{os.getpid()}.partial"
    try:
        with open(tmp, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        with suppress(OSError):
            os.unlink(tmp)
        raise


def _unless_folder(path: str, action: Callable[..., None], *args: Any) -> None:
    """``action(*args)`` on the chunk file ``path``; where a folder stands in its place (made
    there by hand: the chunk reads as damaged), the folder is removed first and it is done
    again."""
    try:
        action(*args)
    except OSError:
        if not os.path.isdir(path):
            raise
        shutil.rmtree(path)
        action(*args)


class ChunkWriter:
    """Arrays ``names`` of the store at ``path`` opened for ``SweepStore.write_chunk``."""

    def __init__(self, path: Path, names: Sequence[str]) -> None:
        self.root = str(path)
        group = zarr.open_group(self.root, mode="r+")
        self.arrays = {n: ArrayChunks(group[n]) for n in names}
        self._dirs: set[str] = set()

    def key(self, name: str, selection: Any) -> str:
        """The store key (file) of the chunk of array ``name`` at ``selection``."""
        a = self.arrays[name]
        return f"{name}/{a.key(a.coords(selection))}"

    def write(self, items: Sequence[Item]) -> dict[str, str | None]:
        """Write ``(name, selection, values)`` items, each one whole chunk; returns the digests
        of the files by key (None: no file, the chunk being all fill value)."""
        return dict(self._write_one(*item) for item in items)

    def _write_one(self, name: str, selection: Any, values: np.ndarray) -> tuple[str, str | None]:
        a = self.arrays[name]
        key = self.key(name, selection)
        path = os.path.join(self.root, key)
        if not a.direct:  # codecs without a synchronous form: Zarr writes, the file is read
            a.array[selection] = values
            return key, file_digest(Path(path))
        data = a.encode(a.chunk(selection, values))
        if data is None:
            with suppress(FileNotFoundError):
                _unless_folder(path, os.unlink, path)
            return key, None
        folder = os.path.dirname(path)
        if folder not in self._dirs:
            os.makedirs(folder, exist_ok=True)
            self._dirs.add(folder)
        _unless_folder(path, _write_file, path, data)
        return key, digest(data)

    def close(self) -> None:
        """Nothing is held open between writes (kept for the writer's interface)."""
