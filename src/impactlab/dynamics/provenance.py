"""What was simulated: the full input of a result as JSON-ready data, and back.

``input_record`` writes the arguments of one ``simulate`` or ``simulate_drop`` call (the body
with its material and sizes, the flat, the contact law and its parameters, the friction model and
mu, angle, velocity, spin, gravity, the tolerance; ``partial_slip_cells`` for ``partial_slip``;
for a drop ``rate``, ``stop``, ``t_max``), the function called (``function``) and the impactlab
version; ``from_record`` reads such a record back into that function's arguments (a record that
lacks a key is refused; one of another version warns), and ``rerun`` runs it again (``impactlab
simulate --from``). Every drop, of a rigid ``Rod`` or a ``FlexibleRod``, records
``simulate_drop``: ``simulate`` takes no drop options for a rigid rod (its rigid engine is
another model), so the drop's own function is the one that runs it again to the same numbers.

Materials, bodies and contact models are written generically from their dataclass fields (the
fields of ``__init__``), each as ``{"type": <class name>, <field>: <value>, ...}``, so a field added
to a body or a material is recorded without a change here. Every float is a quantity object
``{"value": v, "unit": "..."}`` in SI (docs/json-schema.md; the units of body and material fields
are ``impactlab._html.FIELD_UNITS``); a non-finite float (an unset Brinell hardness) is written
as ``{"value": null, "unit": ..., "nonfinite": "nan"}``.
"""

from __future__ import annotations

import dataclasses
import json
import math
import warnings
from collections.abc import Mapping
from typing import Any

import numpy as np

from impactlab._html import FIELD_UNITS
from impactlab._validation import _caller_level
from impactlab._version import __version__
from impactlab.bodies import Rod, Sphere
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel, get_law
from impactlab.contact.rate import RATE_LAWS, RateLaw
from impactlab.contact.registry import ensure_laws, registered_laws
from impactlab.dynamics.flexcore.layout import DROP_DEFAULT_RTOL as DROP_RTOL
from impactlab.dynamics.input_checks import gravity_value
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL
from impactlab.materials import ContactPair, Material

__all__ = ["FUNCTIONS", "KEYS", "RECORD_FORMAT", "SIMULATE", "SIMULATE_DROP",
           "RecordVersionWarning", "check_version", "decode", "encode", "from_record",
           "input_record", "law_params_record", "record_function", "result_record"]  # fmt: skip

#: The format of the record (raised when its layout changes).
RECORD_FORMAT = 1

#: The functions a record may name: ``simulate`` (rigid impacts; a FlexibleRod's drop before
#: the drop recorded itself) and ``simulate_drop`` (every drop, rigid or flexible rod).
SIMULATE = "impactlab.simulate"
SIMULATE_DROP = "impactlab.simulate_drop"
FUNCTIONS = (SIMULATE, SIMULATE_DROP)

#: The classes a record may name, by ``type``.
_TYPES: dict[str, type] = {
    cls.__name__: cls for cls in (Material, ContactPair, Rod, Sphere, FlexibleRod, ContactModel)
}

#: SI units of ``simulate``'s scalar arguments (and of the body and material fields).
UNITS: dict[str, str] = {
    **FIELD_UNITS, "angle": "rad", "velocity": "m/s", "spin": "rad/s", "gravity": "m/s^2",
    "mu": "1", "rtol": "1", "params": "1", "t_max": "s",
}  # fmt: skip
#: The unit written for a float field whose unit is not known here.
_UNKNOWN_UNIT = "SI"


def _float(value: float, unit: str) -> dict[str, Any]:
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
        return _float(float(value), UNITS.get(key, _UNKNOWN_UNIT))
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, list | tuple):
        unit = UNITS.get(key, _UNKNOWN_UNIT)
        if value and all(isinstance(v, float | int) and not isinstance(v, bool) for v in value):
            if all(math.isfinite(v) for v in value):
                return {"value": [float(v) for v in value], "unit": unit}
            return [_float(float(v), unit) for v in value]  # inf/NaN kept, one by one
        return [encode(v, key) for v in value]
    if isinstance(value, Mapping):
        return {str(k): encode(v, str(k)) for k, v in value.items()}
    return value


