"""Brake's law refused for a material without a Brinell hardness names the way to give it in
each context: the material's ``brinell_hardness`` (a sweep study's ``flat_brinell_hardness`` or
``body_brinell_hardness``, the side that lacks it) or the combined ``hardness`` law parameter."""

from __future__ import annotations

import math

import pytest

from impactlab.contact import get_law
from impactlab.materials import AISI_201, ContactPair, get_material
from impactlab.sweep.inputs import MATERIAL_OVERRIDES
from impactlab.sweep.material_inputs import CUSTOM
from impactlab.sweep.models import law_problem

NO_HB = "E=69GPa, nu=0.33, Sy=276MPa, rho=2700kg/m^3, name=plain"


def test_the_message_names_the_study_key_of_the_side_that_lacks_it() -> None:
    flat = get_material(NO_HB)
    with pytest.raises(ValueError, match="Brinell hardness of both") as caught:
        get_law("brake").build(ContactPair(AISI_201, flat), 8.8e-3)
    text = str(caught.value)
    assert text == (
        "hardness: Brake's law needs the Brinell hardness of both materials, and 'plain' has "
        "none; give it a brinell_hardness in kgf/mm^2 (HB=...; in a sweep study: "
        "flat_brinell_hardness), or the combined value as a law parameter, "
        "law_params={'hardness': ...} in kgf/mm^2 (a [law_params] table in a --config file on "
        "the command line, or in a study whose only law is brake)"
    )
    assert "\n" not in text
    with pytest.raises(ValueError, match=r"in a sweep study: body_brinell_hardness and "
                                         r"flat_brinell_hardness\)"):  # fmt: skip
        get_law("brake").build(ContactPair(flat, flat), 8.8e-3)


def test_two_materials_without_one_are_named_in_the_plural() -> None:
    body = get_material(NO_HB.replace("name=plain", "name=other"))
    flat = get_material(NO_HB)
    with pytest.raises(ValueError, match="Brinell hardness of both") as caught:
        get_law("brake").build(ContactPair(body, flat), 8.8e-3)
    assert (
        "and 'other' and 'plain' have none; give them a brinell_hardness in kgf/mm^2 (HB=...; "
        "in a sweep study: body_brinell_hardness and flat_brinell_hardness)" in str(caught.value)
    )
    with pytest.raises(ValueError, match="Brinell") as same:  # one material, both sides: once
        get_law("brake").build(ContactPair(flat, flat), 8.8e-3)
    assert "and 'plain' has none; give it a brinell_hardness" in str(same.value)


def test_a_study_case_gets_the_same_words() -> None:
    """What ``sweep info`` shows for the first refused case (status 103)."""
    cat = {"law": "brake", "body": "rod", "body_material": "aisi-201",
           "flat_material": CUSTOM}  # fmt: skip
    row = {n: math.nan for side in MATERIAL_OVERRIDES.values() for n in side}
    row.update(tip_radius=8.8e-3, flat_E=69e9, flat_nu=0.33, flat_yield_strength=276e6,
               flat_density=2700.0)  # fmt: skip
    why = law_problem(cat, row, {})
    assert (
        "has none; give it a brinell_hardness in kgf/mm^2 (HB=...; in a sweep study: "
        "flat_brinell_hardness)" in why
    )
