"""One drop of a measurements file: its columns read (units, aliases, the unit of an
uncertainty) and checked, with one-line errors naming the drop and the column.

A value is a number (a Python or numpy real scalar), a quantity string, a pint Quantity of any
registry (read as the string of its value and unit) or blank (None, an empty string, NaN: not
given). Numbers are kept in each input's own unit (``impactlab.sweep.inputs``: SI, the Brinell
hardness in kgf/mm^2) and measured values in SI. A bare ``<quantity>_sigma`` takes its
quantity's unit (the column header's or the ``[units]`` entry's). A drop's velocity is (vx, vy)
or speed and incidence (converted to vx, vy as the sweep does), never both.
"""

from __future__ import annotations

import math
import re
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.bodies import PAPER_ROD
from impactlab.calibrate.correlations import check_drop, coefficient, correlation_pair
from impactlab.calibrate.input_magnitudes import check_magnitude
from impactlab.calibrate.measurement_columns import (
    LABEL_KEYS,
    check_column_unit,
    column_kind,
    fraction,
    given_unit,
    in_unit,
    resolve_units,
    split_header,
)
from impactlab.calibrate.quantities import (
    ANGLES,
    E_GRAVITY_DURATION,
    MEASURABLE,
    NOISE_SIGMAS,
    PLAUSIBLE,
)
from impactlab.calibrate.values import bare, did_you_mean, in_own_unit, to_unit
from impactlab.materials import G0, PRESETS
from impactlab.sweep.dimensions import check_allowed, check_rod_angles
from impactlab.sweep.inputs import INPUTS, UNIT_REQUIRED
from impactlab.units import is_quantity

__all__ = ["LABEL_KEYS", "Row", "parse_row", "split_header", "unit_text"]

#: Inputs of a rod that a sphere does not have (as in a sweep of spheres).
_ROD_ONLY = ("angle", "length", "tip_radius", "inertia")


@dataclass
class Row:
    """One drop: label, categories, inputs (each in its own unit), observed and sigma (SI);
    units: the unit each measured value was given in (``given_unit``), which its errors use;
    correlation: (a, b) -> the correlation coefficient of the values of a and b."""

    label: str
    categories: dict[str, str]
    inputs: dict[str, float]
    observed: dict[str, float]
    sigma: dict[str, float]
    units: dict[str, str] = field(default_factory=dict)
    correlation: dict[tuple[str, str], float] = field(default_factory=dict)


def unit_text(unit: str) -> str:
    """`` unit``, or nothing for a pure number."""
    return "" if unit in ("1", "", "-") else f" {unit}"


def _plain(where: str, key: str, v: Any) -> Any:
    """A numpy real scalar (``np.float32(0.4)``, ``np.int64(-2)``) as the Python number it
    holds; a scalar pint Quantity of any registry as the string of its value and unit
    (``"-2.0 m / s"``, read as a quantity string is; ValueError naming the column for an
    array); anything else (a numpy bool too, refused as a value) as it is."""
    if is_quantity(v):
        m = v.magnitude
        m = m.item() if isinstance(m, np.ndarray) and m.ndim == 0 else _plain(where, key, m)
        if isinstance(m, bool) or not isinstance(m, int | float):
            raise ValueError(
                f"{where}: {key} must be one number with its unit, got the Quantity {v!r}"
            )
        return f"{float(m)!r} {v.units:~}".strip()
    return v.item() if isinstance(v, np.integer | np.floating) else v


def _is_nan(v: Any) -> bool:
    return isinstance(v, float) and math.isnan(v)


def _blank(v: Any) -> bool:
    return v is None or (isinstance(v, str) and not v.strip()) or _is_nan(v)


def _value(
    where: str, name: str, v: Any, column_unit: str | None, unit: str, canon: str = ""
) -> float:
    """``v`` in ``unit``: a bare number is in ``column_unit`` (the column header's or the
    ``[units]`` table's; None: ``unit``) and must fit its dimension, as a unit in a value must;
    a fraction (``canon``, the column's canonical name) may be in percent."""
    if isinstance(v, bool) or not isinstance(v, int | float | str):
        raise ValueError(f"{where}: {name} must be a number or a quantity string, got {v!r}")
    try:
        part = fraction(canon or name, v, column_unit)
        if part is not None:
            return part
        if column_unit and bare(v):
            return to_unit(f"{str(v).strip()} {column_unit}", unit, name=name)
        if column_unit:
            to_unit(f"1 {column_unit}", unit, name=f"{name} (column unit [{column_unit}])")
        return to_unit(v, unit, name=name)
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None


