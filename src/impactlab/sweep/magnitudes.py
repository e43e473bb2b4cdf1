"""Implausible magnitudes of a drop's inputs, a unit left out: a bare number is in the input's
unit (SI; a Brinell hardness in kgf/mm^2), so ``flat_yield_strength = 276`` is 276 Pa. A
study refuses such a material value when it is built, as a material by values
(``materials.inputs``) and a calibration's inputs (``calibrate.input_magnitudes``) do."""

from __future__ import annotations

import math
from collections.abc import Sequence

from impactlab.materials.core import PLAUSIBLE

__all__ = ["MATERIAL_MAGNITUDES", "check_magnitudes", "magnitude_error"]

#: Study input -> the Material field whose plausible range it has.
_FIELD = {
    **{f"{side}_E": "E" for side in ("body", "flat")},
    **{f"{side}_yield_strength": "yield_strength" for side in ("body", "flat")},
    **{f"{side}_brinell_hardness": "brinell_hardness" for side in ("body", "flat")},
    "body_density": "density",
}


def _one_side(field: str) -> tuple[float, float, str]:
    """(low, high, the unit to suggest) on the side a unit left out gives: a modulus,
    strength or density too small (MPa, GPa or g/cm^3 read as SI; a value too large is a
    case's to refuse), a Brinell hardness too large (Pa read as kgf/mm^2)."""
    low, high, _unit, hint = PLAUSIBLE[field]
    return (0.0, high, hint) if field == "brinell_hardness" else (low, math.inf, hint)


#: Input -> (lowest, highest plausible value in the input's unit, the unit to suggest) of
#: the material values (``materials.core.PLAUSIBLE``, on the side a unit left out gives).
MATERIAL_MAGNITUDES: dict[str, tuple[float, float, str]] = {
    name: _one_side(field) for name, field in _FIELD.items()
}


def magnitude_error(
    name: str, x: float, unit: str, where: str, rule: tuple[float, float, str]
) -> ValueError | None:
    """The ValueError naming ``where``, ``name`` and the unit to give when ``x`` (in ``unit``)
    lies outside ``rule`` = (low, high, the unit to suggest); None inside it."""
    low, high, hint = rule
    if low <= x <= high:
        return None
    side = f"below {low:g}" if x < low else f"above {high:g}"
    return ValueError(
        f"{where}: {name} = {x:g} {unit} is {side} {unit}: an implausible magnitude (a number "
        f"without its unit is in {unit}); give its unit, e.g. '{x:g} {hint}'"
    )


def check_magnitudes(name: str, values: Sequence[float], where: str) -> None:
    """ValueError naming ``where`` and the first value of input ``name`` (SI; a Brinell
    hardness in kgf/mm^2) outside ``MATERIAL_MAGNITUDES``, with the unit most likely left
    out."""
    rule = MATERIAL_MAGNITUDES.get(name)
    if rule is None:
        return
    unit = PLAUSIBLE[_FIELD[name]][2]
    for x in values:
        error = magnitude_error(name, x, unit, where, rule) if x > 0 else None
        if error is not None:
            raise error
