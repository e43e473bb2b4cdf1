"""The nearest-name hint ignores case as it ignores '-' against '_': ``law="HERTZ"`` is
told 'hertz' (formerly no hint at all)."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab._validation import did_you_mean


@pytest.mark.parametrize(
    ("given", "meant"),
    [
        ("HERTZ", "hertz"),
        ("Ghaednia", "ghaednia"),
        ("Kogut_Komvopoulos", "kogut-komvopoulos"),
        ("ghadnia", "ghaednia"),
    ],
)
def test_the_hint_ignores_case_and_separators(given: str, meant: str) -> None:
    known = ["hertz", "ghaednia", "kogut-komvopoulos"]
    assert did_you_mean(given, known) == f" (did you mean {meant!r}?)"
    assert did_you_mean("xyz", known) == ""


def test_a_drop_with_an_upper_case_law_names_the_law() -> None:
    with pytest.raises(ValueError, match=r"did you mean 'hertz'\?"):
        il.simulate_drop(il.FlexibleRod.paper(), law="HERTZ", mu=0.2, angle=math.radians(20),
                         velocity=(0, -1.41))  # fmt: skip
