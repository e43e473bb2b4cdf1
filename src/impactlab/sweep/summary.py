"""Summaries of a sweep store: case status counts, flagged results, and its progress and contents
(what ``impactlab sweep info`` and ``impactlab sweep run`` print). Damaged chunks (files that no
longer match their checksums) are reported, and left out of the counts."""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import zarr

from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages
from impactlab.sweep.dimensions import Layout
from impactlab.sweep.integrity import describe
from impactlab.sweep.slabs import slabs, store_chunks
from impactlab.sweep.status import STATUS_NOT_RUN
from impactlab.sweep.store import SweepStore, open_sweep

#: At most this many cases of a store are in memory at a time while they are counted.
COUNT_BLOCK_CASES = 1 << 20


def _blocks(ds: Any, name: str) -> Iterator[np.ndarray]:
    """The values of ``ds[name]`` (the case array) a block at a time (``slabs``)."""
    var = ds[name]
    for slab in slabs(tuple(var.shape), COUNT_BLOCK_CASES, store_chunks(ds)):
        yield np.asarray(var[slab].values).ravel()


def _counts(blocks: Iterable[np.ndarray], msgs: Mapping[str, str]) -> dict[str, int]:
    tally: Counter[int] = Counter()
    for values in blocks:
        codes, counts = np.unique(values, return_counts=True)
        tally.update({int(c): int(n) for c, n in zip(codes, counts, strict=True)})
    return {f"{c}: {msgs.get(str(c), '?')}": tally[c] for c in sorted(tally)}


def status_counts(ds: Any) -> dict[str, int]:
    """Number of cases per status, keyed "<code>: <message>" (code 0: ok); a store is read a
    block at a time (``COUNT_BLOCK_CASES``)."""
    return _counts(_blocks(ds, "status"), ds.attrs.get("status_messages", {}))


def dataset_flag_counts(ds: Any) -> dict[str, int]:
    """``flag_counts`` of the sweep ``ds``'s ``flags``, a block at a time."""
    attrs = ds["flags"].attrs
    total: Counter[str] = Counter()
    for values in _blocks(ds, "flags"):
        total.update(flag_counts(values, attrs))
    return {"flagged": total["flagged"]} | {name: total[name] for _, name in _flag_bits(attrs)}


#: Each flag's label in the counts (its message's head: "gravity-dominated", "beyond the tip"),
#: by mask; and its name (``ResultFlag``'s, lower case: ``beyond_tip``), by label.
_FLAG_LABELS = {int(f): messages(f)[0].split(":")[0] for f in ResultFlag if f.value}
FLAG_NAMES = {label: str(ResultFlag(m).name).lower() for m, label in _FLAG_LABELS.items()}


def _flag_bits(attrs: Mapping[str, Any]) -> list[tuple[int, str]]:
    """(mask, label) of each flag of a ``flags`` variable (CF ``flag_masks``/``flag_meanings``;
    a known mask by its label, whatever name an older store wrote)."""
    masks = [int(m) for m in attrs.get("flag_masks", [])]
    names = str(attrs.get("flag_meanings", "")).split()
    return [
        (m, _FLAG_LABELS.get(m, n.replace("_", " "))) for m, n in zip(masks, names, strict=False)
    ]


def flag_counts(flags: np.ndarray, attrs: Mapping[str, Any]) -> dict[str, int]:
    """Number of cases carrying each result flag (``impactlab.flags.ResultFlag``), by name;
    "flagged": cases with any flag. Cases without a result (-1) are not counted."""
    f = np.asarray(flags).ravel()
    f = f[f > 0]
    out = {"flagged": int(f.size)}
    for mask, name in _flag_bits(attrs):
        out[name] = int(np.count_nonzero(f & mask))
    return out


#: The names of the advisory flags (``ADVISORY_FLAGS``: the result stays ``ok``), as counted.
_ADVISORY = {messages(f)[0].split(":")[0] for f in ResultFlag if f & ADVISORY_FLAGS}


def format_flag_counts(counts: Mapping[str, int]) -> str:
    """``"12 case(s) (energy gain: 10, law extrapolated (advisory): 2)"`` (``"none"`` when 0);
    an advisory flag (the result stays ``ok``) is marked so."""
    if not counts.get("flagged"):
        return "none"
    parts = ", ".join(
        f"{k}{' (advisory)' if k in _ADVISORY else ''}: {v:,}"
        for k, v in counts.items()
        if k != "flagged" and v
    )
    return f"{counts['flagged']:,} case(s) ({parts})"


def _intact_values(path: Path, name: str, damaged: set[int], done: set[int]) -> np.ndarray:
    """The values of array ``name`` of a store with damaged chunks, chunk by chunk, leaving
    those out (reading them could fail); a chunk without its completion marker reads -1
    (status: not computed; an integer output: no result), as ``open_sweep`` reads it."""
    z = zarr.open_array(str(path / name), mode="r")
    lay = Layout(tuple(f"dim_{i}" for i in range(z.ndim)), tuple(z.shape), tuple(z.chunks))
    parts = [
        np.full(lay.block_size(k), STATUS_NOT_RUN, dtype=z.dtype)
        if k not in done
        else np.asarray(z[lay.block(k)]).ravel()
        for k in range(lay.n_chunks)
        if k not in damaged
    ]
    return np.concatenate(parts) if parts else np.empty(0, dtype=z.dtype)


def store_info(path: str | Path) -> dict[str, Any]:
    """Progress and contents of the store at ``path``: title, study hash, mode, dimensions,
    cases, chunks done (intact), damaged chunks, outputs, status counts and flagged results."""
    p = Path(path)
    ds = open_sweep(p, verify=False)
    store = SweepStore(p)
    damaged = store.verify()
    done = len(store.done_chunks()) - len(damaged)
    info: dict[str, Any] = {
        "title": ds.attrs.get("title"),
        "study_hash": ds.attrs.get("study_hash"),
        "mode": ds.attrs.get("mode"),
        "dims": {str(k): int(v) for k, v in ds.sizes.items()},
        "cases": ds.attrs.get("n_cases"),
        "chunks_done": f"{done} of {ds.attrs.get('n_chunks')}",
    }
    if damaged:
        info["damaged"] = (
            f"{len(damaged)} chunk(s), not counted below: {describe(damaged)}; run the sweep "
            f"again into this store to recompute them"
        )
    info["outputs"] = list(ds.attrs.get("outputs", []))
    if not damaged:  # the lazy Dataset, a block at a time
        info["status"] = status_counts(ds)
        if "flags" in ds.data_vars:
            info["flagged"] = format_flag_counts(dataset_flag_counts(ds))
        return info
    msgs = ds.attrs.get("status_messages", {})
    marked = store.done_chunks()
    info["status"] = _counts([_intact_values(p, "status", set(damaged), marked)], msgs)
    if "flags" in ds.data_vars:
        flags = _intact_values(p, "flags", set(damaged), marked)
        info["flagged"] = format_flag_counts(flag_counts(flags, ds["flags"].attrs))
    return info


def incomplete_note(path: str | Path) -> str | None:
    """``"store incomplete: 68 of 100 chunks done; run the study again to finish it"`` for
    the store at ``path`` (already opened: its metadata checked), counting its intact chunks;
    None when every chunk is done."""
    store = SweepStore(Path(path))
    total = store.attrs().get("n_chunks")
    done = len(store.done_chunks()) - len(store.verify())
    if not isinstance(total, int) or done >= total:
        return None
    return f"store incomplete: {done} of {total} chunks done; run the study again to finish it"
