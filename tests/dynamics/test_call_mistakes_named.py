"""Likely mistakes at the public calls are named: a misspelt ``velocity`` or ``speed`` with its
nearest keyword, as every other keyword is (it was answered "give the velocity of the centre of
mass"), and a field's name given to ``to_pint``, whose argument is a pint registry."""

from __future__ import annotations

import pytest

import impactlab as il


@pytest.mark.parametrize(
    ("given", "nearest"),
    [({"velocty": (0.0, -1.4)}, "velocity"), ({"speeed": 1.4, "incidence": 0.2}, "speed")],
)
def test_a_misspelt_velocity_keyword_is_named(given: dict, nearest: str) -> None:
    (wrong,) = [k for k in given if k != "incidence"]
    with pytest.raises(
        TypeError, match=rf"^simulate\(\) got unexpected keyword argument\(s\) {wrong} \(did you "
        rf"mean '{nearest}'\?\)"
    ):  # fmt: skip
        il.simulate(il.Rod.paper(), angle=0.3, **given)


def test_the_batch_names_still_get_their_own_words() -> None:
    with pytest.raises(ValueError, match=r"^simulate takes the velocity as one pair"):
        il.simulate(il.Rod.paper(), angle=0.3, vx=0.0, vy=-1.4)


def test_to_pint_named_a_field_says_what_it_takes() -> None:
    r = il.simulate(il.Rod.paper(), angle=0.35, velocity=(0.0, -1.41), mu=0.2, history=False)
    b = il.simulate_batch(il.Rod.paper(), angle=0.35, vy=[-1.41], mu=0.2)
    for result in (r, b):
        with pytest.raises(TypeError, match=r"^registry must be a pint UnitRegistry .* the string "
                           r"'delta_p'; to_pint\(\) returns every field by name"):  # fmt: skip
            result.to_pint("delta_p")
        assert result.to_pint()["delta_p"].units == "meter"
