"""Summaries of a sweep store: case status counts, flagged results, and its progress and contents
(what ``impactlab sweep info`` and ``impactlab sweep run`` print). Damaged chunks (files that no
longer match their checksums) are reported, and left out of the counts."""

from __future__ import annotations

import json
from collections import Counter
from collections.abc import Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import zarr

from impactlab._version import __version__
from impactlab.flags import ADVISORY_FLAGS, ResultFlag, messages
from impactlab.sweep.dimensions import Layout
from impactlab.sweep.display import ADVISORY_NAMES, TOTALS, not_ok_text
from impactlab.sweep.inputs import get_input
from impactlab.sweep.integrity import describe
from impactlab.sweep.slabs import slabs, store_chunks
from impactlab.sweep.status import STATUS_BAD_LAW, STATUS_NOT_RUN, mask_undone
from impactlab.sweep.store import SweepStore, open_dataset, open_sweep

#: At most this many cases of a store are in memory at a time while they are counted.
COUNT_BLOCK_CASES = 1 << 20


def _blocks(ds: Any, name: str) -> Iterator[np.ndarray]:
    """The values of ``ds[name]`` (the case array) a block at a time (``slabs``)."""
    var = ds[name]
    for slab in slabs(tuple(var.shape), COUNT_BLOCK_CASES, store_chunks(ds)):
        yield np.asarray(var[slab].values).ravel()


#: The label of status 0 in the counts: the engine ran the case to its end (whether its result
#: is ok, the flags say: the engine's own message "ok" would read as that).
FINISHED = "finished"


def _counts(blocks: Iterable[np.ndarray], msgs: Mapping[str, str]) -> dict[str, int]:
    tally: Counter[int] = Counter()
    for values in blocks:
        codes, counts = np.unique(values, return_counts=True)
        tally.update({int(c): int(n) for c, n in zip(codes, counts, strict=True)})
    labels = {**msgs, "0": FINISHED}
    return {f"{c}: {labels.get(str(c), '?')}": tally[c] for c in sorted(tally)}


def status_counts(ds: Any) -> dict[str, int]:
    """Number of cases per status, keyed "<code>: <message>" (``"0: finished"``: the engine ran
    the case to its end; the flags say whether its result is ok); a store is read a
    block at a time (``COUNT_BLOCK_CASES``). The message of the cases the contact law refused
    (``STATUS_BAD_LAW``) ends with the law's own words for the first of them
    (:func:`law_words`)."""
    msgs = dict(ds.attrs.get("status_messages", {}))
    counts = _counts(_blocks(ds, "status"), msgs)
    bad = str(STATUS_BAD_LAW)
    if f"{bad}: {msgs.get(bad, '?')}" not in counts:
        return counts
    words = law_words(ds)
    if not words:
        return counts
    return {(f"{k}; {words}" if k.startswith(f"{bad}:") else k): n for k, n in counts.items()}


