"""Resuming a store: why a store cannot be resumed by a study, and repairing its metadata:
arrays whose ``zarr.json`` is gone or unreadable are created again (a result array's or a
sampled input's chunk files, where still there, are kept; a coordinate or fixed input is
written whole from the study), and an unreadable or deleted ``.sweep/study.json`` is written
again, for the study the store was made for (same hash).

Only what the study itself defines is rewritten; no computed value is touched. The chunks
whose files are gone no longer match their completion markers, so the resume that follows
computes exactly those again (``SweepStore.verify``); every intact chunk is kept.
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import zarr

from impactlab.sweep.integrity import CorruptStoreError, RepairableStoreError, recorded_engine
from impactlab.sweep.storebuild import (
    META,
    StoreMeta,
    consolidate,
    create_defined_array,
    create_meta_group,
    create_result_array,
    create_sampled_array,
    defined_arrays,
    write_study_record,
)
from impactlab.sweep.study import Study
from impactlab.sweep.study_record import recorded_study

__all__ = [
    "mismatch_message",
    "record_presentation",
    "repair_metadata",
    "restore_study_record",
    "root_mismatch",
    "study_differences",
]

#: At most this many differences of two studies are named (then "and N more").
SHOWN_DIFFERENCES = 5
#: Keys of a study's ``[study]`` table that are no part of its hash (they change no result).
_UNHASHED = ("description", "max_cases")


def mismatch_message(
    path: Path, old: str | None, attrs: dict[str, object], study: Study, meta: StoreMeta
) -> str:
    """Why the store at ``path`` (study hash ``old``, root attributes ``attrs``) cannot be
    resumed by ``study`` under ``meta``: another study, or this study computed by other code
    (its chunks and new ones would mix results of two versions)."""
    engine = attrs.get("engine")
    if isinstance(engine, str) and engine != meta.engine and study.hash(engine) == old:
        return (
            f"store {str(path)!r} holds this study, computed by other impactlab code (stored: "
            f"{engine!r}; installed: {meta.engine!r}): its chunks and new ones would mix the "
            f"results of two versions; finish it with the impactlab that began it, run with "
            f"--restart to discard it and start fresh, or choose another --out (another store path)"
        )
    try:
        record = json.loads((path / META / "study.json").read_text())
        diff = study_differences(record, json.loads(json.dumps(study.to_dict())))
    except (OSError, ValueError, TypeError, AttributeError):  # no readable record
        diff = []
    if len(diff) > SHOWN_DIFFERENCES:
        more = len(diff) - SHOWN_DIFFERENCES + 1
        diff = [*diff[: SHOWN_DIFFERENCES - 1], f"and {more} more"]
    what = (
        f"({'; '.join(diff)}; the store's -> this study's, in SI units): its chunks cannot "
        "serve this study; undo the changes to resume it, "
        if diff
        else f"(hash {old}, this study {meta.study_hash}); "
    )
    return (
        f"store {str(path)!r} holds a different study {what}run with --restart (restart=True "
        f"in Python) to discard it and start fresh, or choose another --out (another store path)"
    )


def study_differences(old: Mapping[str, Any], new: Mapping[str, Any]) -> list[str]:
    """What differs between two studies' canonical forms (``Study.to_dict()``, as JSON reads
    it), ``"old -> new"``: ``"chunk_size: 65536 -> 32768"``, ``"grid.mu stop: 0.6 -> 0.7"``,
    ``"fixed.vy: -1.41 -> not set"``; the description and ``max_cases`` (no part of the
    study's hash) left out."""
    a, b = _flat(old), _flat(new)
    for key in (*_UNHASHED, "grid_order"):
        a.pop(key, None)
        b.pop(key, None)
    out = [_change(k, a.get(k), b.get(k)) for k in sorted({*a, *b}, key=_order) if _differ(a, b, k)]
    order_a, order_b = list(old.get("grid_order", ())), list(new.get("grid_order", ()))
    if order_a != order_b and sorted(order_a) == sorted(order_b):  # only reordered
        out.append(f"grid order: {', '.join(order_a)} -> {', '.join(order_b)}")
    return out


def _flat(d: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    """``d`` as dotted keys (``grid.mu``, ``sample.mu.low``); the ``[study]`` table's keys bare."""
    out: dict[str, Any] = {}
    for k, v in d.items():
        key = f"{prefix}{k}" if prefix or k != "study" else ""
        if isinstance(v, Mapping):
            out |= _flat(v, f"{key}." if key else "")
        else:
            out[key] = v
    return out


#: The order the differences are named in: the ``[study]`` table's keys, then these tables.
_GROUPS = ("", "grid", "fixed", "sample", "engine", "law_params")


def _order(key: str) -> tuple[int, str]:
    head = key.partition(".")[0] if "." in key else ""
    return (_GROUPS.index(head) if head in _GROUPS else len(_GROUPS), key)


def _differ(a: Mapping[str, Any], b: Mapping[str, Any], key: str) -> bool:
    return key not in a or key not in b or a[key] != b[key]


def _text(v: Any, digits: int = 6) -> str:
    """``v`` as the message shows it: floats to ``digits`` significant digits, or fewer (not
    under 6) where those give the float exactly."""
    if v is None:
        return "not set"
    if isinstance(v, float):
        exact = (f"{v:.{d}g}" for d in range(6, digits) if float(f"{v:.{d}g}") == v)
        return next(exact, f"{v:.{digits}g}")
    if isinstance(v, list):
        return ", ".join(_text(x, digits) for x in v) if len(v) <= 4 else f"{len(v)} values"
    return str(v)


def _arrow(old: Any, new: Any) -> str:
    """``"old -> new"`` with as many significant digits (6 to 17) as it takes for two different
    values to read differently (0.13 -> 0.1300001, not 0.13 -> 0.13)."""
    for digits in range(6, 18):
        a, b = _text(old, digits), _text(new, digits)
        if a != b:
            break
    return f"{a} -> {b}"


def _change(key: str, old: Any, new: Any) -> str:
    """One difference: a grid axis by its start, stop or number of values."""
    if isinstance(old, list) and isinstance(new, list) and len(old) > 4 and len(new) > 4:
        if len(old) != len(new):
            return f"{key}: {len(old)} -> {len(new)} values"
        ends = [
            f"{key} {which}: {_arrow(old[i], new[i])}"
            for which, i in (("start", 0), ("stop", -1))
            if old[i] != new[i]
        ]
        return "; ".join(ends) or f"{key}: values between {_text(old[0])} and {_text(old[-1])}"
    return f"{key}: {_arrow(old, new)}"


def root_mismatch(path: Path, study: Study, meta: StoreMeta) -> str | None:
    """Why the root ``zarr.json`` of the store at ``path`` (gone or unreadable) must not be
    rewritten for ``study`` under ``meta`` (``mismatch_message``: its study record holds another
    study, or the engine identity kept beside it is not the installed one), or None."""
    engine = recorded_engine(path)
    try:
        recorded = recorded_study(json.loads((path / META / "study.json").read_text()))
    except Exception as exc:  # a record that no longer reads as a study: not this one
        return (
            f"store {str(path)!r} is damaged (its zarr.json) and its study record cannot be "
            f"read as a study ({exc}); run with --restart (restart=True in Python) to discard "
            f"it and start fresh"
        )
    old = recorded.hash(engine or "")
    if engine == meta.engine and old == meta.study_hash:
        return None
    return mismatch_message(path, old, {"engine": engine}, study, meta)


def repair_metadata(
    path: Path, problem: RepairableStoreError, study: Study, meta: StoreMeta
) -> None:
    """Write the metadata of the arrays ``problem.missing_arrays`` of the store at ``path``
    again (gone or unreadable), as when the store was built: a result array's or a sampled
    input's over the chunk files still there, a study-defined array whole (its values follow
    from the study), the ``.sweep`` group's; write its study record again when
    ``problem.study_record`` says it is unreadable, and consolidate the metadata. The caller
    holds the store's lock and has checked that the store holds ``study`` (its hash)."""
    if problem.missing_arrays:
        group = zarr.open_group(str(path), mode="r+")
        defined = defined_arrays(study)
        sampled = () if study.sample is None else tuple(study.sample.inputs)
        for name in problem.missing_arrays:
            (path / name / "zarr.json").unlink(missing_ok=True)  # unreadable: written again
            if name in (*meta.outputs, "status"):
                create_result_array(group, name, meta, study)
            elif name in sampled:
                create_sampled_array(group, name, study)
            elif name in defined:
                shutil.rmtree(path / name, ignore_errors=True)
                create_defined_array(group, name, defined[name])
            elif name == META:
                create_meta_group(group, meta)
            else:  # not the study's: nothing to write it from
                raise CorruptStoreError(
                    f"sweep store {str(path)!r} is damaged: {name}/zarr.json cannot be read and "
                    f"{name!r} is not an array of the study; run with --restart (restart=True "
                    f"in Python) to start it fresh"
                )
        consolidate(path)
    if problem.study_record is not None:
        write_study_record(path, study)


def restore_study_record(path: Path, study: Study, meta: StoreMeta) -> None:
    """Write ``.sweep/study.json`` of the store at ``path`` again where it is gone but the root
    attributes, written after every array when the store was built, name ``study``'s hash
    (``meta.study_hash``); nothing otherwise."""
    if (path / META / "study.json").exists() or not (path / META).is_dir():
        return
    try:
        attrs = json.loads((path / "zarr.json").read_text()).get("attributes", {})
    except (OSError, ValueError, AttributeError):
        return
    if isinstance(attrs, dict) and attrs.get("study_hash") == meta.study_hash:
        write_study_record(path, study)


def record_presentation(path: Path, study: Study) -> None:
    """Record ``study`` in the store at ``path`` that holds it (same hash) where its record
    differs in what is no part of the hash (the description, ``max_cases``): the root's
    attributes ``description`` and ``study``, ``.sweep/study.json`` and the consolidated
    metadata written as a fresh store of ``study`` has them, so that a resumed store is the
    store of an uninterrupted run of the study that finished it. The caller holds the lock."""
    text = json.dumps(study.to_dict(), indent=1, sort_keys=True) + "\n"
    try:
        if (path / META / "study.json").read_text() == text:
            return
    except (OSError, UnicodeDecodeError):
        pass  # gone or unreadable: written again below
    group = zarr.open_group(str(path), mode="r+")
    group.attrs.update({"description": study.description, "study": study.to_json()})
    write_study_record(path, study)
    consolidate(path)
