"""With a rate law, an error of the law's name or parameters is the plain error of the law (the
one without a rate, with the nearest name), not a rate problem: before, it read "rate
'johnson-cook': with the flat's yield strength and hardness raised by the rate factor k = 1,
the 'kogut_komvopoulos' law rejects the pair: unknown contact law ..."."""

from __future__ import annotations

import math
from typing import Any

import pytest

import impactlab as il

CASE: dict[str, Any] = {"mu": 0.2, "angle": math.radians(20), "velocity": (0.0, -1.41)}


@pytest.mark.parametrize(
    ("law", "params", "says"),
    [
        ("kogut_komvopoulos", None, "unknown contact law"),
        ("ghaednia", {"publishd_switch": 1}, "unknown parameter"),
    ],
)
def test_a_law_error_with_a_rate_is_the_plain_error(law: str, params: Any, says: str) -> None:
    rod = il.FlexibleRod.paper()
    with pytest.raises(ValueError, match=says) as plain:
        il.simulate_drop(rod, law=law, law_params=params, **CASE)
    with pytest.raises(ValueError, match=says) as rated:
        il.simulate_drop(rod, law=law, law_params=params, rate="johnson-cook", **CASE)
    assert str(rated.value) == str(plain.value)
    assert "rate factor" not in str(rated.value)


def test_the_nearest_name_is_offered() -> None:
    with pytest.raises(ValueError, match=r"^unknown contact law 'kogut_komvopoulos' \(did you mean "
                       r"'kogut-komvopoulos'\?\)"):  # fmt: skip
        il.simulate_drop(il.FlexibleRod.paper(), law="kogut_komvopoulos", rate="johnson-cook",
                         **CASE)  # fmt: skip
