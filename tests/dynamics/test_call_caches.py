"""What is kept between calls gives the answer that working it out again gives: text
quantities, a batch's body and flat records, a law's range line."""

from __future__ import annotations

import dataclasses
import json
import math

import numpy as np
import pytest

import impactlab as il
from impactlab.contact import range_note as rn
from impactlab.dynamics import models
from impactlab.dynamics.export import batch_setup
from impactlab.units import magnitude


def test_text_quantity_read_again_is_the_same_number() -> None:
    first = magnitude("angle", "20 deg", "rad")
    assert first == magnitude("angle", "20 deg", "rad") == math.radians(20.0)
    assert magnitude("length", "1 m", "mm") == 1000.0  # the unit is part of what is kept
    assert magnitude("length", "1 m", "m") == 1.0


@pytest.mark.parametrize("name", ["angle", "spin_axis"])
def test_refused_text_is_refused_each_time_with_its_own_name(name: str) -> None:
    for _ in range(2):
        with pytest.raises(ValueError, match=rf"^{name}: the string '20' has no unit"):
            magnitude(name, "20", "rad")


def test_batch_records_follow_the_object_not_its_value() -> None:
    flat = il.get_material("aisi-1010")
    noted = dataclasses.replace(flat, note="read from a test")
    assert noted == flat  # a note is not compared, but it is recorded
    rod = il.Rod.paper()
    one = batch_setup(rod, flat, friction="coulomb", gravity=True, rtol=None, constant_angle=False)
    two = batch_setup(rod, noted, friction="coulomb", gravity=True, rtol=None, constant_angle=False)
    assert json.loads(two["flat_record"])["note"] == "read from a test"
    assert json.loads(one["flat_record"])["note"] != "read from a test"
    assert one["body"] == str(rod) and one["body_record"] == two["body_record"]


@pytest.mark.parametrize("law", il.law_names())
@pytest.mark.parametrize("flat", ["aisi-1010", "al-6061-t6", "copper-ofhc"])
def test_range_line_kept_equals_the_line_worked_out(law: str, flat: str) -> None:
    model = models.contact_model(il.Rod.paper(), il.get_material(flat), law)
    p = np.asarray(model.params)
    expected = rn._note(model.law_id, p)
    assert rn.range_note(model.law_id, p) == expected
    assert rn.range_note(model.law_id, p) == expected  # the kept line
