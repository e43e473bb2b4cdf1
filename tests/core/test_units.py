"""Quantities with units at the edge."""

from __future__ import annotations

import math

import pytest

from impactlab.units import angle_to_rad, to_si


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("8.8 mm", "m", 8.8e-3),
        ("1.41 m/s", "m/s", 1.41),
        ("-1410 mm/s", "m/s", -1.41),
        ("22 um", "m", 22e-6),
        ("200 GPa", "Pa", 200e9),
        ("0.25 ms", "s", 2.5e-4),
        (3.0, "mm", 3e-3),
        ("20", "degree", 0.3490658503988659),
        ("3", "mm", 3e-3),
    ],
)
def test_to_si(text: object, unit: str, expected: float) -> None:
    assert to_si(text, unit) == pytest.approx(expected, rel=1e-12)


def test_angles_default_to_degrees() -> None:
    assert angle_to_rad(20) == pytest.approx(math.radians(20))
    assert angle_to_rad("0.5 rad") == pytest.approx(0.5)


@pytest.mark.parametrize("bad", ["3 kg", "fast", "", "nan m"])
def test_bad_quantities_name_the_input(bad: str) -> None:
    with pytest.raises(ValueError, match="radius"):
        to_si(bad, "m", name="radius")
