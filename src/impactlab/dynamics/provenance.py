"""What was simulated: the full input of a result as JSON-ready data, and back.

``input_record`` writes the arguments of one ``simulate`` or ``simulate_drop`` call (the body
with its material and sizes, the flat, the contact law and its parameters, the friction model and
mu, angle, velocity, spin, gravity, the tolerance; ``partial_slip_cells`` for ``partial_slip``;
for a drop ``rate``, ``stop``, ``time_limit``), the function called (``function``) and the
impactlab version; ``from_record`` reads such a record back into that function's arguments (a
record that lacks a key is refused; one of another version warns; a drop's time limit recorded
as ``t_max``, its name before 0.3, is read as ``time_limit``, without a word: the record was
written by impactlab, not by its user), and ``rerun`` runs it again (``impactlab simulate
--from``). Every drop, of a rigid ``Rod`` or a ``FlexibleRod``, records
``simulate_drop``: ``simulate`` takes no drop options for a rigid rod (its rigid engine is
another model), so the drop's own function is the one that runs it again to the same numbers.

Materials, bodies and contact models are written generically from their dataclass fields (the
fields of ``__init__``), each as ``{"type": <class name>, <field>: <value>, ...}``, so a field added
to a body or a material is recorded without a change here. Every float is a quantity object
``{"value": v, "unit": "..."}`` in SI (docs/json-schema.md; the units of body and material fields
are ``impactlab._html.FIELD_UNITS``); a non-finite float (an unset Brinell hardness) is written
as ``{"value": null, "unit": ..., "nonfinite": "nan"}`` (``dynamics.record_codec``: ``encode``,
``decode``).
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Mapping
from typing import Any

from impactlab._code_identity import results_code_hash
from impactlab._validation import _caller_level
from impactlab._version import __version__
from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel, get_law
from impactlab.contact.rate import RATE_LAWS, RateLaw
from impactlab.contact.registry import ensure_laws, registered_laws
from impactlab.dynamics.flexcore.layout import DROP_DEFAULT_RTOL as DROP_RTOL
from impactlab.dynamics.input_checks import gravity_value
from impactlab.dynamics.kernels.layout import DEFAULT_RTOL, PARTIAL_SLIP_RTOL
from impactlab.dynamics.record_codec import UNITS as UNITS
from impactlab.dynamics.record_codec import decode, encode
from impactlab.dynamics.record_codec import key_form as _form
from impactlab.dynamics.record_codec import quantity as _float
from impactlab.dynamics.time_limit import RENAMED_KEYWORDS
from impactlab.materials import Material

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
    of ``function``; ``extra``: the drop's options ``rate``, ``stop``, ``time_limit``, or an
    impact's ``partial_slip_cells``)."""
    if function not in FUNCTIONS:
        raise ValueError(f"function must be one of {FUNCTIONS}, got {function!r}")
    record: dict[str, Any] = {
        "impactlab_version": __version__,
        "results_code_hash": results_code_hash(),
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
_META = ("impactlab_version", "results_code_hash", "format", "function")
#: The keys every record of the format holds, by its function (``input_record`` writes them).
_COMMON = ("format", "function", "body", "flat", "law", "law_params", "friction", "mu", "angle",
           "velocity", "spin", "gravity", "rtol")  # fmt: skip
KEYS = {
    SIMULATE: (*_COMMON, "constant_angle"),
    SIMULATE_DROP: (*_COMMON, "rate", "stop", "time_limit"),
}


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
    than this one, or names no ``impactlab_version``, or, of this version, by other code that
    computes results (its ``results_code_hash``, ``impactlab._code_identity``; a record
    without one is taken at its version's word)."""
    old = _input(record).get("impactlab_version", record.get("impactlab_version"))
    code = _input(record).get("results_code_hash")
    if old == __version__ and code not in (None, results_code_hash()):
        warnings.warn(
            f"the record was written by other code of impactlab {old} than this one (the "
            f"code that computes results: {code!r}, here {results_code_hash()!r}; a "
            "development version, or a change since): its numbers may differ from the "
            "recorded result",
            RecordVersionWarning,
            stacklevel=_caller_level(),
        )
        return
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
    given, record = record, _renamed(_input(record))
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


def _renamed(record: Mapping[str, Any]) -> Mapping[str, Any]:
    """``record`` with each key written before 0.3 (``RENAMED_KEYWORDS``: ``t_max``) under its
    new name (``time_limit``); ValueError for a record that holds both."""
    for old, new in RENAMED_KEYWORDS.items():
        if old in record and new in record:
            raise ValueError(
                f"the record holds {new!r} and {old!r}, its name before 0.3: they are one; "
                f"keep {new!r}"
            )
    if not RENAMED_KEYWORDS.keys() & record.keys():
        return record
    return {RENAMED_KEYWORDS.get(k, k): v for k, v in record.items()}


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
