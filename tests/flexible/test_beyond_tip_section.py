"""BEYOND_TIP of the flexible drop reads the rim at the angle of the end's section: the rod's
angle plus the section's elastic rotation, with which the tip's hemisphere turns
(docs/flexible.md, "Flags"); and its advice fits a rod that falls onto the flat."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.flags import ResultFlag, messages

ROD = il.FlexibleRod.paper()


@pytest.mark.parametrize(
    ("deg", "vy", "beyond"),
    [
        # the end section turns 0.2-0.5 deg beyond the rod during the contacts: the flat
        # passes its rim by 0.5 um (5.8 deg) and 4.6 um (8.3 deg) though not the rim at the
        # rod's angle
        (5.8, -1.41, True),
        (8.3, -3.0, True),
        (20.0, -1.41, False),  # 40 um against a rim about 500 um deep
    ],
)
def test_the_rim_is_read_at_the_end_sections_angle(deg: float, vy: float, beyond: bool) -> None:
    r = il.simulate_drop(ROD, angle=math.radians(deg), velocity=(0.0, vy), mu=0.2, history=False)
    assert (ResultFlag.BEYOND_TIP in r.flags) == beyond
    assert r.ok == (not beyond)
    b = il.simulate_drops(ROD, angle=math.radians(deg), vy=[vy], mu=0.2)
    assert int(b.flags[0]) == int(r.flags)


def test_a_rod_falling_onto_the_flat_is_not_told_to_slow_down() -> None:
    """At 5 mm/s the rod tips over onto the flat (gravity-dominated): lowering the impact
    velocity cannot keep the flat off the rim, and the warning says so."""
    r = il.simulate_drop(ROD, angle=math.radians(20), velocity=(0.0, -0.005), mu=0.2,
                         history=False)  # fmt: skip
    assert ResultFlag.GRAVITY_DOMINATED in r.flags and ResultFlag.BEYOND_TIP in r.flags
    (text,) = [w for w in r.warnings if w.startswith("beyond the tip")]
    assert "lower the impact velocity" not in text
    assert "falls over onto the flat" in text and "not meaningful" in text
    (alone,) = messages(ResultFlag.BEYOND_TIP)
    assert alone.endswith("(raise the angle or lower the impact velocity)")
