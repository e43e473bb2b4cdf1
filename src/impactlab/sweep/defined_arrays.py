"""The arrays of a sweep store that its study defines (the grid coordinates, the fixed inputs as
scalars, the resolved material values; ``storebuild.defined_arrays``), checked against the
study and written again from it.

They are written once, when the store is built, and no chunk's completion marker covers them: a
coordinate file deleted or cut short would otherwise read as NaN coordinates, or make the store
unreadable, although nothing computed is lost. ``open_sweep`` refuses such a store with the
arrays named; a run of the same study into it (``SweepStore.prepare``) writes them again from
the study and keeps every computed chunk.
"""

from __future__ import annotations

import json
import shutil
from pathlib import Path
from typing import Any

import numpy as np
import zarr

from impactlab.sweep.integrity import DamagedStoreError
from impactlab.sweep.storebuild import consolidate, create_defined_array, defined_arrays
from impactlab.sweep.study import Study
from impactlab.sweep.study_record import recorded_study

__all__ = ["damaged_defined_arrays", "defined_arrays_error", "rewrite_defined_arrays"]


def _stored_study(group: Any) -> Study | None:
    """The study recorded in the store's root attributes (None when there is none)."""
    text = group.attrs.get("study")
    return recorded_study(json.loads(text)) if isinstance(text, str) else None


def _same(stored: Any, expected: Any) -> bool:
    a, b = np.asarray(stored), np.asarray(expected)
    if a.shape != b.shape:
        return False
    if a.dtype.kind in "fc" and b.dtype.kind in "fciu":
        return bool(np.array_equal(a, b.astype(a.dtype), equal_nan=True))
    return [str(v) for v in a.ravel().tolist()] == [str(v) for v in b.ravel().tolist()]


def damaged_defined_arrays(path: str | Path, study: Study | None = None) -> dict[str, str]:
    """The study-defined arrays of the store at ``path`` that cannot be read or do not hold the
    study's values, each with what is wrong (``{}``: all intact). ``study``: the store's own
    (read from its root attributes by default)."""
    group = zarr.open_group(str(path), mode="r")  # its consolidated metadata: one read
    study = _stored_study(group) if study is None else study
    if study is None:
        return {}
    problems = {}
    for name, (value, _dims, _attrs) in defined_arrays(study).items():
        try:
            node: Any = group[name]
            stored = node[...]
        except Exception as exc:  # zarr raises many unrelated types for a damaged array
            problems[name] = f"cannot be read ({type(exc).__name__}: {exc})"
            continue
        if not _same(stored, value):
            problems[name] = "does not hold the study's values (its file is gone or changed)"
    return problems


def defined_arrays_error(path: str | Path, problems: dict[str, str]) -> DamagedStoreError:
    """The error of a store whose study-defined arrays ``problems`` are damaged."""
    named = "; ".join(f"{name} {why}" for name, why in sorted(problems.items()))
    return DamagedStoreError(
        f"sweep store {str(path)!r} is damaged: {named}; run the same study into it again "
        f"(impactlab sweep run STUDY.toml --out {path}) to write these arrays again from the "
        "study: every computed chunk is kept"
    )


def rewrite_defined_arrays(path: str | Path, study: Study) -> list[str]:
    """Write the damaged study-defined arrays of the store at ``path`` again from ``study``
    (the store's own: the caller checked its hash and holds its lock); returns their names."""
    root = Path(path)
    problems = damaged_defined_arrays(root, study)
    if not problems:
        return []
    entries = defined_arrays(study)
    group = zarr.open_group(str(root), mode="r+")
    for name in sorted(problems):
        shutil.rmtree(root / name, ignore_errors=True)
        create_defined_array(group, name, entries[name])
    consolidate(root)
    return sorted(problems)
