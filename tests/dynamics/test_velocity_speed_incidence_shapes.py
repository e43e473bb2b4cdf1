"""Arrays of ``speed`` and ``incidence`` that do not broadcast get one error naming both and
their shapes, in ``simulate_batch`` and ``simulate_drops``, as ``vx``/``vy`` do."""

from __future__ import annotations

import re

import pytest

import impactlab as il
from impactlab.dynamics.velocity_inputs import speed_incidence


@pytest.mark.parametrize("batch", [il.simulate_batch, il.simulate_drops])
def test_mismatched_speed_and_incidence_are_named(batch: object) -> None:
    text = "speed and incidence do not broadcast (speed: (3,), incidence: (2,))"
    with pytest.raises(ValueError, match=re.escape(text)):
        batch(il.Rod.paper(), angle=0.35, speed=[1, 2, 3], incidence=[0.1, 0.2])  # type: ignore[operator]


def test_a_scalar_or_equal_lengths_broadcast() -> None:
    vx, vy = speed_incidence([1.0, 2.0], 0.0)
    assert vy.tolist() == [-1.0, -2.0] and vx.tolist() == [0.0, 0.0]
    vx, vy = speed_incidence(2.0, [0.0, 0.0, 0.0])
    assert vy.tolist() == [-2.0, -2.0, -2.0]
