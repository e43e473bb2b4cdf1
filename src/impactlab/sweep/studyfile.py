"""Study files (TOML, docs/sweep.md) and their canonical tables: parsing and validation into the
arguments of :class:`impactlab.sweep.study.Study`.

In a study file a bare number is in the input's SI unit unless the table gives ``unit``; a
string such as ``"8.8 mm"`` is converted. An angle is the exception: a bare angle is refused
(``"20 deg"``, or ``unit = "deg"`` in its table), as on the command line. With ``units = "si"``
in ``[study]`` (the canonical form ``Study.to_dict`` writes) bare numbers are SI, angles in rad.
"""

from __future__ import annotations

import math
import re
import tomllib
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

from impactlab._validation import read_text_file
from impactlab.contact.law_file import read_law_file
from impactlab.sweep.dimensions import Axis, Sample, Value
from impactlab.sweep.distributions import (
    Distribution,
    distribution_from_canonical,
    distribution_from_dict,
)
from impactlab.sweep.inputs import INPUTS, UNIT_REQUIRED, get_input, unknown_input
from impactlab.sweep.limits import DEFAULT_MAX_CASES, check_max_cases
from impactlab.sweep.options import STUDY_FORMAT, EngineOptions, UncertaintySpec
from impactlab.sweep.ranges import Limit, range_values
from impactlab.units import bare_text, convert_quantity, parse_quantity
from impactlab.units import registry as units_registry

_TABLES = (
    "study",
    "fixed",
    "grid",
    "sample",
    "outputs",
    "engine",
    "law_params",
    "laws",
    "uncertainty",
    "format",
    "grid_order",
)

Converter = Callable[..., float]


def read_study_file(path: str | Path) -> tuple[dict[str, Any], str]:
    """The table of a study file (TOML) and its source name; the study's name defaults to the
    file's stem."""
    p = Path(path)
    if p.is_dir():
        raise ValueError(f"{str(p)!r} is a directory (a sweep store?); give the study file (TOML)")
    if not p.is_file():
        raise ValueError(f"study file {str(p)!r} does not exist")
    try:
        text = read_text_file(p, "TOML", f"study file {str(p)!r}")
    except ValueError as exc:
        raise ValueError(f"{exc}: give the study file (TOML)") from None
    except OSError as exc:
        raise ValueError(f"cannot read study file {str(p)!r}: {exc.strerror or exc}") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:  # its text ends with "(at line L, column C)"
        raise ValueError(f"study file {str(p)!r} is not valid TOML: {exc}") from None
    data = dict(data)
    study_tab = dict(data.get("study", {})) if isinstance(data.get("study"), dict) else {}
    study_tab.setdefault("name", re.sub(r"[^A-Za-z0-9._-]", "_", p.stem).lstrip(".") or "study")
    data["study"] = study_tab
    if isinstance(data.get("laws"), dict):  # law files are relative to the study file
        data["laws"] = {
            k: str(p.parent / v) if isinstance(v, str) else v for k, v in data["laws"].items()
        }
    return data, str(p)


def study_arguments(
    data: Mapping[str, Any], source: str, max_cases: int | None = None
) -> dict[str, Any]:
    """The keyword arguments of ``Study`` from a study-file table (or ``Study.to_dict()``);
    ``max_cases`` (when given) replaces the table's ``[study] max_cases``."""
    unknown = sorted(set(data) - set(_TABLES))
    if unknown:
        raise ValueError(
            f"{source}: unknown table(s) {unknown}; known: "
            f"{', '.join(t for t in _TABLES if t not in ('format', 'grid_order'))}"
        )
    if "format" in data and data["format"] != STUDY_FORMAT:
        raise ValueError(f"{source}: unsupported study format {data['format']!r}")

    def table(key: str) -> dict[str, Any]:
        t = data.get(key, {})
        if not isinstance(t, dict):
            raise ValueError(f"{source}: [{key}] must be a table, got {t!r}")
        return dict(t)

    st = table("study")
    allowed_study = {"name", "description", "chunk_size", "units", "max_cases"}
    bad = sorted(set(st) - allowed_study)
    if bad:
        raise ValueError(f"[study] unknown key(s) {bad}; allowed: {sorted(allowed_study)}")
    si = st.get("units", "file") == "si"
    limit = check_max_cases(
        st.get("max_cases", DEFAULT_MAX_CASES) if max_cases is None else max_cases
    )
    grid_tab = table("grid")
    outputs = _outputs(table("outputs")) if "outputs" in data else None
    # the study-level rules: Study.__post_init__ (check_kinematics, the flexible rod)
    return {
        "name": str(st.get("name", "study")),
        "description": str(st.get("description", "")),
        "chunk_size": st.get("chunk_size"),  # None: the default for what a case costs
        "fixed": _fixed(table("fixed"), si),
        "grid": _grid(grid_tab, data.get("grid_order", list(grid_tab)), si, (limit, outputs)),
        "sample": _sample(data["sample"], si) if "sample" in data else None,
        "outputs": outputs,
        "engine": _engine(table("engine")),
        "uncertainty": _uncertainty(table("uncertainty")) if "uncertainty" in data else None,
        "law_params": table("law_params"),
        "laws": _laws(table("laws"), source),
        "max_cases": limit,
    }


