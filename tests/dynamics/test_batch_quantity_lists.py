"""A batch takes a list of quantities, each in its own unit, as ``simulate`` takes one: the same
results as the numbers in SI; a bare number string in the list is refused naming its place."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab as il


def test_a_list_of_quantities_is_its_numbers_in_si() -> None:
    rod = il.Rod.paper()
    given = il.simulate_batch(rod, angle=["20 deg", "45 deg"], vy=["-1.41 m/s", -2.0], mu=0.2)
    plain = il.simulate_batch(rod, angle=np.radians([20.0, 45.0]), vy=[-1.41, -2.0], mu=0.2)
    np.testing.assert_array_equal(given.e, plain.e)


def test_a_bare_number_string_is_refused_by_its_place() -> None:
    with pytest.raises(ValueError, match=r"angle\[1\]: the string '45' has no unit"):
        il.simulate_batch(il.Rod.paper(), angle=["20 deg", "45"], vy=-1.41, mu=0.2)
