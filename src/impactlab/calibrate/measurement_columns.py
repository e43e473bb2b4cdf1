"""The columns of a measurements file: what each name is (aliases resolved), the ``[units]``
table of a TOML file read through the same names, and values in percent.

A ``[units]`` key is a column's name as a drop's column would be written (``T`` is
``duration``, ``F_sigma`` is ``mean_force_sigma``); a key that names no column, or a column
that is not a quantity (``label``, ``body``), is refused, so that no unit is dropped silently.
A fraction (``quantities.FRACTIONS``: e, e_energy, e_t, mu, damping) may be given in percent,
1 % = 0.01 of 1 (``"43 %"``, a header ``e [%]``, ``[units] e = "%"``); a plain number's column
may say so (``e [-]``, ``e [1]``: ``PLAIN_MARKS``), which a quantity with a unit refuses. A
correlation coefficient (``correlation_e_spin_out``, ``impactlab.calibrate.correlations``) is a
plain number: no unit.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from functools import cache
from typing import Any

from impactlab.calibrate.correlations import PREFIX, correlation_column, correlation_pair
from impactlab.calibrate.quantities import (
    AMBIGUOUS,
    ANGLES,
    DROP_CATEGORIES,
    FRACTIONS,
    KINEMATICS,
    MEASURABLE,
    NUMERIC_INPUTS,
    OUTPUT_ALIASES,
    canonical_output,
)
from impactlab.calibrate.values import bare, did_you_mean, is_number, to_unit
from impactlab.sweep.inputs import INPUTS
from impactlab.units import parse_quantity, to_si

__all__ = [
    "LABEL_KEYS",
    "check_column_unit",
    "column_kind",
    "fraction",
    "given_unit",
    "in_unit",
    "input_sigma",
    "is_percent",
    "resolve_units",
    "split_header",
]

LABEL_KEYS = ("label", "drop", "name")
#: Every column name a drop takes (for the nearest name offered for a misspelt one).
_COLUMNS: tuple[str, ...] = (
    *LABEL_KEYS,
    *DROP_CATEGORIES,
    *NUMERIC_INPUTS,
    *(n for q in (*MEASURABLE, *OUTPUT_ALIASES) for n in (q, f"{q}_sigma")),
)
_PERCENT = re.compile(r"^\s*(?P<x>\S+?)\s*(?:%|percent)\s*$", re.IGNORECASE)
#: A number standing alone in a unit's text (``10 um``, ``1e-6 m``; not the 2 of ``m^2``).
_NUMBER = re.compile(r"(?:^|\s)[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?(?=\s|$)")
#: A unit to show for each SI unit (or a Brinell hardness's kgf/mm^2) in an example.
_EXAMPLE = {"m": "um", "s": "ms", "Pa": "MPa", "kg": "g", "J": "mJ", "rad": "deg",
            "kgf/mm^2": "HB"}  # fmt: skip


#: Unit texts that mark a plain number (a header ``e [-]`` or ``e [1]``): read as unit "1".
PLAIN_MARKS = ("-", "1")


def split_header(key: str) -> tuple[str, str | None]:
    """``"delta_p [um]"`` -> ("delta_p", "um"); a plain-number mark (``"e [-]"``,
    ``PLAIN_MARKS``) -> ("e", "1")."""
    key = key.strip()
    if key.endswith("]") and "[" in key:
        name, unit = key[:-1].split("[", 1)
        unit = unit.strip()
        return name.strip(), "1" if unit in PLAIN_MARKS else unit
    return key, None


def column_kind(where: str, name: str) -> tuple[str, str]:
    """(what the column is: "label", "category", "input", "sigma", "value", "correlation", its
    canonical name: ``correlation_<a>_<b>`` in the order of ``MEASURABLE``); ValueError for a
    column a drop does not take (with the nearest name) and for a column without a name."""
    if not name.strip():
        raise ValueError(
            f"{where}: a column has an empty name ({name!r}); name the column, or leave it out"
        )
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
    if name.endswith("_sigma") and name.removesuffix("_sigma") in NUMERIC_INPUTS:
        raise ValueError(f"{where}: column {name!r}: {input_sigma(name.removesuffix('_sigma'))}")
    if name.endswith("_sigma") and q:
        return "sigma", f"{q}_sigma"
    if canonical_output(name):
        return "value", str(canonical_output(name))
    if name.startswith(PREFIX):
        return "correlation", correlation_column(*correlation_pair(where, name))
    if ";" in name or "\t" in name:
        raise ValueError(
            f"{where}: the header is one column {name!r}: the file separates its columns "
            "with ';' or tabs; a measurements CSV separates them with commas"
        )
    raise ValueError(
        f"{where}: unknown column {name!r}{did_you_mean(name, _COLUMNS)}; a drop takes label, "
        f"{', '.join(DROP_CATEGORIES)}, the numeric inputs ({', '.join(NUMERIC_INPUTS)}) "
        f"and measured quantities ({', '.join(MEASURABLE)}) with <name>_sigma (and "
        "correlation_<a>_<b>)"
    )


def check_column_unit(where: str, key: str) -> None:
    """ValueError naming ``where`` and the column ``key`` (a header, ``"delta_p [10 um]"``)
    when its unit is not one of its column: text that is no unit (a number in it, a bracket,
    an unknown name), a unit of another dimension, percent on a quantity that is no fraction,
    any unit on the label, a category or a correlation coefficient. A column that is not known
    is left to the rows' reading, which names it."""
    problem = _header_problem(key)
    if problem:
        raise ValueError(f"{where}: column {key!r}: {problem}")


