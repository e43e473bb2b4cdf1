"""The inputs a candidate model fixes for every drop (``CandidateModel.fixed``, a ``[[model]]``
table's ``fixed``): known names (a misspelt one is refused with the nearest), values with units
read in the input's own unit, and the single impact's allowed range (``sweep.dimensions``)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from impactlab.calibrate.quantities import KINEMATICS, NUMERIC_INPUTS
from impactlab.calibrate.values import did_you_mean, to_unit
from impactlab.sweep.dimensions import check_allowed
from impactlab.sweep.inputs import INPUTS

__all__ = ["FIXABLE", "fixed_values"]

#: What a model may fix: the inputs a free parameter may be (not a drop's kinematics).
FIXABLE: tuple[str, ...] = tuple(n for n in NUMERIC_INPUTS if n not in KINEMATICS)


def fixed_values(model: str, fixed: Any) -> dict[str, float]:
    """``fixed`` (input name -> a number in the input's unit or a quantity string, ``"300
    MPa"``) as numbers in each input's unit. ValueError naming the model and the key for an
    unknown name, an unreadable value or one outside the input's allowed range."""
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
        if isinstance(v, bool) or not isinstance(v, int | float | str):
            raise ValueError(f"{where}: expected a number or a quantity string, got {v!r}")
        try:
            x = to_unit(v, INPUTS[name].unit, name=name)
        except ValueError as exc:
            raise ValueError(f"{where}: {exc}") from None
        check_allowed(name, [x], where)
        out[name] = x
    return out
