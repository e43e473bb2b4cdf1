"""Implausible magnitudes of a drop's inputs, a unit left out: a bare number is in the input's
unit (SI; a Brinell hardness in kgf/mm^2), so a yield strength of ``300`` is 300 Pa, a tip radius
of ``4`` is 4 m. Such a value is refused where it is read (a measurements file's column, a
model's ``fixed``), naming it, instead of failing later in every case of the calibration."""

from __future__ import annotations

import math

__all__ = ["PLAUSIBLE_INPUTS", "check_magnitude"]

_STRESS = (1e4, math.inf, "MPa")  # 10 kPa: below any solid a drop test strikes (materials)
_MODULUS = (1e4, math.inf, "GPa")

#: Input -> (lowest, highest plausible value in the input's unit, the unit to suggest): a
#: stress or a modulus below 10 kPa (MPa or GPa read as Pa), a Brinell hardness above 10^4
#: kgf/mm^2 (Pa read as kgf/mm^2; the hardest metals are below 10^3), a rod longer than 10 m, a
#: tip or a sphere over 1 m in radius, a body over 100 kg (mm or g read as m or kg), a density
#: below 5 kg/m^3 (g/cm^3 read as kg/m^3).
PLAUSIBLE_INPUTS: dict[str, tuple[float, float, str]] = {
    **{f"{side}_yield_strength": _STRESS for side in ("body", "flat")},
    **{f"{side}_E": _MODULUS for side in ("body", "flat")},
    **{f"{side}_brinell_hardness": (0.0, 1e4, "Pa") for side in ("body", "flat")},
    "length": (0.0, 10.0, "mm"),
    "tip_radius": (0.0, 1.0, "mm"),
    "radius": (0.0, 1.0, "mm"),
    "mass": (0.0, 100.0, "g"),
    "body_density": (5.0, math.inf, "g/cm^3"),
}


def check_magnitude(name: str, x: float, unit: str, where: str, like: str | None = None) -> None:
    """ValueError naming ``where`` and ``name`` when ``x`` (in ``unit``, the input's) lies
    outside what a drop's input can be (``PLAUSIBLE_INPUTS`` of ``name``, or of the input
    ``like``: a law's hardness is a Brinell hardness), with the unit to give."""
    rule = PLAUSIBLE_INPUTS.get(like or name)
    if rule is None or not math.isfinite(x):
        return
    low, high, hint = rule
    if low <= x <= high:
        return
    side = f"below {low:g}" if x < low else f"above {high:g}"
    raise ValueError(
        f"{where}: {name} = {x:g} {unit} is {side} {unit}: an implausible "
        f"magnitude (a number without its unit is in {unit}); give its unit, e.g. "
        f"'{x:g} {hint}'"
    )
