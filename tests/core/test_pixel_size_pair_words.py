"""A pixel size with a unit on one side only ("12, 12 um") is refused, suggesting the two
readings: one size with a decimal point, or x then y each with the unit that was left off."""

from __future__ import annotations

import pytest

from impactlab.experiment.profilometry.heightmap import pixel_pair


@pytest.mark.parametrize(
    ("text", "one", "pair"),
    [("12, 12 um", "12.12 um", "12 um, 12 um"), ("12,5 um", "12.5 um", "12 um, 5 um")],
)
def test_a_unit_left_off_suggests_x_then_y_with_it(text: str, one: str, pair: str) -> None:
    with pytest.raises(ValueError, match="is ambiguous") as err:
        pixel_pair(text, "--pixel-size")
    message = str(err.value)
    assert f"write '{one}' (a decimal point) for one size or '{one}, {one}' for x" in message
    assert f"or, a unit left off, '{pair}' for x then y" in message
