"""One drop of a measurements file: its columns read (units, aliases, the unit of an
uncertainty) and checked, with one-line errors naming the drop and the column.

Numbers are kept in each input's own unit (``impactlab.sweep.inputs``: SI, the Brinell hardness
in kgf/mm^2) and measured values in SI. A ``<quantity>_sigma`` without a unit of its own takes
its quantity's (the column header's or the ``[units]`` entry's). A drop's velocity is (vx, vy)
or speed and incidence (converted to vx, vy as the sweep does), never both.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

from impactlab.bodies import PAPER_ROD
from impactlab.calibrate.input_magnitudes import check_magnitude
from impactlab.calibrate.quantities import (
    AMBIGUOUS,
    DROP_CATEGORIES,
    MEASURABLE,
    NUMERIC_INPUTS,
    PLAUSIBLE,
    canonical_output,
)
from impactlab.calibrate.values import bare, to_unit
from impactlab.materials import PRESETS
from impactlab.sweep.dimensions import check_allowed, check_rod_angles
from impactlab.sweep.inputs import INPUTS, UNIT_REQUIRED

__all__ = ["LABEL_KEYS", "Row", "parse_row", "split_header", "unit_text"]

LABEL_KEYS = ("label", "drop", "name")
#: Inputs of a rod that a sphere does not have (as in a sweep of spheres).
_ROD_ONLY = ("angle", "length", "tip_radius", "inertia")


@dataclass
class Row:
    """One drop: label, categories, inputs (each in its own unit), observed and sigma (SI)."""

    label: str
    categories: dict[str, str]
    inputs: dict[str, float]
    observed: dict[str, float]
    sigma: dict[str, float]


def split_header(key: str) -> tuple[str, str | None]:
    """``"delta_p [um]"`` -> ("delta_p", "um")."""
    key = key.strip()
    if key.endswith("]") and "[" in key:
        name, unit = key[:-1].split("[", 1)
        return name.strip(), unit.strip()
    return key, None


def unit_text(unit: str) -> str:
    """`` unit``, or nothing for a pure number."""
    return "" if unit in ("1", "", "-") else f" {unit}"


def _is_nan(v: Any) -> bool:
    return isinstance(v, float) and math.isnan(v)


def _blank(v: Any) -> bool:
    return v is None or (isinstance(v, str) and not v.strip()) or _is_nan(v)


def _value(where: str, name: str, v: Any, column_unit: str | None, unit: str) -> float:
    """``v`` in ``unit``: a bare number is in ``column_unit`` (the column header's or the
    ``[units]`` table's; None: ``unit``) and must fit its dimension, as a unit in a value must."""
    if isinstance(v, bool) or not isinstance(v, int | float | str):
        raise ValueError(f"{where}: {name} must be a number or a quantity string, got {v!r}")
    try:
        if column_unit and bare(v):
            return to_unit(f"{str(v).strip()} {column_unit}", unit, name=name)
        if column_unit:
            to_unit(f"1 {column_unit}", unit, name=f"{name} (column unit [{column_unit}])")
        return to_unit(float(v) if bare(v) else v, unit, name=name)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None


def _category(where: str, name: str, value: str) -> str:
    known = ("rod", "sphere") if name == "body" else tuple(PRESETS)
    if value not in known:
        raise ValueError(f"{where}: unknown {name} {value!r}; known: {', '.join(known)}")
    return value


def _kind(where: str, name: str) -> tuple[str, str]:
    """(what the column is: "label", "category", "input", "sigma", "value", its canonical
    name); ValueError for a column a drop does not take."""
    if name in LABEL_KEYS:
        return "label", "label"
    if name in ("law", "friction"):
        raise ValueError(
            f"{where}: {name!r} is not a property of a drop: the contact law and the "
            "friction model are chosen by the candidate models of the calibration"
        )
    ambiguous = AMBIGUOUS.get(name.removesuffix("_sigma"))
    if ambiguous:
        raise ValueError(f"{where}: column {name!r}: {ambiguous}")
    if name in DROP_CATEGORIES:
        return "category", name
    if name in NUMERIC_INPUTS:
        return "input", name
    q = canonical_output(name.removesuffix("_sigma"))
    if name.endswith("_sigma") and q:
        return "sigma", f"{q}_sigma"
    if canonical_output(name):
        return "value", str(canonical_output(name))
    if ";" in name or "\t" in name:
        raise ValueError(
            f"{where}: the header is one column {name!r}: the file separates its columns "
            "with ';' or tabs; a measurements CSV separates them with commas"
        )
    raise ValueError(
        f"{where}: unknown column {name!r}; a drop takes label, "
        f"{', '.join(DROP_CATEGORIES)}, the numeric inputs ({', '.join(NUMERIC_INPUTS)}) "
        f"and measured quantities ({', '.join(MEASURABLE)}) with <name>_sigma"
    )


def parse_row(i: int, record: Mapping[str, Any], units: Mapping[str, str]) -> Row:
    """Drop ``i`` (from 0) of a file: ``record`` column -> value, ``units`` the ``[units]``
    table. ValueError naming the drop and the column for anything it cannot use."""
    where = f"drop {i + 1}"
    cols = []
    seen: dict[str, str] = {}
    for key, v in record.items():
        name, unit = split_header(str(key))
        kind, canon = _kind(where, name)
        if canon in seen:
            raise ValueError(
                f"{where}: {canon} is given twice (columns {seen[canon]!r} and {str(key)!r}); "
                "keep one"
            )
        seen[canon] = str(key)
        cols.append((kind, canon, name, unit, v))
    # the unit of each measured value's column: its uncertainty's unless that has its own
    value_units = {c: u or units.get(n) for k, c, n, u, _ in cols if k == "value"}
    texts = {c: v for k, c, _, _, v in cols if k == "value"}
    label, cats, inputs, obs, sig = f"drop {i + 1}", {}, {}, {}, {}
    nan: set[str] = set()
    for kind, canon, name, unit, v in cols:
        if kind == "label":
            label = label if _blank(v) else str(v).strip()
            continue
        if _blank(v):
            if _is_nan(v):
                nan.add(canon)
            continue
        if kind == "category":
            cats[canon] = _category(where, canon, str(v).strip())
        elif kind == "input":
            unit = unit or units.get(name)
            if canon in UNIT_REQUIRED and not unit and bare(v):
                raise ValueError(
                    f"{where}: {canon}: the bare number {v!r} has no unit; an angle needs one, "
                    f"e.g. '20 deg', or a unit in the column header ('{canon} [deg]')"
                )
            spec = INPUTS[canon]
            unit = unit or (spec.parse_unit if spec.parse_unit != spec.unit else None)
            inputs[canon] = _value(where, name, v, unit, spec.unit)
        elif kind == "sigma":
            q = canon.removesuffix("_sigma")
            own = unit or units.get(name)
            unit = own or value_units.get(q) or units.get(name.removesuffix("_sigma"))
            _sigma_unit(where, name, v, unit, q, texts.get(q))
            sig[q] = _value(where, name, v, unit, MEASURABLE[q].unit)
        else:
            obs[canon] = _value(where, name, v, unit or units.get(name), MEASURABLE[canon].unit)
    row = Row(label, cats, inputs, obs, sig)
    _velocity(f"{where} ({label})", row)
    _body(f"{where} ({label})", row)
    _check_row(where, row, nan)
    return row


def _sigma_unit(where: str, name: str, v: Any, unit: str | None, q: str, value: Any) -> None:
    """A bare uncertainty beside a value written with its unit (``"12 um"``) would be read in
    SI: refused, with the value's unit to give it."""
    if unit or not bare(v) or MEASURABLE[q].unit in ("1", "") or value is None or bare(value):
        return
    if isinstance(value, str) and value.strip():
        shown = re.sub(r"^[-+0-9.eE]+\s*", "", value.strip())
        raise ValueError(
            f"{where}: {name} = {v!r} has no unit while {q} = {value!r} has one: give the "
            f"uncertainty's unit too (e.g. '{str(v).strip()} {shown}')"
        )


def _velocity(where: str, row: Row) -> None:
    """speed and incidence (together, without vx or vy) as vx, vy; ValueError otherwise."""
    given = [n for n in ("speed", "incidence") if n in row.inputs]
    if not given:
        return
    both = [n for n in ("vx", "vy") if n in row.inputs]
    if both:
        raise ValueError(
            f"{where}: {' and '.join(both)} and {' and '.join(given)} both given: they say the "
            "same thing (the velocity); give (vx, vy) or speed and incidence"
        )
    if len(given) == 1:
        other = "incidence" if given[0] == "speed" else "speed"
        raise ValueError(f"{where}: speed and incidence go together: {other} has no value")
    for name in given:
        check_allowed(name, [row.inputs[name]], f"{where}, column {name!r}")
    speed, incidence = row.inputs.pop("speed"), row.inputs.pop("incidence")
    row.inputs["vx"] = speed * math.sin(incidence)
    row.inputs["vy"] = -speed * math.cos(incidence)


def _body(where: str, row: Row) -> None:
    """A sphere's inputs on a sphere, a rod's on a rod (what the engine would ignore)."""
    if row.categories.get("body", "rod") == "sphere":
        rod_only = [n for n in _ROD_ONLY if n in row.inputs]
        if rod_only:
            raise ValueError(
                f"{where}: {', '.join(rod_only)}: a sphere has no angle, length, tip radius or "
                "inertia (its radius, and its mass or the body material's density); leave "
                "them out, or make the drop a rod"
            )
        if "radius" not in row.inputs:
            raise ValueError(
                f"{where}: a sphere needs its radius (column 'radius'); its mass is the "
                "column 'mass', or comes from the body material's density"
            )
        row.inputs["angle"] = math.pi / 2.0  # a sphere has no axis: the angle is unused
    elif "radius" in row.inputs:
        raise ValueError(
            f"{where}: radius is the radius of a sphere, and this drop's body is a rod; a "
            "rod's tip radius is the column 'tip_radius'"
        )


def _check_row(where: str, row: Row, nan: set[str]) -> None:
    for req in ("angle", "vy"):
        if req not in row.inputs:
            raise ValueError(f"{where} ({row.label}): the drop needs {req!r}")
    where = f"{where} ({row.label})"
    _check_inputs(where, row)
    if row.inputs["vy"] >= 0.0:
        raise ValueError(f"{where}: vy = {row.inputs['vy']:g} m/s must be < 0 (towards the flat)")
    for q in row.sigma:
        if q not in row.observed:
            if q in nan:
                raise ValueError(
                    f"{where}: {q} is NaN (not a number) while {q}_sigma is given: give {q}, "
                    "or leave both out for a drop that did not measure it"
                )
            raise ValueError(f"{where}: {q}_sigma is given without {q}")
    for q, x in row.observed.items():
        s = row.sigma.get(q)
        if s is None:
            if f"{q}_sigma" in nan:
                raise ValueError(
                    f"{where}: {q}_sigma is NaN (not a number): give the standard uncertainty "
                    f"of {q}, a number > 0"
                )
            raise ValueError(
                f"{where}: {q} = {x:g} has no standard uncertainty; add the column {q}_sigma "
                "(same unit), > 0"
            )
        if not (math.isfinite(s) and s > 0.0):
            raise ValueError(f"{where}: {q}_sigma must be finite and > 0, got {s!r}")
        m = MEASURABLE[q]
        if (m.low is not None and x < m.low) or (m.high is not None and x > m.high):
            raise ValueError(
                f"{where}: {q} = {x:g}{unit_text(m.unit)} lies outside the possible range "
                f"[{m.low}, {m.high}] ({m.description})"
            )
        if q == "e_t" and row.inputs.get("vx", 0.0) == 0.0:
            raise ValueError(f"{where}: e_t needs a drop with vx != 0")
    _check_magnitudes(where, row)


def _check_inputs(where: str, row: Row) -> None:
    """The values a single impact refuses (the sweep's rules: ``sweep.dimensions``): an angle
    of a rod outside (0, 90] deg, mu < 0, a size, mass or material property <= 0, ...; and
    implausible magnitudes, a unit left out (``input_magnitudes``: a yield strength of 300 Pa)."""
    for name, x in row.inputs.items():
        check_allowed(name, [x], f"{where}, column {name!r}")
        check_magnitude(name, x, INPUTS[name].unit, f"{where}, column {name!r}")
    if row.categories.get("body", "rod") != "sphere":
        check_rod_angles([row.inputs["angle"]], f"{where}, column 'angle'")


def _check_magnitudes(where: str, row: Row) -> None:
    """A unit mistake read as a value: a dent deeper than the tip radius (um read as m), a mark
    of kilometres, a contact of seconds; an uncertainty as large (or wider than the whole
    range of a restitution)."""
    radius = row.inputs.get("tip_radius", row.inputs.get("radius"))
    if radius is None and row.categories.get("body", "rod") != "sphere":
        radius = PAPER_ROD.tip_radius
    for q, x in row.observed.items():
        s, m = row.sigma[q], MEASURABLE[q]
        limit, hint = PLAUSIBLE.get(q, (0.0, ""))
        if q in ("delta_p", "delta_max"):
            limit, hint = radius or 0.0, "um"
        if limit and abs(x) > limit:
            what = "the tip radius" if q.startswith("delta") else "what an impact gives"
            raise ValueError(
                f"{where}: {q} = {x:g} {m.unit} exceeds {what} ({limit:g} {m.unit}): an "
                f"implausible magnitude; give its unit (e.g. '12 {hint}' or a header "
                f"'{q} [{hint}]')"
            )
        if limit and s > limit:
            raise ValueError(
                f"{where}: {q}_sigma = {s:g} {m.unit} exceeds {limit:g} {m.unit}: an "
                f"implausible magnitude for the uncertainty of {q}; give its unit (e.g. "
                f"'2 {hint}' or a header '{q}_sigma [{hint}]')"
            )
        if m.low is not None and m.high is not None and s > m.high - m.low:
            raise ValueError(
                f"{where}: {q}_sigma = {s:g} is wider than the whole range of {q} "
                f"[{m.low:g}, {m.high:g}]: an implausible uncertainty; check its unit and value"
            )