def decode(data: Any, key: str = "", units: Mapping[str, str] | None = None) -> Any:
    """The Python values of :func:`encode`'s data: quantity objects to numbers (or lists) in
    the unit :func:`encode` writes for their key (``units``, default ``UNITS``; a field of
    unknown unit in SI), converted from the unit the object names (a record edited by hand
    may say ``{"value": 5, "unit": "mm"}``); ``{"type": ...}`` to the named class.
    ValueError for an unknown type, an unknown unit or a unit of the wrong dimension."""
    units = UNITS if units is None else units
    if isinstance(data, Mapping):
        if "value" in data and "unit" in data:
            return _quantity_value(data, key, units)
        if "type" in data:
            name = data["type"]
            cls = _TYPES.get(name)
            if cls is None:
                raise ValueError(f"unknown type {name!r} in the record; known: {sorted(_TYPES)}")
            fields = {k: decode(v, k) for k, v in data.items() if k != "type"}
            return _build(cls, fields)
        return {k: decode(v, k, units) for k, v in data.items()}
    if isinstance(data, list):
        return [decode(v, key, units) for v in data]
    return data


def _quantity_value(data: Mapping[str, Any], key: str, units: Mapping[str, str]) -> Any:
    """The number (or list) of a quantity object in the unit written for ``key``."""
    if "nonfinite" in data:
        return float(data["nonfinite"])
    v = data["value"]
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


def _build(cls: type, values: dict[str, Any]) -> Any:
    """``cls(**values)`` of a record (a Sphere takes its mass; the density follows)."""
    if cls is ContactModel:
        values = {k: v for k, v in values.items() if k in ("name", "law_id", "params", "details")}
    if cls is Sphere and values.get("mass") is not None:
        values.pop("density", None)  # one of the two; the mass is what the dynamics use
    fields = [f for f in dataclasses.fields(cls) if f.init]
    known = {f.name for f in fields}
    unknown = sorted(set(values) - known)
    if unknown:
        raise ValueError(
            f"the record's {cls.__name__} has field(s) {unknown} this impactlab does not know; "
            f"known: {sorted(known)}"
        )
    required = [f.name for f in fields if f.default is f.default_factory is dataclasses.MISSING]
    if lacking := [k for k in required if k not in values]:  # a field without a default
        forms = ", ".join(_form(k) for k in lacking)
        raise ValueError(f"the record's {cls.__name__} lacks {forms}: every record holds it")
    return cls(**values)


def law_params_record(law: Any, given: Mapping[str, Any] | None) -> dict[str, Any] | None:
    """The given law parameters as quantity objects in the parameters' units (strings with
    units and pint Quantities converted; the law's defaults are those of the version)."""
    if not given:
        return None
    if not isinstance(law, str):
        return encode(dict(given))
    spec = get_law(law)
    units = _param_units(law)
    return {k: _float(v, units[k]) for k, v in spec.parameter_values(given).items()}


def _param_units(law: str) -> dict[str, str]:
    """The units of a named law's parameters."""
    return {q.name: ("1" if q.unit in ("-", "") else q.unit) for q in get_law(law).parameters}