def law_words(ds: Any) -> str:
    """What the contact law says of the first case of the sweep ``ds`` that it refused
    (``STATUS_BAD_LAW``), with that case's grid coordinates: ``"first at flat_E = 1e+09 Pa:
    the 'ghaednia' law gives ..."``; "" when there is none, or the study is not readable here
    (a law of one's own that this process does not know)."""
    where = _first_refused(ds)
    if where is None or "study" not in ds.attrs:
        return ""
    from impactlab.sweep.models import law_problem
    from impactlab.sweep.study_record import recorded_study

    try:
        study = recorded_study(json.loads(ds.attrs["study"]))
        lay = study.layout
        pos = tuple(where[d] for d in lay.dims)
        chunk = tuple(p // c for p, c in zip(pos, lay.chunks, strict=True))
        k = int(np.ravel_multi_index(chunk, lay.chunk_grid))
        numeric, categories, shape = study.chunk_cases(k)
        inside = tuple(p - b.start for p, b in zip(pos, lay.block(k), strict=True))
        j = int(np.ravel_multi_index(inside, shape))
        row = {n: float(v[j]) for n, v in numeric.items()}
        why = law_problem(categories, row, study.law_params)
    except (ValueError, KeyError, IndexError):
        return ""
    at = ", ".join(f"{a.name} = {_shown(a, where[a.name])}" for a in study.axes)
    return f"first at {at}: {why}" if why and at else why


def _first_refused(ds: Any) -> dict[str, int] | None:
    """The index along each dimension of the first case of ``ds`` (C order) whose status is
    ``STATUS_BAD_LAW``; None when there is none. Read a block at a time."""
    var = ds["status"]
    shape = tuple(int(n) for n in var.shape)
    for slab in slabs(shape, COUNT_BLOCK_CASES, store_chunks(ds)):
        values = np.asarray(var[slab].values)
        hit = np.flatnonzero(values.ravel() == STATUS_BAD_LAW)
        if hit.size:
            pos = np.unravel_index(int(hit[0]), values.shape)
            starts = [s.indices(n)[0] for s, n in zip(slab, shape, strict=True)]
            at = (a + int(p) for a, p in zip(starts, pos, strict=True))
            return dict(zip(var.dims, at, strict=True))
    return None


def _shown(axis: Any, i: int) -> str:
    """Value ``i`` of a grid ``axis`` with its SI unit (``"5e+08 Pa"``, ``"aisi-1010"``)."""
    value, unit = axis.values[i], get_input(axis.name).unit
    if axis.is_category:
        return str(value)
    return f"{value:g}" + ("" if unit in ("", "1") else f" {unit}")


def dataset_flag_counts(ds: Any) -> dict[str, int]:
    """``flag_counts`` of the sweep ``ds``'s ``flags``, a block at a time."""
    attrs = ds["flags"].attrs
    total: Counter[str] = Counter()
    for values in _blocks(ds, "flags"):
        total.update(flag_counts(values, attrs))
    return {k: total[k] for k in TOTALS} | {name: total[name] for _, name in _flag_bits(attrs)}


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
    "flagged": cases with any flag; "not ok": cases with a flag that is not advisory (not
    plain success; ``ADVISORY_FLAGS`` such as law extrapolated leave a result ok). Cases
    without a result (-1) are not counted."""
    f = np.asarray(flags).ravel()
    f = f[f > 0]
    out = {"flagged": int(f.size), "not ok": int(np.count_nonzero(f & ~ADVISORY_FLAGS))}
    for mask, name in _flag_bits(attrs):
        out[name] = int(np.count_nonzero(f & mask))
    return out


def format_flag_counts(counts: Mapping[str, int]) -> str:
    """``"58 case(s) not ok (energy gain: 15, gravity-dominated: 48); advisory (the result
    stays ok): law extrapolated: 74; 80 flagged in all"``: the cases not ok first, with their
    flags, then the advisory flags and the cases with any flag (only when an advisory flag
    counts); ``"none"`` when no case is flagged. Counts without "not ok" (an older form):
    ``"12 case(s) (energy gain: 10, law extrapolated (advisory): 2)"``."""
    if not counts.get("flagged"):
        return "none"
    flags = {k: v for k, v in counts.items() if k not in TOTALS and v}
    if "not ok" not in counts:
        parts = ", ".join(
            f"{k}{' (advisory)' * (k in ADVISORY_NAMES)}: {v:,}" for k, v in flags.items()
        )
        return f"{counts['flagged']:,} case(s) ({parts})"
    text = not_ok_text(counts)
    advisory = ", ".join(f"{k}: {v:,}" for k, v in flags.items() if k in ADVISORY_NAMES)
    if advisory:
        text += (
            f"; advisory (the result stays ok): {advisory}; {counts['flagged']:,} flagged in all"
        )
    return text


def flagged_values(counts: Mapping[str, int]) -> dict[str, int]:
    """:func:`flag_counts`' ``counts`` as ``store_info`` and ``--json`` give them: ``total``
    (cases with any flag, the advisory law extrapolated included), ``not_ok`` (cases with a
    flag that is not advisory), then each flag that marks a case, by its ``ResultFlag`` name in
    lower case (``law_extrapolated``, ``beyond_tip``; the stored ``flag_meanings``)."""
    total = int(counts.get("flagged", 0))
    out = {"total": total}
    if "not ok" in counts or not total:  # counts of an older form have no "not ok"
        out["not_ok"] = int(counts.get("not ok", 0))
    out |= {
        FLAG_NAMES.get(k, k.replace(" ", "_")): int(v)
        for k, v in counts.items()
        if k not in TOTALS and v
    }
    return out


def flagged_text(values: Mapping[str, int]) -> str:
    """:func:`format_flag_counts`' text of :func:`flagged_values`' ``values`` (the table's
    ``flagged`` row of ``impactlab sweep info``)."""
    labels = {name: label for label, name in FLAG_NAMES.items()}
    counts = {"flagged": int(values.get("total", 0))}
    if "not_ok" in values:
        counts["not ok"] = int(values["not_ok"])
    for name, n in values.items():
        if name not in ("total", "not_ok"):
            counts[labels.get(name, name.replace("_", " "))] = int(n)
    return format_flag_counts(counts)


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
    """Progress and contents of the store at ``path``, the values ``impactlab sweep info
    --json`` prints: ``title``, ``study_hash``, ``store_version`` (the impactlab version that
    wrote the store), ``mode``, ``dims``, ``cases``, ``chunks_done`` (intact chunks) and
    ``chunks_total`` (integers), ``damaged`` (a text, only when chunks are damaged; they are
    left out of the counts), ``outputs``, ``status`` (:func:`status_counts`), ``flagged``
    (:func:`flagged_values`; only with a ``flags`` output), ``body_yields_first`` (only when a
    material pair's body yields first: :func:`body_yields_first_pairs`), ``law_ranges`` (the
    store's attribute; None when it records none) and ``impactlab_version`` (this one)."""
    p = Path(path)
    ds = open_sweep(p, verify=False)
    store = SweepStore(p)
    damaged = store.verify()
    info: dict[str, Any] = {
        "title": ds.attrs.get("title"),
        "study_hash": ds.attrs.get("study_hash"),
        "store_version": ds.attrs.get("impactlab_version"),
        "mode": ds.attrs.get("mode"),
        "dims": {str(k): int(v) for k, v in ds.sizes.items()},
        "cases": ds.attrs.get("n_cases"),
        "chunks_done": len(store.done_chunks()) - len(damaged),
        "chunks_total": ds.attrs.get("n_chunks"),
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
            info["flagged"] = flagged_values(dataset_flag_counts(ds))
    else:
        msgs = ds.attrs.get("status_messages", {})
        marked = store.done_chunks()
        info["status"] = _counts([_intact_values(p, "status", set(damaged), marked)], msgs)
        if "flags" in ds.data_vars:
            flags = _intact_values(p, "flags", set(damaged), marked)
            info["flagged"] = flagged_values(flag_counts(flags, ds["flags"].attrs))
    pairs = body_yields_first_pairs(ds)
    if pairs:
        info["body_yields_first"] = pairs
    return info | {"law_ranges": store.attrs().get("law_ranges"), "impactlab_version": __version__}


def body_yields_first_pairs(ds: Any) -> list[dict[str, Any]]:
    """The library material pairs of the sweep ``ds``'s study whose impacting body yields first
    (``materials.body_yields_first``): their delta_p is the body's flattening, not a dent in the
    flat. Each as ``body_material``, ``flat_material``, ``cases`` (of the store) and ``warning``
    (``dynamics.dent.flattening_warning`` for the largest stored delta_p of their finished
    cases; None when none left one or delta_p is not kept). A material by values (``custom``)
    is not checked here; ``[]`` when the study is not readable here."""
    from impactlab.dynamics.dent import body_flattening, flattening_warning
    from impactlab.materials import body_yields_first, get_material
    from impactlab.sweep.material_inputs import CUSTOM
    from impactlab.sweep.study_meta import category_values
    from impactlab.sweep.study_record import recorded_study

    try:
        values = category_values(recorded_study(json.loads(ds.attrs["study"])))
        pairs = [
            (b, f, get_material(b, "body_material"), get_material(f, "flat_material"))
            for b in values["body_material"]
            for f in values["flat_material"]
            if CUSTOM not in (b, f)
        ]
    except (ValueError, KeyError, TypeError):
        return []
    out: list[dict[str, Any]] = []
    for b, f, body, flat in pairs:
        if not body_yields_first(body, flat):
            continue
        sub = ds
        for dim, value in (("body_material", b), ("flat_material", f)):
            if dim in ds.dims:
                sub = sub.sel({dim: value})
        clause = ""
        if "delta_p" in sub.data_vars:
            depth = float(sub["delta_p"].where(sub["status"] == 0).max())
            what = "the largest delta_p of these cases"
            clause = body_flattening(body, flat, depth, what) if depth > 0.0 else ""
        out.append({"body_material": b, "flat_material": f, "cases": int(sub["status"].size),
                    "warning": flattening_warning(clause) if clause else None})  # fmt: skip
    return out


def flattening_rows(pairs: list[dict[str, Any]]) -> dict[str, str]:
    """The table rows of :func:`body_yields_first_pairs`: ``"body yields first: <body> on
    <flat>"`` -> its cases and warning; ``{}`` when no pair's body yields first."""
    return {
        f"body yields first: {p['body_material']} on {p['flat_material']}": f"{p['cases']:,} "
        "case(s) (materials.body_yields_first)" + (f": {p['warning']}" if p["warning"] else "")
        for p in pairs
    }


def result_counts(path: str | Path) -> tuple[dict[str, int], dict[str, int]]:
    """:func:`status_counts` and :func:`dataset_flag_counts` ({} for a store without ``flags``)
    of the store at ``path``, a block at a time, for the run that has just written (or
    checked) it: neither its metadata nor its chunks are checked again."""
    ds = open_dataset(Path(path))
    ds = mask_undone(ds, SweepStore(Path(path)).done_chunks())
    flagged = dataset_flag_counts(ds) if "flags" in ds.data_vars else {}
    return status_counts(ds), flagged


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