@cache
def _header_problem(key: str) -> str | None:
    """What is wrong with the unit of the header ``key`` (``check_column_unit``), or None."""
    name, unit = split_header(key)
    if unit is None:
        return None
    unit = key.strip()[:-1].split("[", 1)[1].strip()  # as written, for the message
    try:
        kind, canon = column_kind("", name)
    except ValueError:
        return None
    if kind in ("label", "category"):  # even an empty "[]"
        return f"{name} is not a quantity, so it takes no unit; write the header {name!r}"
    if not unit or (kind == "correlation" and unit in PLAIN_MARKS):
        return None
    if kind == "correlation":
        return (
            "a correlation coefficient is a plain number in [-1, 1] and takes no unit; write "
            f"the header {name!r}"
        )
    found = unit_problem(canon, unit)
    if found is None:
        return None
    takes = _valid_units(name, canon, "{name} [{unit}]", f"the header {name!r}")
    return f"{found}; {name} takes {takes}"


def unit_problem(canon: str, unit: str) -> str | None:
    """Why the text ``unit`` is no unit of the numeric column ``canon`` (a canonical input,
    measured quantity or ``<quantity>_sigma``): ``"'10 um' is not a unit: ..."``; None when it
    is one (the ``_value`` reading of a row then takes it)."""
    base = canon.removesuffix("_sigma")
    if is_percent(unit):
        if base in FRACTIONS:
            return None
        return f"{unit!r} is percent, and only a fraction ({', '.join(FRACTIONS)}) may be"
    target = INPUTS[canon].unit if canon in INPUTS else MEASURABLE[base].unit
    if unit in PLAIN_MARKS:
        return None if target in ("1", "") else f"{unit!r} marks a plain number, without a unit"
    try:
        to_unit(f"1 {unit}", target, name=canon)
    except ValueError as exc:
        if "Brinell" in str(exc):  # HB on another input than a Brinell hardness
            return f"{unit!r} is a Brinell hardness's unit, not one of {target}"
    else:
        return None
    if "[" in unit or "]" in unit:
        return f"{unit!r} is not a unit: it holds a bracket (a header gives one [unit])"
    if _NUMBER.search(unit):
        return (
            f"{unit!r} is not a unit: it holds a number (a column's unit is written alone; "
            "each drop gives its number)"
        )
    try:
        to_si(1.0, unit)
    except Exception as exc:  # pint raises many kinds for text that is no unit
        detail = str(exc).strip()
        return f"{unit!r} is not a unit" + (f" ({detail})" if detail else "")
    if target in ("1", ""):
        return f"{unit!r} is a unit, where a plain number is expected"
    return f"{unit!r} has the wrong dimension"


def _valid_units(name: str, canon: str, form: str, plain: str) -> str:
    """What units the column ``name`` (canonical ``canon``) takes, with an example written
    as ``form`` (``"{name} [{unit}]"``); ``plain``: how it is written without one."""
    base = canon.removesuffix("_sigma")
    target = INPUTS[canon].unit if canon in INPUTS else MEASURABLE[base].unit
    if target in ("1", ""):
        if base in FRACTIONS:
            percent = form.format(name=name, unit="%")
            return f"no unit (a fraction of 1: {plain}) or percent, e.g. {percent!r}"
        return f"no unit (a plain number: {plain})"
    example = form.format(name=name, unit=_EXAMPLE.get(target, target))
    return f"a unit convertible to {target}, e.g. {example!r}"


def input_sigma(name: str) -> str:
    """Why the input ``name`` of a drop takes no uncertainty (a column ``<name>_sigma``), and
    how an uncertain one is calibrated."""
    exact = (
        f"{name} is an input of the drop, taken as exact; only a measured quantity takes an "
        "uncertainty (<quantity>_sigma)"
    )
    if name in KINEMATICS:
        return f"{exact}: remove the column"
    if name in ("n_axial", "n_bending"):  # integer mode counts: nothing to measure
        return f"{exact} (a count of the flexible rod's modes): remove the column"
    return (
        f"{exact}. An uncertain {name} is calibrated as a free parameter with a normal prior "
        f'of its value and uncertainty, e.g. -p "{name}=normal(mean, sd)" ([parameters] in a '
        f"config file; one value for every drop, in place of the file's {name}): remove the "
        "column"
    )