def input_record(
    body: Any, flat: Material, *, law: str | ContactModel, law_params: Mapping[str, Any] | None,
    friction: str, mu: float, angle: float | None, velocity: tuple[float, float], spin: float,
    gravity: float, constant_angle: bool | None, rtol: float,
    extra: Mapping[str, Any] | None = None, function: str = SIMULATE,
) -> dict[str, Any]:  # fmt: skip
    """The JSON-ready record of one call of ``function`` (``SIMULATE`` or ``SIMULATE_DROP``;
    SI, checked values; ``angle`` None for a sphere; ``constant_angle`` None: not an argument
    of ``function``; ``extra``: the drop's options ``rate``, ``stop``, ``t_max``, or an
    impact's ``partial_slip_cells``)."""
    if function not in FUNCTIONS:
        raise ValueError(f"function must be one of {FUNCTIONS}, got {function!r}")
    record: dict[str, Any] = {
        "impactlab_version": __version__,
        "format": RECORD_FORMAT,
        "function": function,
        "body": encode(body),
        "flat": encode(flat),
        "law": encode(law),
        "law_params": law_params_record(law, law_params),
        "friction": friction,
        "mu": encode(float(mu), "mu"),
        "angle": None if angle is None else encode(float(angle), "angle"),
        "velocity": encode(tuple(float(v) for v in velocity), "velocity"),
        "spin": encode(float(spin), "spin"),
        "gravity": encode(float(gravity), "gravity"),
        "constant_angle": None if constant_angle is None else bool(constant_angle),
        "rtol": encode(float(rtol), "rtol"),
    }
    if constant_angle is None:
        del record["constant_angle"]
    for k, v in (extra or {}).items():
        record[k] = _rate_record(v) if k == "rate" else encode(v, k)
    if isinstance(law, str) and law in registered_laws():  # a user's law travels with its data
        record["law_data"] = registered_laws()[law].record()
    return record


#: Units of a rate law's constants in a record.
_RATE_UNITS = {"D": "1/s", "q": "1", "C": "1", "rate0": "1/s"}


def _rate_record(rate: RateLaw | str | None) -> Any:
    """A drop's rate law in a record: None, the library law's name, or, for a law with other
    constants (``RateLaw.custom``), its form, constants and description, so that the record
    runs it again."""
    if rate is None or isinstance(rate, str):
        return rate
    if RATE_LAWS.get(rate.name) == rate:
        return rate.name
    return {
        "form": rate.name,
        "parameters": {k: _float(float(v), _RATE_UNITS[k]) for k, v in rate.parameters},
        "description": rate.description,
    }


def _rate_from_record(data: Any) -> Any:
    """The ``rate`` argument of a record's ``rate`` (``_rate_record``)."""
    if not isinstance(data, Mapping):
        return data
    try:
        params = {str(k): decode(v, str(k), _RATE_UNITS) for k, v in data["parameters"].items()}
        return RateLaw.custom(str(data["form"]), str(data.get("description", "")), **params)
    except (KeyError, TypeError, AttributeError) as exc:
        raise ValueError(
            f"the record's rate {data!r} is not a rate law: expected 'form' and 'parameters' "
            f"({exc})"
        ) from None


#: Keys of a record that are not arguments of ``simulate``.
_META = ("impactlab_version", "format", "function")
#: The keys every record of the format holds, by its function (``input_record`` writes them).
_COMMON = ("format", "function", "body", "flat", "law", "law_params", "friction", "mu", "angle",
           "velocity", "spin", "gravity", "rtol")  # fmt: skip
KEYS = {SIMULATE: (*_COMMON, "constant_angle"), SIMULATE_DROP: (*_COMMON, "rate", "stop", "t_max")}


def _form(key: str) -> str:
    """``key`` named, with its quantity object's form (for the error that it is missing)."""
    if key not in UNITS:
        return repr(key)
    value = "[vx, vy]" if key == "velocity" else "[...]" if key == "params" else "..."
    return f'{key!r} ({{"value": {value}, "unit": "{UNITS[key]}"}})'


class RecordVersionWarning(UserWarning):
    """A record that another impactlab version wrote (or that names none) is run again: the
    law defaults and the engine are this version's, so its numbers may differ."""


def _input(record: Mapping[str, Any]) -> Mapping[str, Any]:
    """The input record itself, or the ``input`` of a result's ``to_dict()``."""
    if "input" in record and isinstance(record["input"], Mapping):
        return record["input"]
    if "input" in record and record["input"] is None:
        raise ValueError(
            "the result's 'input' is null: it was not returned by impactlab.simulate or "
            "impactlab.simulate_drop (a result assembled otherwise records no input)"
        )
    return record


def record_function(record: Mapping[str, Any]) -> str:
    """The function a record (or a result's ``to_dict()``) calls: ``SIMULATE`` or
    ``SIMULATE_DROP``; ValueError for another."""
    function = _input(record).get("function", SIMULATE)
    if function not in FUNCTIONS:
        raise ValueError(f"the record's function {function!r} is not one of {FUNCTIONS}")
    return str(function)


