"""A contact model's loading curve gives a float for a scalar interference, an array of the
input's shape for an array (numpy's convention)."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.contact import get_law, law_names
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)


@pytest.mark.parametrize("law", [n for n in law_names() if n != "tabulated"])
def test_a_scalar_interference_gives_a_float(law: str) -> None:
    model = get_law(law).build(PAIR, radius=8.8e-3)
    for value in (50e-6, "50 um", np.float64(50e-6)):
        f, a = model.force(value), model.contact_radius(value)
        assert isinstance(f, float) and isinstance(a, float)
        assert f > 0.0 and a > 0.0
    assert f == model.force([50e-6])[0]


@pytest.mark.parametrize("shape", [(1,), (3,), (2, 2)])
def test_an_array_keeps_its_shape(shape: tuple[int, ...]) -> None:
    model = get_law("ghaednia").build(PAIR, radius=8.8e-3)
    d = np.full(shape, 20e-6)
    assert model.force(d).shape == shape
    assert model.contact_radius(d).shape == shape