def resolve_units(units: Any) -> dict[str, str]:
    """The ``[units]`` table as canonical column -> unit text (``{"T": "ms"}`` ->
    ``{"duration": "ms"}``). ValueError naming the key for one that names no column (with
    the nearest name), a column that is not a quantity (label, body, materials), a column
    named twice (``T`` and ``duration``) and a unit that is not text."""
    if not isinstance(units, Mapping):
        raise ValueError(f"[units] must be a table of column = unit, got {units!r}")
    out: dict[str, str] = {}
    keys: dict[str, str] = {}
    for key, unit in units.items():
        name = str(key)
        base = name.removesuffix("_sigma")
        if name.startswith(PREFIX):
            raise ValueError(
                f"[units] {name} = {unit!r}: a correlation coefficient is a plain number in "
                "[-1, 1] and takes no unit; remove the key"
            )
        if name not in _COLUMNS and base not in AMBIGUOUS and base not in NUMERIC_INPUTS:
            raise ValueError(
                f"[units]: unknown column {name!r}{did_you_mean(name, _COLUMNS)}; a key of "
                "[units] is a column of the drops: a numeric input, a measured quantity or its "
                "_sigma"
            )
        kind, canon = column_kind("[units]", name)
        if kind in ("label", "category"):
            raise ValueError(
                f"[units] {name} = {unit!r}: {name} is not a quantity ({_what(kind)}), so it "
                "takes no unit; remove the key"
            )
        if not isinstance(unit, str) or not unit.strip():
            raise ValueError(
                f'[units] {name} = {unit!r}: a unit is text, e.g. {name} = "um" (a number '
                'with its unit belongs in the drop: "22 um")'
            )
        found = unit_problem(canon, unit.strip())
        if found:
            takes = _valid_units(name, canon, '{name} = "{unit}"', "no [units] entry")
            raise ValueError(f"[units] {name} = {unit!r}: {found}; {name} takes {takes}")
        if canon in keys:
            raise ValueError(
                f"[units]: {canon} is given twice (keys {keys[canon]!r} and {name!r}); keep one"
            )
        text = unit.strip()
        keys[canon], out[canon] = name, "1" if text in PLAIN_MARKS else text
    return out


def _what(kind: str) -> str:
    return "the drop's name" if kind == "label" else "a body or a material, chosen by name"


def is_percent(unit: str | None) -> bool:
    """Whether the unit text ``unit`` is percent (``%``, ``percent``)."""
    return unit is not None and unit.strip().lower() in ("%", "percent")


def fraction(name: str, v: Any, column_unit: str | None) -> float | None:
    """``v`` as a fraction of 1 when it is in percent (``"43 %"``, or a bare 43 in a column of
    unit ``%``): 0.43; None when it is not. ValueError for a percentage of ``name`` when
    ``name`` is no fraction (``quantities.FRACTIONS``)."""
    m = _PERCENT.match(v) if isinstance(v, str) else None
    if m and is_number(m.group("x")):
        x = float(m.group("x"))
    elif is_percent(column_unit) and not isinstance(v, bool) and _number(v):
        x = float(v)
    else:
        return None
    base = name.removesuffix("_sigma")
    if base not in FRACTIONS:
        raise ValueError(
            f"{name}: {v!r} is in percent; only a fraction ({', '.join(FRACTIONS)}) may be, and "
            f"{base} is not one: give it as a plain number"
        )
    return x / 100.0


def _number(v: Any) -> bool:
    return isinstance(v, int | float) or (isinstance(v, str) and is_number(v))


def given_unit(q: str, v: Any, column_unit: str | None) -> str | None:
    """The unit the file gave the value ``v`` of the measured quantity ``q`` in: its column's
    (``column_unit``: the header's or the ``[units]`` entry's) or a quantity string's own
    (``"64 um"``: ``um``; ``"43 %"``: ``%``); None for a bare number in a column without one."""
    if column_unit:
        return column_unit
    if not isinstance(v, str) or bare(v):
        return None
    if _PERCENT.match(v):
        return "%"
    try:
        return f"{parse_quantity(q, v, MEASURABLE[q].unit).units:~}"
    except ValueError:
        return None


def in_unit(q: str, x: float, unit: str | None = None) -> tuple[float, str]:
    """(``x``, a value of the measured quantity ``q`` in SI, in ``unit``: the unit the file gave
    it in, ``given_unit``; that unit as an error writes it after the number, `` um``): an angle
    always in degrees (its range is in degrees), with no ``unit`` (or one of 1) SI."""
    if q in ANGLES:
        return math.degrees(x), " deg"
    if unit and is_percent(unit):
        return x * 100.0, " %"
    if unit and unit.strip() not in ("1", "-"):
        try:
            return x / to_si(1.0, unit), f" {unit.strip()}"
        except (ValueError, AttributeError):  # pint's unknown unit is an AttributeError
            pass
    si = MEASURABLE[q].unit
    return x, "" if si in ("1", "", "-") else f" {si}"
