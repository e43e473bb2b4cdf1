"""Implausible magnitudes of a drop's inputs, a unit left out: a bare number is in the input's
unit (SI; a Brinell hardness in kgf/mm^2), so a yield strength of ``300`` is 300 Pa, a tip radius
of ``4`` is 4 m. Such a value is refused where it is read (a measurements file's column, a
model's ``fixed``), naming it, instead of failing later in every case of the calibration."""

from __future__ import annotations

import math

from impactlab.sweep.magnitudes import MATERIAL_MAGNITUDES, magnitude_error

__all__ = ["PLAUSIBLE_INPUTS", "check_magnitude"]

#: Input -> (lowest, highest plausible value in the input's unit, the unit to suggest): the
#: material values of a study (``sweep.magnitudes.MATERIAL_MAGNITUDES``: a modulus or stress
#: below 10 kPa, a density below 5 kg/m^3, a Brinell hardness above 10^4 kgf/mm^2), a rod
#: longer than 10 m, a tip or a sphere over 1 m in radius, a body over 100 kg (mm or g read as
#: m or kg), a velocity above 100 m/s (a drop from 500 m: cm/s or mm/s read as m/s) and a spin
#: above 1000 rad/s (deg/s or rpm read as rad/s).
PLAUSIBLE_INPUTS: dict[str, tuple[float, float, str]] = {
    **MATERIAL_MAGNITUDES,
    "length": (0.0, 10.0, "mm"),
    "tip_radius": (0.0, 1.0, "mm"),
    "radius": (0.0, 1.0, "mm"),
    "mass": (0.0, 100.0, "g"),
    "vx": (-100.0, 100.0, "cm/s"),
    "vy": (-100.0, 100.0, "cm/s"),
    "spin": (-1000.0, 1000.0, "deg/s"),
}


def check_magnitude(name: str, x: float, unit: str, where: str, like: str | None = None) -> None:
    """ValueError naming ``where`` and ``name`` when ``x`` (in ``unit``, the input's) lies
    outside what a drop's input can be (``PLAUSIBLE_INPUTS`` of ``name``, or of the input
    ``like``: a law's hardness is a Brinell hardness), with the unit to give."""
    rule = PLAUSIBLE_INPUTS.get(like or name)
    if rule is None or not math.isfinite(x):
        return
    error = magnitude_error(name, x, unit, where, rule)
    if error is not None:
        raise error
