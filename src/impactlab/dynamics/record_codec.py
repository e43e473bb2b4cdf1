"""A record's values as JSON-ready data and back: dataclasses as ``{"type": ..., <field>: ...}``,
floats as quantity objects ``{"value": v, "unit": "..."}`` in SI (``UNITS``), read back in any
unit pint converts (``encode``, ``decode``).
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._html import FIELD_UNITS
from impactlab.bodies import Rod, Sphere
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.materials import ContactPair, Material

__all__ = ["OPTIONAL_FIELDS", "UNITS", "decode", "encode", "key_form", "quantity"]

#: The classes a record may name, by ``type``.
_TYPES: dict[str, type] = {
    cls.__name__: cls for cls in (Material, ContactPair, Rod, Sphere, FlexibleRod, ContactModel)
}

#: SI units of ``simulate``'s scalar arguments (and of the body and material fields; ``t_max``:
#: a drop's ``time_limit`` in a record written before 0.3; ``params``: a ``ContactModel``'s
#: compiled parameters, each entry in its own SI unit (``impactlab.contact.kernels``' layout),
#: written as the unit ``"SI"``).
UNITS: dict[str, str] = {
    **FIELD_UNITS, "angle": "rad", "velocity": "m/s", "spin": "rad/s", "gravity": "m/s^2",
    "mu": "1", "rtol": "1", "params": "SI", "time_limit": "s", "t_max": "s",
}  # fmt: skip
#: The unit written for a float field whose unit is not known here, or for a list of mixed units
#: (each entry in its SI unit).
_UNKNOWN_UNIT = "SI"


def quantity(value: float, unit: str) -> dict[str, Any]:
    """``value`` [``unit``] as a quantity object (a non-finite one as ``nonfinite``)."""
    if math.isfinite(value):
        return {"value": value, "unit": unit}
    return {"value": None, "unit": unit, "nonfinite": repr(value)}


def encode(value: Any, key: str = "") -> Any:
    """``value`` as JSON-ready data: a dataclass as ``{"type", fields...}``, a float as a
    quantity object (unit by ``key``), a pint Quantity or a numpy value as SI numbers, tuples
    and arrays as lists."""
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        out: dict[str, Any] = {"type": type(value).__name__}
        for f in dataclasses.fields(value):
            if f.init and not f.name.startswith("_"):
                out[f.name] = encode(getattr(value, f.name), f.name)
        if isinstance(value, ContactModel):  # the compiled parameters define the model
            out["params"] = encode([float(p) for p in value.params], "params")
            out["details"] = {k: encode(float(v), "") for k, v in value.details.items()}
            out.pop("references", None)
        return out
    if hasattr(value, "to_base_units") and hasattr(value, "magnitude"):  # pint, any registry
        return encode(float(value.to_base_units().magnitude), key)
    if isinstance(value, bool | np.bool_):
        return bool(value)
    if isinstance(value, int | np.integer):
        return int(value)
    if isinstance(value, float | np.floating):
        return quantity(float(value), UNITS.get(key, _UNKNOWN_UNIT))
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, list | tuple):
        unit = UNITS.get(key, _UNKNOWN_UNIT)
        if value and all(isinstance(v, float | int) and not isinstance(v, bool) for v in value):
            if all(math.isfinite(v) for v in value):
                return {"value": [float(v) for v in value], "unit": unit}
            return [quantity(float(v), unit) for v in value]  # inf/NaN kept, one by one
        return [encode(v, key) for v in value]
    if isinstance(value, Mapping):
        return {str(k): encode(v, str(k)) for k, v in value.items()}
    return value


def decode(data: Any, key: str = "", units: Mapping[str, str] | None = None) -> Any:
    """The Python values of :func:`encode`'s data: quantity objects to numbers (or lists) in
    the unit :func:`encode` writes for their key (``units``, default ``UNITS``; a field of
    unknown unit in SI), converted from the unit the object names (a record edited by hand
    may say ``{"value": 5, "unit": "mm"}``); ``{"type": ...}`` to the named class, which must
    hold every field :func:`encode` writes for it (``OPTIONAL_FIELDS`` aside). ValueError for
    an unknown type, a missing field, an unknown unit or a unit of the wrong dimension."""
    return _decode(data, key, UNITS if units is None else units, key)


def _decode(data: Any, key: str, units: Mapping[str, str], path: str) -> Any:
    """:func:`decode`; ``path``: where ``data`` lies in the record (``body.material``)."""
    if isinstance(data, Mapping):
        if "value" in data and "unit" in data:
            return _quantity_value(data, key, units)
        if "type" in data:
            name = data["type"]
            cls = _TYPES.get(name)
            if cls is None:
                raise ValueError(f"unknown type {name!r} in the record; known: {sorted(_TYPES)}")
            fields = {
                k: _decode(v, k, UNITS, f"{path}.{k}" if path else k)
                for k, v in data.items()
                if k != "type"
            }
            return _build(cls, fields, path)
        return {k: _decode(v, k, units, f"{path}.{k}" if path else k) for k, v in data.items()}
    if isinstance(data, list):
        return [_decode(v, key, units, path) for v in data]
    return data


def _quantity_value(data: Mapping[str, Any], key: str, units: Mapping[str, str]) -> Any:
    """The number (or list) of a quantity object in the unit written for ``key``; ValueError
    naming ``key`` for a ``nonfinite`` that is not "nan", "inf" or "-inf" and for a list
    entry that is not a number (a null: write ``{"value": null, "unit": ..., "nonfinite":
    "nan"}`` entries, as a record does)."""
    name = f"the record's {key!r}" if key else "a quantity of the record"
    if "nonfinite" in data:
        text = str(data["nonfinite"]).strip().lower()
        if text not in ("nan", "inf", "-inf", "+inf"):
            raise ValueError(
                f"{name}: nonfinite must be 'nan', 'inf' or '-inf', got {data['nonfinite']!r}"
            )
        return float(text)
    v = data["value"]
    if isinstance(v, list):
        bad = [x for x in v if isinstance(x, bool) or not isinstance(x, int | float)]
        if bad:
            raise ValueError(
                f"{name}: every value of its list must be a number, got {bad[0]!r} in {v!r} "
                "(a value that is not finite is a list of quantity objects, each with its "
                "'nonfinite')"
            )
    value = [float(x) for x in v] if isinstance(v, list) else v
    unit, want = data["unit"], units.get(key, _UNKNOWN_UNIT)
    if value is None or unit in (want, _UNKNOWN_UNIT):
        return value
    return _converted(value, unit, want, key)


def _converted(value: Any, unit: Any, want: str, key: str) -> Any:
    """``value`` [``unit``] in ``want`` (SI base units where ``want`` is not known)."""
    import pint

    from impactlab.units import registry

    name = f"the record's {key!r}" if key else "a quantity of the record"
    reg = registry()
    try:
        q = reg.Quantity(np.asarray(value, dtype=float), str(unit))
        out = q.to_base_units() if want == _UNKNOWN_UNIT else q.to(want)
    except pint.DimensionalityError:
        raise ValueError(
            f"{name}: the unit {unit!r} is not a unit of {want} (the value {value!r})"
        ) from None
    except Exception as exc:  # an unknown unit name: pint raises several types
        raise ValueError(f"{name}: cannot read the unit {unit!r} ({exc})") from None
    m = np.asarray(out.magnitude, dtype=float)
    return [float(x) for x in m] if isinstance(value, list) else float(m)


#: The fields a record's object may leave out, by class; every other field of ``__init__`` that
#: :func:`encode` writes is required, so that a rerun never runs on a default (a body's
#: ``damping``, ``n_bending`` or ``material`` left out would run another rod). A
#: ``ContactModel`` is rebuilt from its compiled parameters (``name``, ``law_id``, ``params``):
#: its ``details``, ``source`` and ``references`` only describe it. Records began with format 1
#: (no released version wrote an earlier one), and each holds every field of its classes; a
#: field added later belongs here only for the records whose version predates it.
OPTIONAL_FIELDS: dict[type, frozenset[str]] = {
    ContactModel: frozenset({"details", "source", "references"}),
}


def _build(cls: type, values: dict[str, Any], path: str = "") -> Any:
    """``cls(**values)`` of a record (a Sphere takes its mass; the density follows); ``path``:
    where the object lies in the record (``body``, ``body.material``), for the errors."""
    fields = [f for f in dataclasses.fields(cls) if f.init]
    known = {f.name for f in fields}
    unknown = sorted(set(values) - known)
    where = f"the record's {path} {cls.__name__}" if path else f"the record's {cls.__name__}"
    if unknown:
        raise ValueError(
            f"{where} has field(s) {unknown} this impactlab does not know; known: {sorted(known)}"
        )
    optional = OPTIONAL_FIELDS.get(cls, frozenset())
    written = [f.name for f in fields if not f.name.startswith("_") and f.name not in optional]
    if lacking := [k for k in written if k not in values]:
        forms = ", ".join(key_form(k) for k in lacking)
        raise ValueError(
            f"{where} lacks {forms}: every record of the format holds each, and a rerun "
            "without one would run on a default, not as recorded (docs/json-schema.md)"
        )
    if cls is ContactModel:
        values = {k: v for k, v in values.items() if k in ("name", "law_id", "params", "details")}
    if cls is Sphere and values.get("mass") is not None:  # one of the two is given
        values.pop("mass" if _density_gives_mass(values) else "density", None)
    return cls(**values)


def _density_gives_mass(values: Mapping[str, Any]) -> bool:
    """Whether a recorded Sphere's radius and density give its recorded mass to the bit (as
    ``Sphere`` computes it): then it is built from the density, and its record reads back as
    written; else from the mass, which is what the dynamics use (a density from the mass can
    differ from the recorded one in its last bit)."""
    R, rho, m = values.get("radius"), values.get("density"), values.get("mass")
    if not (isinstance(R, float) and isinstance(rho, float) and isinstance(m, float)):
        return False
    return 4.0 / 3.0 * math.pi * R**3 * rho == m


def key_form(key: str) -> str:
    """``key`` named, with its quantity object's form (for the error that it is missing)."""
    if key not in UNITS:
        return repr(key)
    value = "[vx, vy]" if key == "velocity" else "[...]" if key == "params" else "..."
    return f'{key!r} ({{"value": {value}, "unit": "{UNITS[key]}"}})'