def _angle_unit(where: str, name: str, v: Any, unit: str | None, header: str) -> None:
    """An angle (an input's or a measured one) refused as a bare number without a unit: 20
    could be degrees or radians (the angle rule, docs/glossary.md)."""
    if not unit and bare(v):
        raise ValueError(
            f"{where}: {name}: the bare number {v!r} has no unit; an angle needs one, "
            f"e.g. '{str(v).strip()} deg', or a unit in the column header ('{header} [deg]')"
        )


def _category(where: str, name: str, value: str) -> str:
    known = ("rod", "sphere") if name == "body" else tuple(PRESETS)
    if value not in known:
        raise ValueError(
            f"{where}: unknown {name} {value!r}{did_you_mean(value, known)}; known: "
            f"{', '.join(known)}"
        )
    return value


def parse_row(i: int, record: Mapping[str, Any], units: Mapping[str, Any]) -> Row:
    """Drop ``i`` (from 0) of a file: ``record`` column -> value, ``units`` the ``[units]``
    table (its keys read as column names: ``measurement_columns.resolve_units``). ValueError
    naming the drop and the column for anything it cannot use."""
    where = f"drop {i + 1}"
    units = resolve_units(units)
    cols = []
    seen: dict[str, str] = {}
    for key, given in record.items():
        v = _plain(where, str(key), given)
        name, unit = split_header(str(key))
        kind, canon = column_kind(where, name)
        if canon in seen:
            raise ValueError(
                f"{where}: {canon} is given twice (columns {seen[canon]!r} and {str(key)!r}); "
                "keep one"
            )
        check_column_unit(where, str(key))
        seen[canon] = str(key)
        cols.append((kind, canon, name, unit or units.get(canon), v))
    # the unit of each measured value's column: its uncertainty's unless that has its own
    value_units = {c: u for k, c, _, u, _ in cols if k == "value"}
    texts = {c: v for k, c, _, _, v in cols if k == "value"}
    label, cats, inputs, obs, sig, given, corr = f"drop {i + 1}", {}, {}, {}, {}, {}, {}
    nan: set[str] = set()
    for kind, canon, name, unit, v in cols:
        if kind == "label":
            label = label if _blank(v) else str(v).strip()
            continue
        if _blank(v):
            if _is_nan(v):
                nan.add(canon)
            continue
        if kind == "correlation":
            corr[correlation_pair(where, canon)] = coefficient(where, name, v, unit)
        elif kind == "category":
            cats[canon] = _category(where, canon, str(v).strip())
        elif kind == "input":
            if canon in UNIT_REQUIRED:
                _angle_unit(where, canon, v, unit, canon)
            spec = INPUTS[canon]
            unit = unit or (spec.parse_unit if spec.parse_unit != spec.unit else None)
            inputs[canon] = _value(where, name, v, unit, spec.unit, canon)
        elif kind == "sigma":
            q = canon.removesuffix("_sigma")
            own, unit = bool(unit), unit or value_units.get(q) or units.get(q)
            _sigma_unit(where, name, v, unit, q, texts.get(q), value_units.get(q), own)
            if q in ANGLES:
                _angle_unit(where, name, v, unit, f"{q}_sigma")
            sig[q] = _value(where, name, v, unit, MEASURABLE[q].unit, canon)
        else:
            if canon in ANGLES:
                _angle_unit(where, name, v, unit, canon)
            obs[canon] = _value(where, name, v, unit, MEASURABLE[canon].unit, canon)
            given[canon] = given_unit(canon, v, unit)
    row = Row(label, cats, inputs, obs, sig, {q: u for q, u in given.items() if u}, corr)
    _velocity(f"{where} ({label})", row)
    _body(f"{where} ({label})", row)
    _check_row(where, row, nan)
    check_drop(f"{where} ({label})", corr, list(obs))
    return row


