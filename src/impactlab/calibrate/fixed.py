"""The inputs a candidate model fixes for every drop (``CandidateModel.fixed``, a ``[[model]]``
table's ``fixed``): known names (a misspelt one is refused with the nearest), values with units
(or results.json's quantity objects) read in the input's own unit, the single impact's allowed
range (``sweep.dimensions``) and a plausible magnitude (``input_magnitudes``: a bare
``flat_yield_strength = 300`` is 300 Pa); and the law parameters a model sets
(``CandidateModel.law_params``), read as the contact law reads them."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from impactlab.calibrate.input_magnitudes import check_magnitude
from impactlab.calibrate.measurement_columns import fraction
from impactlab.calibrate.quantities import FRACTIONS, KINEMATICS, NUMERIC_INPUTS
from impactlab.calibrate.values import did_you_mean, to_unit
from impactlab.contact import get_law
from impactlab.sweep.dimensions import check_allowed
from impactlab.sweep.inputs import INPUTS

__all__ = ["FIXABLE", "fixed_values", "law_param_values", "quantity_object"]

#: What a model may fix: the inputs a free parameter may be (not a drop's kinematics).
FIXABLE: tuple[str, ...] = tuple(n for n in NUMERIC_INPUTS if n not in KINEMATICS)


def quantity_object(v: Any) -> Any:
    """A quantity object of results.json (``{"value": 3e8, "unit": "Pa"}``) as the text of
    that quantity (``"300000000.0 Pa"``); anything else as it is."""
    if isinstance(v, Mapping) and set(v) == {"value", "unit"}:
        value, unit = v["value"], str(v["unit"])
        if isinstance(value, int | float) and not isinstance(value, bool):
            return value if unit in ("", "1") else f"{float(value)!r} {unit}"
    return v


def fixed_values(model: str, fixed: Any) -> dict[str, float]:
    """``fixed`` (input name -> a number in the input's unit, a quantity string, ``"300
    MPa"``, a fraction in percent, ``"5 %"``, or a quantity object of results.json, ``{"value":
    3e8, "unit": "Pa"}``) as numbers
    in each input's unit. ValueError naming the model and the key for an unknown name, an
    unreadable value, one outside the input's allowed range or an implausible magnitude (a unit
    left out)."""
    if not isinstance(fixed, Mapping):
        raise ValueError(
            f"model {model!r}: fixed must be a table of input = value (e.g. "
            f"{{ damping = 0.05 }}), got {fixed!r}"
        )
    out: dict[str, float] = {}
    for key, v in fixed.items():
        name = str(key)
        if name not in FIXABLE:
            raise ValueError(
                f"model {model!r}: fixed {name!r} is not an input a model can fix"
                f"{did_you_mean(name, FIXABLE)}; known: {', '.join(FIXABLE)}"
            )
        where = f"model {model!r}, fixed {name}"
        v = quantity_object(v)
        if isinstance(v, bool) or not isinstance(v, int | float | str):
            raise ValueError(f"{where}: expected a number or a quantity string, got {v!r}")
        try:
            share = fraction(name, v, None) if name in FRACTIONS else None
            x = share if share is not None else to_unit(v, INPUTS[name].unit, name=name)
        except ValueError as exc:
            raise ValueError(f"{where}: {exc}") from None
        check_allowed(name, [x], where)
        check_magnitude(name, x, INPUTS[name].unit, where)
        out[name] = x
    return out


def law_param_values(model: str, law: str, law_params: Any) -> dict[str, float]:
    """``law_params`` (parameter name -> a number in the parameter's unit, a quantity string,
    ``"105 kgf/mm^2"``, a quantity object of results.json, ``{"value": 105, "unit":
    "kgf/mm^2"}``, or a switch's True/False) as numbers in each parameter's unit, read by the
    contact law ``law`` (``ContactLaw.parameter_values``). ValueError naming the model for an
    unknown name or a bad value."""
    if not isinstance(law_params, Mapping):
        raise ValueError(
            f"model {model!r}: law_params must be a table of parameter = value (e.g. "
            f'{{ hardness = "105 HB" }}), got {law_params!r}'
        )
    contact_law = get_law(law)
    units = {q.name: q.unit for q in contact_law.parameters if q.unit not in ("", "-", "1")}
    try:
        given = {}
        for key, v in law_params.items():
            v = quantity_object(v)
            if isinstance(v, str) and key in units:  # "105 HB" read as the calibration reads it
                v = to_unit(v, units[key], name=str(key))
            given[str(key)] = v
        values = contact_law.parameter_values(given)
    except ValueError as exc:
        raise ValueError(f"model {model!r}, law_params: {exc}") from None
    where = f"model {model!r}, law_params"
    for key, x in values.items():  # a hardness of 1.03e9: Pa read as kgf/mm^2
        if units.get(key) == "kgf/mm^2":
            check_magnitude(key, x, "kgf/mm^2", where, like="flat_brinell_hardness")
    return values
