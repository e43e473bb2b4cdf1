"""A gravity given as text that is not a quantity names what gravity may be."""

import pytest

import impactlab as il


@pytest.mark.parametrize("gravity", ["yes", "on", "abc m/s^2"])
def test_a_gravity_that_is_not_a_quantity_says_what_is_allowed(gravity):
    with pytest.raises(ValueError, match=r"^gravity: cannot parse") as info:
        il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0, -1.41), gravity=gravity)
    text = str(info.value)
    assert text.startswith("gravity: cannot parse")
    assert "True (9.80665 m/s^2), False (none) or a value in m/s^2" in text


def test_a_gravity_with_units_is_still_read():
    a = il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0, -1.41), gravity="9.80665 m/s^2")
    b = il.simulate(il.Rod.paper(), angle="20 deg", velocity=(0, -1.41), gravity=True)
    assert a.e == b.e
