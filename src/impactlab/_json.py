"""Turn results into JSON-ready Python values (numpy scalars/arrays, non-finite floats -> None)."""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np


def jsonable(x: Any) -> Any:
    """Recursively convert mappings, sequences and numpy values; NaN and inf become None."""
    if isinstance(x, Mapping):
        return {str(k): jsonable(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [jsonable(v) for v in x]
    if isinstance(x, np.ndarray):
        return jsonable(x.tolist())
    if isinstance(x, np.generic):
        return jsonable(x.item())
    if isinstance(x, float) and not math.isfinite(x):
        return None
    return x


def quantity(value: Any, unit: str, sigma: Any = None) -> dict[str, Any]:
    """The JSON shape of a quantity: ``{"value": v, "unit": "...", "sigma": s}`` (SI; ``sigma``
    only when there is an uncertainty > 0; ``value`` may be a list for a vector)."""
    out: dict[str, Any] = {"value": jsonable(value), "unit": unit}
    if sigma is not None and isinstance(sigma, int | float) and sigma > 0:
        out["sigma"] = jsonable(sigma)
    return out


def _is_number(x: Any) -> bool:
    if isinstance(x, bool | np.bool_):
        return False
    if isinstance(x, float | np.floating):
        return True
    return isinstance(x, list | tuple) and len(x) > 0 and all(_is_number(v) for v in x)


def to_json(data: Any, units: Mapping[str, str], sigmas: Mapping[str, Any] | None = None) -> Any:
    """``data`` as JSON-ready values where every float (or list of floats) under a key with a
    known SI unit in ``units`` becomes :func:`quantity` (nested mappings and lists of mappings
    too); integers, text, flags and the rest stay plain (:func:`jsonable`). The documented
    shape: docs/json-schema.md."""
    sigmas = sigmas or {}
    if isinstance(data, Mapping):
        out: dict[str, Any] = {}
        for k, v in data.items():
            key = str(k)
            if key in units and _is_number(v):
                out[key] = quantity(v, units[key], sigmas.get(key))
            else:
                out[key] = to_json(v, units, sigmas)
        return out
    if isinstance(data, list | tuple) and any(isinstance(v, Mapping) for v in data):
        return [to_json(v, units) for v in data]
    return jsonable(data)


def shape_problems(data: Any, path: str = "") -> list[str]:
    """Where ``data`` (parsed JSON) breaks the documented shape (docs/json-schema.md): a
    quantity object must hold ``value`` (a number, a list of numbers or null), a non-empty
    ``unit`` string and, optionally, a ``sigma`` > 0; a float must not appear outside one.
    Returns the problems, one line each (``[]``: the shape holds)."""
    if isinstance(data, Mapping):
        if "value" in data and "unit" in data:
            return _quantity_problems(data, path)
        return [p for k, v in data.items() for p in shape_problems(v, f"{path}.{k}")]
    if isinstance(data, list):
        return [p for i, v in enumerate(data) for p in shape_problems(v, f"{path}[{i}]")]
    if isinstance(data, float):
        return [f"{path or '.'}: the number {data!r} is not a quantity object"]
    return []


def _quantity_problems(q: Mapping[str, Any], path: str) -> list[str]:
    out = []
    extra = set(q) - {"value", "unit", "sigma"}
    if extra:
        out.append(f"{path}: unknown key(s) {sorted(extra)} in a quantity")
    if not isinstance(q["unit"], str) or not q["unit"]:
        out.append(f"{path}: the unit {q['unit']!r} is not a non-empty string")
    v = q["value"]
    values = v if isinstance(v, list) else [v]
    if not all(
        x is None or (isinstance(x, int | float) and not isinstance(x, bool)) for x in values
    ):
        out.append(f"{path}: the value {v!r} is not a number, a list of numbers or null")
    if "sigma" in q and not (isinstance(q["sigma"], int | float) and q["sigma"] > 0):
        out.append(f"{path}: the sigma {q['sigma']!r} is not a number > 0")
    return out
