"""A drop's history and ``to_dict`` read as an impact's where the names carry over: the tip's
``penetration`` (it suggested the other end's ``penetration_1``), and the keys before 0.3
through ``get`` as through ``d[key]`` (``get`` gave None without a word)."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab as il


@pytest.fixture(scope="module")
def drop() -> il.DropResult:
    return il.simulate(il.FlexibleRod.paper(), law="ghaednia", friction="coulomb", mu=0.2,
                       angle="20 deg", velocity=(0, -1.41))  # fmt: skip


def test_penetration_is_the_tips(drop: il.DropResult) -> None:
    h = drop.history
    assert h is not None
    assert np.array_equal(h.penetration, h.penetration_0)
    assert h.penetration.max() > 0.0


def test_old_keys_read_through_get_and_in(drop: il.DropResult) -> None:
    d = drop.to_dict()
    with pytest.warns(DeprecationWarning, match="'delta_p' is renamed 'dent_depth'"):
        assert d.get("delta_p") == d["dent_depth"]
    with pytest.warns(DeprecationWarning, match="'delta_p' is renamed"):
        assert d["delta_p"] == d["dent_depth"]
    assert d.get("no such key", 5) == 5
    assert "delta_p" not in d and "delta_p" not in list(d)  # not among its keys
