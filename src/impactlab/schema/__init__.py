"""The one table of result fields: name, SI unit and meaning of every engine output, history
column and derived result field.

Everything that prints or stores a result field's unit or description reads it from here (the
compiled engine's output layout, ``ImpactResult``/``BatchResult``, sweep stores, the CLI).
Units are SI and spelled one way, parseable by pint: ``"m"``, ``"m/s"``, ``"rad"``,
``"rad/s"``, ``"N"``, ``"N s"``, ``"J"``, ``"s"``, and ``"1"`` for dimensionless values.

A flexible drop's history and its sequence totals use the same names where they mean the same
quantity (per end of the rod: ``end_column``, ``"normal_force_0"``), names of their own where
they do not (``SEQUENCE_FIELDS``); the names before 0.3 read the same data with a
DeprecationWarning (``RENAMED_DROP_HISTORY``, ``RENAMED_DROP_FIELDS``).

To add an engine output: append a ``Field`` to ``OUTPUT_FIELDS`` (``schema.impact``; the
order is the column order of the engine's ``out`` array, so append, never insert) and fill it in
``impactlab.dynamics.core.driver`` (a recompilation). To add a field computed from the engine's
outputs, without touching the compiled engine: ``register_output`` (a derived output; it appears
in ``ImpactResult``, ``BatchResult``, ``DropResult`` and sweep stores, see
docs/architecture.md, "An output field").
"""

from __future__ import annotations

import functools
import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from impactlab.schema.drop import (
    DROP_FIELDS,
    DROP_HISTORY_FIELDS,
    DROP_MEANINGS,
    END_SUFFIXES,
    RENAMED_DROP_FIELDS,
    RENAMED_DROP_HISTORY,
    SEQUENCE_FIELDS,
    end_column,
)
from impactlab.schema.field import Field
from impactlab.schema.impact import HISTORY_FIELDS, OUTPUT_FIELDS, RESULT_FIELDS

__all__ = [
    "DERIVED_FIELDS",
    "DROP_FIELDS",
    "DROP_HISTORY_FIELDS",
    "DROP_MEANINGS",
    "END_SUFFIXES",
    "FIELDS",
    "HISTORY_FIELDS",
    "OUTPUT_FIELDS",
    "RENAMED_DROP_FIELDS",
    "RENAMED_DROP_HISTORY",
    "RESULT_FIELDS",
    "SEQUENCE_FIELDS",
    "DerivedField",
    "Field",
    "RenamedDropKeys",
    "derived_values",
    "description",
    "end_column",
    "register_output",
    "unit",
    "unregister_output",
    "warn_renamed",
]


FIELDS: dict[str, Field] = {
    f.name: f
    for f in (*OUTPUT_FIELDS, *HISTORY_FIELDS, *RESULT_FIELDS, *DROP_HISTORY_FIELDS, *DROP_FIELDS)
}


def warn_renamed(old: str, new: str, what: str, stacklevel: int = 3) -> None:
    """The DeprecationWarning of a renamed ``what`` (``"history column"``, ...): ``old`` still
    reads the data of ``new``, for one release."""
    warnings.warn(
        f"{what} {old!r} is renamed {new!r} (impactlab 0.3); the old name goes in 0.4",
        DeprecationWarning,
        stacklevel=stacklevel,
    )


class RenamedDropKeys(dict[str, Any]):
    """A drop's ``to_dict`` whose keys before 0.3 (``RENAMED_DROP_FIELDS``) still read their
    value, with a DeprecationWarning (``d[key]``, ``d.get(key)``); they are not among its keys
    (``key in d`` is False, nor in its JSON)."""

    def __missing__(self, key: str) -> Any:
        new = RENAMED_DROP_FIELDS.get(key)
        if new is None:
            raise KeyError(key)
        warn_renamed(key, new, "DropResult.to_dict key")
        return self[new]

    def get(self, key: str, default: Any = None) -> Any:  # type: ignore[override]
        new = RENAMED_DROP_FIELDS.get(key)
        return self[key] if key in self or (new is not None and new in self) else default


def unit(name: str) -> str:
    """SI unit of the field ``name`` (``"1"`` for dimensionless); KeyError names the known."""
    return _get(name).unit


def description(name: str) -> str:
    """One-line description of the field ``name``."""
    return _get(name).description


def _get(name: str) -> Field:
    try:
        return FIELDS[name]
    except KeyError:
        raise KeyError(f"unknown result field {name!r}; known: {', '.join(FIELDS)}") from None


@dataclass(frozen=True)
class DerivedField:
    """An output computed from the engine's outputs: ``field`` (name, unit, meaning), the
    engine outputs it ``needs`` (``OUTPUT_FIELDS`` names) and ``compute``, called with them as
    keyword arguments (floats, or arrays of one shape: it must broadcast, as numpy does)."""

    field: Field
    needs: tuple[str, ...]
    compute: Callable[..., Any]


#: The derived outputs registered (``register_output``), by name, in registration order.
DERIVED_FIELDS: dict[str, DerivedField] = {}


