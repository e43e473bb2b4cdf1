"""A batch's ``speed=`` as a list of pint Quantities (read as its other columns are), and the
words of a case that is not ok: the flags that make it so, then the advisory ones."""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import pint
import pytest

import impactlab as il
from impactlab.dynamics.batch_fields import flagged_messages
from impactlab.flags import ADVISORY_FLAGS, ResultFlag

ROD = il.Rod.paper()
U: Any = pint.UnitRegistry()  # a registry of the user's, not impactlab's


@pytest.mark.parametrize("run", [il.simulate_batch, il.simulate_drops])
def test_speed_as_a_list_of_quantities(run: Any) -> None:
    body = ROD if run is il.simulate_batch else il.FlexibleRod.paper()
    speed = [U.Quantity(1.4, "m/s"), U.Quantity(1000.0, "mm/s")]
    b = run(body, mu=0.2, angle=0.35, speed=speed, incidence=0.1)
    assert np.allclose(b.vx, [1.4 * math.sin(0.1), math.sin(0.1)])
    assert np.allclose(b.vy, [-1.4 * math.cos(0.1), -math.cos(0.1)])


def test_speed_list_elements_are_named() -> None:
    with pytest.raises(ValueError, match=r"^speed\[1\]: .*wrong dimension"):
        il.simulate_batch(ROD, angle=0.35, speed=[U.Quantity(1.4, "m/s"), U.Quantity(1, "s")],
                          incidence=0.1)  # fmt: skip
    with pytest.raises(ValueError, match=r"speed\[1\] = -1.0 m/s \(1 of 2 cases\)"):
        il.simulate_batch(ROD, angle=0.35, speed=[U.Quantity(1.4, "m/s"), -1.0], incidence=0.1)
    inc = [U.Quantity(10, "deg"), U.Quantity(0.5, "rad")]
    b = il.simulate_batch(ROD, angle=0.35, speed=1.4, incidence=inc)
    assert np.allclose(b.vx, 1.4 * np.sin([math.radians(10), 0.5]))


def test_advisory_flags_follow_the_reasons() -> None:
    b = il.simulate_batch(ROD, mu=0.13, angle=np.radians([10, 80]), vy=[-4.0, -0.01])
    flags = [int(f) for f in b.flags]
    assert not b.ok.any() and all(f & ADVISORY_FLAGS for f in flags)
    assert flags[0] == ResultFlag.BEYOND_TIP | ResultFlag.LAW_EXTRAPOLATED
    assert b.messages[0] == (
        f"computed, not ok (flags {flags[0]}): beyond the tip; advisory: law extrapolated"
    )
    assert b.messages[1].endswith("; advisory: law extrapolated")
    assert "law extrapolated" not in b.messages[1].split(";")[0]


def test_no_advisory_part_without_an_advisory_flag() -> None:
    gain, tip = int(ResultFlag.ENERGY_GAIN), int(ResultFlag.BEYOND_TIP)
    flags = np.array([gain | tip, gain | int(ADVISORY_FLAGS), int(ADVISORY_FLAGS), 0])
    ok = np.array([False, False, True, True])
    out = flagged_messages(["ok"] * 4, flags, ok)
    assert out == [
        f"computed, not ok (flags {gain | tip}): energy gain, beyond the tip",
        f"computed, not ok (flags {flags[1]}): energy gain; advisory: law extrapolated",
        "ok",
        "ok",
    ]
