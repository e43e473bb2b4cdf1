"""The materials of a study: a library name, or a material defined whole by its per-property
inputs (``flat_E``, ``flat_nu``, ...), never a library entry partly changed.

Rule (the same as every other input of impactlab, ``impactlab.materials.inputs``): a side
("body" or "flat") whose study sets any of its property inputs must set E, nu and the yield
strength (and, for the body, the density) in [fixed], [grid] or [sample]; that side's material is
then :data:`CUSTOM` (its label in the store, the CSV and every report: the values are the
per-case columns). The Brinell hardness and the Meyer index are taken only from the study
(unset: no hardness, Brake's law refuses the case; Meyer index 2.2). Naming a library material
as well (``flat_material = "aisi-1010"`` with ``flat_E``) is refused: it would label the cases
with a material they do not have.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Iterable, Mapping
from typing import Any

from impactlab._validation import ImplausibleInputWarning
from impactlab.materials import Material, get_material
from impactlab.materials.core import hardness_below_yield
from impactlab.sweep.inputs import MATERIAL_OVERRIDES

#: The category value of a material defined by its property inputs.
CUSTOM = "custom"
#: The property inputs a material defined by values needs, by side.
REQUIRED_FIELDS: dict[str, tuple[str, ...]] = {
    "body": ("E", "nu", "yield_strength", "density"),
    "flat": ("E", "nu", "yield_strength"),
}
#: Density of a custom flat [kg/m^3]: the flat is massive, its density plays no part.
FLAT_DENSITY = 7850.0


def check_material_inputs(
    fixed: Mapping[str, Any], varied: Iterable[str], categories: Mapping[str, Iterable[Any]]
) -> dict[str, Any]:
    """``fixed`` with ``<side>_material = "custom"`` added for every side defined by values.
    ``varied``: the inputs on the grid or in the sample; ``categories``: the values of the
    category inputs set in [fixed] or on the grid. ValueError for a partial definition, for
    a library name beside property inputs, or for a material fixed by values that is not one
    (S_y >= E, nu out of range: every case would fail; a hardness below the yield strength, a
    unit slip, as in a material by values)."""
    given = set(fixed) | set(varied)
    out = dict(fixed)
    for side, fields in MATERIAL_OVERRIDES.items():
        props = [name for name in fields if name in given]
        key = f"{side}_material"
        if not props and CUSTOM in [str(v) for v in categories.get(key, ())]:
            raise ValueError(
                f"{key} = {CUSTOM!r}: a {side} material by values needs "
                f"{', '.join(f'{side}_{f}' for f in REQUIRED_FIELDS[side])} (every case of it "
                f"would fail); set them in [fixed], [grid] or [sample], or name library materials"
            )
        if not props:
            continue
        missing = [f"{side}_{f}" for f in REQUIRED_FIELDS[side] if f"{side}_{f}" not in given]
        if missing:
            raise ValueError(
                f"{', '.join(props)} without {', '.join(missing)}: a {side} material by values "
                f"needs {', '.join(f'{side}_{f}' for f in REQUIRED_FIELDS[side])} (a library "
                f"material is never partly changed); set them too, or name a library material "
                f"with {side}_material and leave out the {side}_* properties"
            )
        names = [str(v) for v in categories.get(key, ()) if str(v) != CUSTOM]
        if names:
            raise ValueError(
                f"{key} = {names[0]!r} together with {', '.join(props)}: the cases would carry a "
                f"library name for a material they do not have; leave out {key} (the material "
                f"is then labelled {CUSTOM!r}) or the {side}_* properties"
            )
        out[key] = CUSTOM
        if not set(props) & set(varied):  # one material for every case: checked now, not
            values = {f: float(fixed[n]) for n, f in fields.items() if n in fixed}  # per case
            try:
                slip = hardness_below_yield(custom_material(side, values))
            except ValueError as exc:
                raise ValueError(f"[fixed] {side}_*: {exc}") from None
            if slip:  # given by the user, as in a material by values (get_material)
                raise ValueError(f"[fixed] {side}_*: {slip}")
    return out


def custom_material(side: str, values: Mapping[str, float]) -> Material:
    """The material of ``side`` defined by its property ``values`` (field -> SI value, NaN
    for not set); ValueError (a bad material) when a required one is missing."""
    given = {k: float(v) for k, v in values.items() if not math.isnan(v)}
    missing = [f for f in REQUIRED_FIELDS[side] if f not in given]
    if missing:
        raise ValueError(f"{side} material by values: {', '.join(missing)} not set")
    if side == "flat":
        given.setdefault("density", FLAT_DENSITY)
    with warnings.catch_warnings():  # the study (or the prior) was checked when it was made:
        warnings.simplefilter("ignore", ImplausibleInputWarning)  # not once per case
        return Material(f"{side} material by values", **given)  # type: ignore[arg-type]


def material_of(side: str, name: str, values: Mapping[str, float]) -> Material:
    """The material of a case: :func:`custom_material` for :data:`CUSTOM`, else the library
    material (or material text) ``name``, which takes no property values."""
    if name == CUSTOM:
        return custom_material(side, values)
    if any(not math.isnan(v) for v in values.values()):
        raise ValueError(f"{side} material {name!r} with property values: refused")
    return get_material(name, f"{side}_material")


def validate_material_names(names: Iterable[str], key: str) -> None:
    """ValueError unless every value of the category ``key`` is :data:`CUSTOM` or a material
    ``get_material`` reads (a library name, or properties as text)."""
    for name in names:
        if name != CUSTOM:
            get_material(name, key)