def _laws(table: Mapping[str, Any], source: str) -> dict[str, dict[str, Any]]:
    """``[laws]``: name -> a law file (``contact.law_file``; relative to the study file) or a
    registered law's record (``Study.to_dict``), each registered; their records by name."""
    out = {}
    for name, value in table.items():
        if isinstance(value, str):
            law = read_law_file(value)
            if law.name != name:
                raise ValueError(
                    f"{source}: [laws] {name} = {value!r}: the file's law is named {law.name!r}"
                )
            out[name] = law.record()
        elif isinstance(value, Mapping):
            out[name] = dict(value)
        else:
            raise ValueError(
                f"{source}: [laws] {name} must be a law file's path or a law record, got {value!r}"
            )
    return out


def _quantity(value: Any, unit: str, bare_unit: str | None, label: str) -> float:
    """``value`` (a number in ``bare_unit``, or a quantity string) as a float in ``unit``.

    Text follows the rules of every text input (``impactlab.units``: one number and one unit,
    no comma, no temperature, the powers of the radian, no hertz for an angular velocity); the
    study file adds two: a bare number (written or not) is in ``bare_unit`` (None: refused, an
    angle), and an angle is a quantity of radians (not percent, not sr). Converted with pint,
    so that a scale is kept (``unit = "percent"``: 20 is 0.2)."""
    if isinstance(value, bool) or not isinstance(value, int | float | str):
        raise ValueError(f"{label}: expected a number or a quantity string, got {value!r}")
    value = bare_text(value)  # "\u22124": a bare number, its minus sign read as any text's is
    q: Any
    shown = value
    if _bare(value):
        if bare_unit is None:
            raise ValueError(
                f"{label}: the bare number {value!r} has no unit; an angle needs one, e.g. "
                f"'{str(value).strip()} deg' (or unit = 'deg' in the input's table)"
            )
        q = float(value) * _unit(label, bare_unit)
        shown = f"{str(value).strip()} {bare_unit}"  # a table's unit named with the number
    elif unit == "dimensionless":
        raise ValueError(
            f"{label}: {value!r} is not a plain number; this input has no unit: write the "
            f"number alone (e.g. 0.2), or a scale as the table's unit (unit = 'percent')"
        )
    else:
        q = parse_quantity(label, str(value), "deg" if unit == "rad" else unit)
    if unit == "rad" and dict(q.to_base_units().unit_items()) != {"radian": 1}:
        raise ValueError(
            f"{label}: {shown!r} is not an angle (its unit is {q.units:~}); give deg, rad, turn "
            f"or arcmin, e.g. '20 deg'"
        )
    if q.unitless and not _bare(value):
        raise ValueError(
            f"{label}: {value!r} is a pure number ({q:~}); write the number alone or with a "
            f"unit of {unit}, e.g. '1.0 {unit}'"
        )
    x = float(convert_quantity(label, q, unit, shown).magnitude)
    if not math.isfinite(x):
        raise ValueError(f"{label} must be finite, got {value!r}")
    return x


def _unit(label: str, unit: Any) -> Any:
    """The pint unit named ``unit`` (a table's ``unit``, or the input's own)."""
    if not isinstance(unit, str):
        raise ValueError(f"{label}: unit must be a unit's name (text), got {unit!r}")
    try:
        return units_registry().Unit(unit)
    except Exception as exc:  # pint's parser raises several unrelated types
        raise ValueError(f"{label}: unit {unit!r} is not a unit ({exc})") from None


def _bare(value: Any) -> bool:
    """True for a number, or a string that is only a number (no unit)."""
    if isinstance(value, int | float):
        return True
    try:
        float(str(value))
    except ValueError:
        return False
    return True


def _converter(name: str, si: bool, unit: str | None, where: str) -> Converter:
    """Converter of input ``name``'s numbers: bare numbers are in ``unit`` if given, else in the
    input's SI unit (an angle's are refused); with ``si`` bare numbers are SI."""
    spec = get_input(name)
    storage = "dimensionless" if spec.unit == "1" else spec.unit
    bare: str | None = unit or ("dimensionless" if spec.unit == "1" else spec.parse_unit)
    if unit is None and name in UNIT_REQUIRED:
        bare = None
    if si and unit is None:
        bare = storage

    def convert(value: Any, key: str = "") -> float:
        label = f"{where} {name}" + (f".{key}" if key else "")
        return _quantity(value, storage, bare, label)

    return convert


def _value(name: str, value: Any, si: bool, where: str, unit: str | None = None) -> Value:
    spec = get_input(name)
    if spec.kind == "category":
        if not isinstance(value, str):
            raise ValueError(f"{where} {name}: expected a name (string), got {value!r}")
        return value
    return _converter(name, si, unit, where)(value)