def check_version(record: Mapping[str, Any]) -> None:
    """RecordVersionWarning when ``record`` (or its ``input``) was written by another impactlab
    than this one, or names no ``impactlab_version``."""
    old = _input(record).get("impactlab_version", record.get("impactlab_version"))
    if old == __version__:
        return
    said = "names no impactlab_version" if old is None else f"was written by impactlab {old}"
    warnings.warn(
        f"the record {said} and runs with impactlab {__version__}: the law defaults and the "
        "engine are this version's, so its numbers may differ from the recorded result",
        RecordVersionWarning,
        stacklevel=_caller_level(),
    )


def from_record(record: Mapping[str, Any]) -> dict[str, Any]:
    """The keyword arguments of the record's function (:func:`record_function`) from a record
    of :func:`input_record` (or from a result's ``to_dict()`` / ``--json`` output, whose
    ``input`` it reads). ValueError naming what is missing (every key of the format:
    ``KEYS``; a rerun never falls back on a default) or unknown; RecordVersionWarning
    (:func:`check_version`)."""
    function = record_function(record)
    given, record = record, _input(record)
    missing = [k for k in ("body", "flat", "law", "velocity") if k not in record]
    if missing:
        raise ValueError(
            f"the record lacks {missing}: give the 'input' of a result's to_dict() or of "
            f"the output of 'impactlab simulate ... --json' or 'impactlab drop ... --json'"
        )
    fmt = record.get("format", RECORD_FORMAT)
    if fmt != RECORD_FORMAT:
        raise ValueError(f"record format {fmt!r} is not supported (this impactlab reads 1)")
    keys = KEYS[function] if "function" in record else ("function",)  # whose keys: unknown
    if lacking := [_form(k) for k in keys if k not in record]:
        raise ValueError(
            f"the record lacks {', '.join(lacking)}: every record of the format holds each, and "
            "a rerun without one would run on a default, not as recorded (docs/json-schema.md)"
        )
    check_version(given)
    if "law_data" in record:  # a user's law (register_law): registered here if need be
        # a --json output writes its numbers as quantity objects: back to numbers
        ensure_laws({str(record["law"]): decode(record["law_data"])})
    law = record["law"]
    params = _param_units(law) if isinstance(law, str) else None
    args = {
        k: decode(v, k, params if k == "law_params" else None)
        for k, v in record.items()
        if k not in _META and k not in ("law_data", "rate")
    }
    if "rate" in record:
        args["rate"] = _rate_from_record(record["rate"])
    v = args["velocity"]
    if not isinstance(v, list | tuple) or not all(isinstance(x, float | int) for x in v):
        shown = json.dumps(record["velocity"], default=str)
        raise ValueError(f"the record's velocity {shown} is not a pair of numbers: write it as "
                         '{"value": [vx, vy], "unit": "m/s"}')  # fmt: skip
    args["velocity"] = tuple(v)
    return args


def result_record(result: Any) -> dict[str, Any] | None:
    """The input record of an ``ImpactResult`` or a ``DropResult`` that ``simulate`` returned
    (None for one assembled otherwise): its recorded call with the checked values the result
    holds (mu, angle, velocity, spin) and the tolerance actually used."""
    call = getattr(result, "_call", None)
    if call is None:
        return None
    body, flat, law, law_params, gravity, constant_angle, rtol, drop_options, *function = call
    if rtol is None and drop_options is not None:
        rtol = DROP_RTOL
    elif rtol is None:
        rtol = PARTIAL_SLIP_RTOL if result.friction == "partial_slip" else DEFAULT_RTOL
    angle = result.angle if isinstance(body, Rod | FlexibleRod) else None
    return input_record(
        body, flat, law=law, law_params=law_params, friction=result.friction, mu=result.mu,
        angle=angle, velocity=result.velocity_in, spin=result.spin_in,
        gravity=gravity_value(gravity), constant_angle=constant_angle, rtol=rtol,
        extra=drop_options, function=function[0] if function else SIMULATE,
    )  # fmt: skip
