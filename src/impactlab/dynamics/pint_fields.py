"""A result's fields as pint Quantities (SI), for ``to_pint`` of impacts, batches and drops."""

from __future__ import annotations

from typing import Any

import numpy as np

from impactlab import schema

__all__ = ["pint_quantities", "pint_registry", "pint_unit"]


def pint_unit(unit: str) -> str:
    return "dimensionless" if unit == "1" else unit


def pint_registry(registry: Any) -> Any:
    """``registry``, a pint UnitRegistry, or impactlab's for None (pint loads on first use);
    TypeError for anything else (a field's name is the likely mistake)."""
    if registry is None:
        from impactlab.units import registry as shared

        return shared()
    if not callable(getattr(registry, "Quantity", None)):
        what = f"the string {registry!r}" if isinstance(registry, str) else repr(registry)
        raise TypeError(
            f"registry must be a pint UnitRegistry (or None: impactlab's), got {what}; "
            "to_pint() returns every field by name: to_pint()['delta_p']"
        )
    return registry


def pint_quantities(result: Any, units: dict[str, str], registry: Any = None) -> dict[str, Any]:
    """The fields of ``result`` that have a unit in ``units`` as pint Quantities (SI; a pair
    such as ``velocity_out`` as one Quantity of an array), then every derived output
    (``schema.register_output``, in its unit); ``registry``: the caller's pint registry
    (default ``impactlab.units.registry()``)."""
    ureg = pint_registry(registry)
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