def _sigma_unit(
    where: str, name: str, v: Any, unit: str | None, q: str, value: Any, value_unit: Any, own: bool
) -> None:
    """Refused: a bare uncertainty, not in a column of its ``own`` unit, beside a value with a
    unit of its own (``"12 um"``, not ``unit``); one in percent beside a value that is not
    (``e = 0.43``, ``e_sigma = "5 %"``: 5 % of e or 0.05?)."""
    if value is None or _blank(value):
        return
    try:
        value_part = fraction(q, value, value_unit) is not None
        own_part = fraction(name, v, unit) is not None
    except ValueError as exc:
        raise ValueError(f"{where}: {exc}") from None
    if own_part and not value_part:
        raise ValueError(
            f"{where}: {name} = {_shown(v, unit)!r} is in percent while {q} = "
            f"{_shown(value, value_unit)!r} is not: a percentage of {q} could be relative (of "
            f"the value) or of 1; give {name} as {q} is (a fraction of 1), or {q} in percent too"
        )
    if not bare(v) or bare(value) or own or (unit and not in_own_unit(value, unit)):
        return
    if MEASURABLE[q].unit in ("1", "") and not value_part:
        return
    if isinstance(value, str) and value.strip():
        shown = re.sub(r"^[-+0-9.eE]+\s*", "", value.strip())
        raise ValueError(
            f"{where}: {name} = {v!r} has no unit while {q} = {value!r} has one"
            f"{f' (a bare number is read in {unit})' if unit else ''}: give the uncertainty's "
            f"unit too (e.g. '{str(v).strip()} {shown}')"
        )


def _shown(v: Any, unit: str | None) -> str:
    """A value as the file gives it: ``"5 %"`` for a bare 5 in a column of unit %."""
    return f"{str(v).strip()} {unit}" if bare(v) and unit else str(v).strip()


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
            got = f"{math.degrees(s):g} deg" if q in ANGLES else repr(s)
            raise ValueError(f"{where}: {q}_sigma must be finite and > 0, got {got}")
        if s < sys.float_info.min:  # subnormal: 1/sigma^2 overflows the likelihood
            raise ValueError(
                f"{where}: {q}_sigma = {s!r} is below {sys.float_info.min:.3g} in SI: too small"
            )
        _check_range(where, row, q, x, s)
        if q == "e_t" and row.inputs.get("vx", 0.0) == 0.0:
            raise ValueError(f"{where}: e_t needs a drop with vx != 0")
    _check_magnitudes(where, row)


def _bound(x: float | None, open_end: float) -> float:
    return open_end if x is None else x


def _check_range(where: str, row: Row, q: str, x: float, s: float) -> None:
    """A measured value ``x`` (uncertainty ``s``) more than NOISE_SIGMAS sigma outside its
    quantity's possible range is refused; within, it is noise and used as measured. The
    range of e ends at 1 + g T/|vy|: its gravity impulse (T: E_GRAVITY_DURATION, or the drop's
    measured duration when longer)."""
    m = MEASURABLE[q]
    low, high, what = _bound(m.low, -math.inf), _bound(m.high, math.inf), m.description
    if q == "e":
        t = max(E_GRAVITY_DURATION, row.observed.get("duration", 0.0))
        high += G0 * t / abs(row.inputs["vy"])
        what = (
            "e, the normal COR with the gravity impulse of the contact removed, (v_n,out + g T)"
            f"/|v_n,in|, reaches 1 + g T/|vy|: g = {G0:g} m/s^2, T = {t * 1e3:g} ms (the longer "
            f"of {E_GRAVITY_DURATION * 1e3:g} ms and the drop's measured duration)"
        )
    if low - NOISE_SIGMAS * s <= x <= high + NOISE_SIGMAS * s:
        return
    unit = row.units.get(q)  # the unit the file gave the value in
    (shown, u), sd = in_unit(q, x, unit), in_unit(q, s, unit)[0]
    lo, hi = in_unit(q, low, unit)[0], in_unit(q, high, unit)[0]
    raise ValueError(
        f"{where}: {q} = {shown:g}{u} lies outside the possible range "
        f"[{lo:g}, {hi:g}]{u} by more than {NOISE_SIGMAS:g} "
        f"sigma ({q}_sigma = {sd:g}{u}; within {NOISE_SIGMAS:g} sigma a value is read as "
        f"measurement noise) ({what})"
    )


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
            unit = row.units.get(q)
            (shown, u), low = in_unit(q, s, unit), in_unit(q, m.low, unit)[0]
            high = in_unit(q, m.high, unit)[0]
            raise ValueError(
                f"{where}: {q}_sigma = {shown:g}{u} is wider than the whole range of {q} "
                f"[{low:g}, {high:g}]{u}: an implausible uncertainty; check its unit and value"
            )
