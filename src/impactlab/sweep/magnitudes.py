"""Implausible magnitudes of a study's material values: a modulus, strength, density or
Brinell hardness outside the plausible range of a solid (``materials.core.PLAUSIBLE``) is most
likely a number given without its unit (``flat_yield_strength = 276`` is 276 Pa): refused when
the study is built, as a material by values and a calibration's inputs refuse it."""

from __future__ import annotations

import math
from collections.abc import Sequence

from impactlab.materials.core import PLAUSIBLE

__all__ = ["check_magnitudes"]

#: Study input -> the Material field whose plausible range it has.
_FIELD = {
    **{f"{side}_E": "E" for side in ("body", "flat")},
    **{f"{side}_yield_strength": "yield_strength" for side in ("body", "flat")},
    **{f"{side}_brinell_hardness": "brinell_hardness" for side in ("body", "flat")},
    "body_density": "density",
}


def check_magnitudes(name: str, values: Sequence[float], where: str) -> None:
    """ValueError naming ``where`` and the first value of input ``name`` (SI; a Brinell
    hardness in kgf/mm^2) on the side of its plausible range that a unit left out gives (a
    modulus, strength or density below it; a hardness above it), with that unit."""
    field = _FIELD.get(name)
    if field is None:
        return
    low, high, unit, hint = PLAUSIBLE[field]
    if field == "brinell_hardness":  # Pa read as kgf/mm^2: too large
        low = 0.0
    else:  # MPa, GPa or g/cm^3 read as SI: too small (a value too large is a case's to refuse)
        high = math.inf
    for x in values:
        if x > 0 and not low <= x <= high:
            side = f"below {low:g}" if x < low else f"above {high:g}"
            raise ValueError(
                f"{where}: {name} = {x:g} {unit} is {side} {unit}: an implausible magnitude (a "
                f"number without its unit is in {unit}); give its unit, e.g. '{x:g} {hint}'"
            )
