"""Whether the metadata of a store's arrays (their ``zarr.json``) still follows from the study.

A ``zarr.json`` that is valid JSON and that Zarr reads can still disagree with the study: a
data type, shape, chunk shape, fill value or dimension name changed by hand or by another tool.
Its chunks would then be read wrongly (``cannot reshape``, a wrong fill), or the arrays would no
longer fit together. Two references are used:

- the consolidated metadata of the root ``zarr.json`` (each array as the store was built, from
  the study): every array's layout fields must equal it;
- the root attributes (``chunk_shape``, ``n_cases``, ``outputs``): a result array (a kept
  output or ``status``) must be chunked like the work, hold every case and have a data type
  and fill value of an output (``float64`` and NaN, or an integer type and -1).

A mismatch is repairable: a resume writes the array's metadata again from the study
(``repair.repair_metadata``), over its chunk files, which then fit again.
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from typing import Any

from impactlab.sweep.inputs import INTEGER_OUTPUTS

__all__ = ["LAYOUT_FIELDS", "mismatch", "root_attrs_problem"]

#: The fields of an array's ``zarr.json`` that say how its chunks are laid out and read.
LAYOUT_FIELDS = (
    "data_type",
    "shape",
    "chunk_grid",
    "chunk_key_encoding",
    "fill_value",
    "codecs",
    "dimension_names",
)

#: Root attributes every sweep store has (``storebuild._root_attrs``): without them the store
#: cannot be read as the study's (its outputs, cases and chunks are unknown).
REQUIRED_ROOT_ATTRS = ("study_hash", "study", "outputs", "n_cases", "n_chunks", "chunk_shape")


def root_attrs_problem(meta: Mapping[str, Any]) -> str | None:
    """What the root ``zarr.json`` ``meta`` (read as a JSON object) lacks of a sweep store's
    attributes (``"lacks the study's attributes (study_hash, outputs, ...)"``), or None."""
    attrs = meta.get("attributes")
    attrs = attrs if isinstance(attrs, Mapping) else {}
    gone = [k for k in REQUIRED_ROOT_ATTRS if k not in attrs]
    if not gone and isinstance(attrs["outputs"], list) and isinstance(attrs["chunk_shape"], list):
        return None
    named = ", ".join(gone) if gone else "outputs or chunk_shape not a list"
    return f"lacks the study's attributes ({named})"


def _text(value: Any) -> str:
    return json.dumps(value, sort_keys=True)


def _chunks(meta: Mapping[str, Any]) -> Any:
    grid = meta.get("chunk_grid")
    conf = grid.get("configuration") if isinstance(grid, Mapping) else None
    return conf.get("chunk_shape") if isinstance(conf, Mapping) else None


def _is_nan(value: Any) -> bool:
    return value == "NaN" or (isinstance(value, float) and math.isnan(value))


def _result_problems(name: str, meta: Mapping[str, Any], attrs: Mapping[str, Any]) -> list[str]:
    """How the result array ``name`` (metadata ``meta``) differs from what the root attributes
    ``attrs`` say every result array is."""
    out = []
    dtype = meta.get("data_type")
    ints = sorted(set(INTEGER_OUTPUTS.values()))
    allowed = ("int32",) if name == "status" else ("float64", *ints)
    if dtype not in allowed:
        out.append(f"data_type {_text(dtype)} (the study's: {' or '.join(allowed)})")
    fill = meta.get("fill_value")
    if dtype in allowed and ((fill != -1) if dtype != "float64" else not _is_nan(fill)):
        want_fill = "NaN" if dtype == "float64" else "-1"
        out.append(f"fill_value {_text(fill)} (the study's: {want_fill})")
    want = attrs.get("chunk_shape")
    if _chunks(meta) != want:
        out.append(f"chunk shape {_text(_chunks(meta))} (the study's: {_text(want)})")
    shape = meta.get("shape")
    if not isinstance(shape, list) or not isinstance(want, list) or len(shape) != len(want):
        out.append(f"shape {_text(shape)} (the study's has {len(want or [])} dimensions)")
    elif math.prod(shape) != attrs.get("n_cases"):
        out.append(f"shape {_text(shape)} (the study's has {attrs.get('n_cases')} cases)")
    return out


def mismatch(
    name: str,
    meta: Mapping[str, Any],
    built: Mapping[str, Any] | None,
    attrs: Mapping[str, Any],
    results: tuple[str, ...],
) -> str | None:
    """Why the array ``name`` whose ``zarr.json`` holds ``meta`` no longer follows from the
    study (``"does not match the study: data_type "float32" (the study's: "float64")"``), or
    None. ``built``: its entry in the root's consolidated metadata (None where there is none);
    ``attrs``: the root attributes; ``results``: the store's result arrays."""
    if meta.get("node_type") != "array":
        return None
    problems = []
    if isinstance(built, Mapping) and built.get("node_type") == "array":
        problems = [
            f"{key} {_text(meta.get(key))} (the study's: {_text(built.get(key))})"
            for key in LAYOUT_FIELDS
            if _text(meta.get(key)) != _text(built.get(key))
        ]
    if not problems and name in results:
        problems = _result_problems(name, meta, attrs)
    return f"does not match the study: {'; '.join(problems)}" if problems else None