def _known(name: str, where: str) -> None:
    if name not in INPUTS:
        raise ValueError(f"{where} {unknown_input(name)}")


def _fixed(tab: Mapping[str, Any], si: bool) -> dict[str, Value]:
    fixed: dict[str, Value] = {}
    for name, value in tab.items():
        _known(name, "[fixed]")
        fixed[name] = _value(name, value, si, "[fixed]")
    return fixed


def _grid(tab: Mapping[str, Any], order: Any, si: bool, limit: Limit) -> tuple[Axis, ...]:
    axes = []
    for name in order:
        _known(name, "[grid]")
        axes.append(_axis(name, tab[name], si, limit))
    return tuple(axes)


def _axis(name: str, spec: Any, si: bool, limit: Limit) -> Axis:
    where = "[grid]"
    if isinstance(spec, list):
        return Axis(name, tuple(_value(name, v, si, where) for v in spec))
    if not isinstance(spec, dict):
        raise ValueError(
            f"[grid] {name}: expected a list of values or a table with start/stop/num, got {spec!r}"
        )
    allowed = {"values", "start", "stop", "num", "step", "spacing", "unit"}
    unknown = sorted(set(spec) - allowed)
    if unknown:
        raise ValueError(f"[grid] {name}: unknown key(s) {unknown}; allowed: {sorted(allowed)}")
    unit = spec.get("unit")
    if "values" in spec:
        extra = sorted(set(spec) - {"values", "unit"})
        if extra:
            raise ValueError(f"[grid] {name}: 'values' cannot be combined with {extra}")
        if not isinstance(spec["values"], list):
            raise ValueError(f"[grid] {name}: 'values' must be a list")
        return Axis(name, tuple(_value(name, v, si, where, unit) for v in spec["values"]))
    if get_input(name).kind == "category":
        raise ValueError(f"[grid] {name}: a category axis takes a list of names")
    for key in ("start", "stop"):
        if key not in spec:
            raise ValueError(f"[grid] {name}: missing {key!r} (or give 'values')")
    conv = _converter(name, si, unit, where)
    start, stop = conv(spec["start"], "start"), conv(spec["stop"], "stop")
    spacing = spec.get("spacing", "linear")
    if spacing not in ("linear", "log"):
        raise ValueError(f"[grid] {name}: spacing must be 'linear' or 'log', got {spacing!r}")
    if ("num" in spec) == ("step" in spec):
        raise ValueError(f"[grid] {name}: give exactly one of 'num' and 'step'")
    return Axis(name, tuple(range_values(name, spec, start, stop, conv, spacing, limit)))


def _sample(tab: Any, si: bool) -> Sample:
    if not isinstance(tab, dict):
        raise ValueError("[sample] must be a table")
    if "size" not in tab:
        raise ValueError("[sample] needs 'size' (number of Monte Carlo cases)")
    size, seed = tab["size"], tab.get("seed", 0)
    inputs: dict[str, Distribution] = {}
    for name, spec in tab.items():
        if name in ("size", "seed"):
            continue
        if name not in INPUTS:
            raise ValueError(f"[sample] {unknown_input(name)} (and the keys size, seed)")
        if not isinstance(spec, dict):
            raise ValueError(
                f'[sample] {name}: expected a table such as {{ dist = "normal", mean = ..., '
                f"std = ... }}, got {spec!r}"
            )
        if get_input(name).kind == "category":
            raise ValueError(f"[sample] input {name!r} is a category; put it on the [grid] instead")
        conv = _converter(name, si, spec.get("unit"), "[sample]")
        inputs[name] = (
            distribution_from_canonical(spec) if si else distribution_from_dict(spec, conv, name)
        )
    return Sample(size=size, seed=seed, inputs=inputs)


def _outputs(tab: Mapping[str, Any]) -> tuple[str, ...]:
    bad = sorted(set(tab) - {"keep"})
    if bad or "keep" not in tab or not isinstance(tab["keep"], list):
        raise ValueError('[outputs] takes one key: keep = ["e", "delta_p", ...]')
    return tuple(str(o) for o in tab["keep"])


def _engine(tab: Mapping[str, Any]) -> EngineOptions:
    bad = sorted(set(tab) - {"gravity", "constant_angle", "rtol", "partial_slip_cells"})
    if bad:
        raise ValueError(
            f"[engine] unknown key(s) {bad}; allowed: gravity, constant_angle, rtol, "
            "partial_slip_cells"
        )
    return EngineOptions(**tab)


def _uncertainty(tab: Mapping[str, Any]) -> UncertaintySpec:
    bad = sorted(set(tab) - {"outputs", "percentiles"})
    if bad:
        raise ValueError(f"[uncertainty] unknown key(s) {bad}; allowed: outputs, percentiles")
    for k, v in tab.items():
        if not isinstance(v, list):
            raise ValueError(f"[uncertainty] {k} must be a list, got {v!r}")
    return UncertaintySpec(**{k: tuple(v) for k, v in tab.items()})