def register_output(
    name: str,
    unit: str,
    description: str,
    needs: tuple[str, ...] | list[str],
    compute: Callable[..., Any],
    symbol: str = "",
) -> DerivedField:
    """Register a derived output ``name`` [``unit``, SI, pint-parseable; "1" dimensionless],
    computed by ``compute(**{need: value})`` from the engine outputs ``needs``. It then shows
    in every result's ``to_dict`` and as an attribute (``ImpactResult``, ``DropResult``), as a
    column of ``BatchResult`` (``batch[name]``, ``to_xarray``, ``to_dataframe``) and as a sweep
    output (a store variable). ValueError for a name already taken (any field), a ``unit`` that
    pint cannot parse or that is not SI (``"mm"``, ``"deg"``: give
    the SI unit and compute in it), a need that is no engine output, or a ``compute`` that is
    not callable."""
    if not (isinstance(name, str) and name.isidentifier() and not name.startswith("_")):
        raise ValueError(f"output name must be a Python identifier, got {name!r}")
    if name in FIELDS:
        raise ValueError(f"output name {name!r} is taken: {FIELDS[name].description}")
    _check_unit(name, unit)
    outputs = {f.name for f in OUTPUT_FIELDS}
    bad = [n for n in needs if n not in outputs]
    if not needs or bad:
        raise ValueError(
            f"needs must name engine outputs, got {list(needs)!r}; engine outputs: "
            f"{', '.join(f.name for f in OUTPUT_FIELDS)}"
        )
    if not callable(compute):
        raise ValueError(f"compute must be callable, got {compute!r}")
    derived = DerivedField(Field(name, unit, description, symbol), tuple(needs), compute)
    DERIVED_FIELDS[name] = derived
    FIELDS[name] = derived.field
    return derived


@functools.cache
def _si_registry() -> Any:
    """A plain pint registry, made on first use: enough to read an SI unit (this module is
    engine source and imports nothing of the package's text reading, ``impactlab.units``)."""
    import pint

    return pint.UnitRegistry()


#: Named SI units (and their usual products) offered for a unit of another size with the same
#: base units: ``"kgf/mm^2"`` -> ``"Pa"``.
_NAMED_SI = ("N", "Pa", "J", "N m", "W", "N s", "Pa s", "N/m", "C", "V", "ohm", "F", "T", "Wb", "H")


def _named_si(base_units: Any) -> str:
    """The named SI units of ``_NAMED_SI`` whose base units are ``base_units``, as a hint
    (``'J' or 'N m'``); empty when none is."""
    reg = _si_registry()
    same = [u for u in _NAMED_SI if reg.Quantity(1.0, u).to_base_units().units == base_units]
    return " or ".join(repr(u) for u in same)


def _check_unit(name: str, unit: Any) -> None:
    """ValueError (one line, naming ``unit``) unless ``unit`` is an SI unit that pint parses,
    ``"1"`` for dimensionless: every value of a result is SI, so a unit of another size
    (``"mm"``, ``"furlongs"``) or with an offset (``"degC"``) would mislabel them. The hint
    names the SI unit to give instead (``"kgf/mm^2"``: ``'Pa'``)."""
    want = 'an SI unit pint parses ("m", "N s", "J/m", "1" for dimensionless)'
    if not isinstance(unit, str) or not unit.strip():
        raise ValueError(f"unit of output {name!r} must be {want}, got {unit!r}")
    try:
        text = "dimensionless" if unit == "1" else unit
        base = _si_registry().Quantity(1.0, text).to_base_units()
        zero = _si_registry().Quantity(0.0, text).to_base_units()
    except Exception as exc:  # pint raises several kinds for text it cannot read
        why = str(exc).splitlines()[0] if str(exc) else "not a unit expression"
        raise ValueError(f"unit of output {name!r} must be {want}, got {unit!r} ({why})") from None
    si = f"{base.units:~}" or "1"
    if float(zero.magnitude) != 0.0:  # "degC": 0 degC is 273.15 K
        raise ValueError(
            f"unit of output {name!r} must be {want}, got {unit!r}, a scale with an offset "
            f"(0 {unit} is {float(zero.magnitude):g} {si}, not 0); values are SI: give {si!r} "
            "and compute in it"
        )
    if not math.isclose(float(base.magnitude), 1.0, rel_tol=1e-12):
        size = f"{float(base.magnitude):.6g}" + ("" if si == "1" else f" {si}")
        give = _named_si(base.units) or repr(si)
        raise ValueError(
            f"unit of output {name!r} must be {want}, got {unit!r}, which is {size} (values "
            f"are SI: give {give} and compute in it)"
        )


def unregister_output(name: str) -> None:
    """Remove the derived output ``name`` (ValueError if none is registered under it)."""
    if DERIVED_FIELDS.pop(name, None) is None:
        raise ValueError(f"no derived output {name!r}; registered: {list(DERIVED_FIELDS)}")
    del FIELDS[name]


def derived_values(value_of: Callable[[str], Any]) -> dict[str, Any]:
    """Every derived output from ``value_of(engine output name)`` (a float or an array)."""
    return {
        name: d.compute(**{n: value_of(n) for n in d.needs}) for name, d in DERIVED_FIELDS.items()
    }
