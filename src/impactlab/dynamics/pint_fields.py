"""A result's fields as pint Quantities (SI), for ``to_pint`` of impacts, batches and drops."""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab import schema

__all__ = ["pint_quantities", "pint_unit"]


def pint_unit(unit: str) -> str:
    return "dimensionless" if unit == "1" else unit


def pint_quantities(result: Any, units: dict[str, str], registry: Any = None) -> dict[str, Any]:
    """The fields of ``result`` that have a unit in ``units`` as pint Quantities (SI; a pair
    such as ``velocity_out`` as one Quantity of an array), then every derived output
    (``schema.register_output``, in its unit); ``registry``: the caller's pint registry
    (default ``impactlab.units.registry()``)."""
    from impactlab.units import registry as shared  # pint loads on first use

    ureg = shared() if registry is None else registry
    out: dict[str, Any] = {}
    for name, unit in units.items():
        value = getattr(result, name, None)
        if isinstance(value, tuple):
            value = np.asarray(value, dtype=np.float64)
        elif not isinstance(value, float | int) or isinstance(value, bool):
            continue
        out[name] = ureg.Quantity(value, pint_unit(unit))
    for name, derived in schema.DERIVED_FIELDS.items():
        value = np.asarray(getattr(result, name), dtype=np.float64)
        number = float(value) if value.ndim == 0 else value
        out[name] = ureg.Quantity(number, pint_unit(derived.field.unit))
    return out
