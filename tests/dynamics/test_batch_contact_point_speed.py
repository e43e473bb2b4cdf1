"""The batches warn of an implausible speed as ``simulate`` does: the largest of the centre
of mass's and the contact point's speed (spin included, each case's lever arms), over the
cases that run only (inputs finite, the contact point approaching the flat)."""

from __future__ import annotations

import contextlib
import math
import warnings

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import impactlab as il
from impactlab import ImplausibleInputWarning
from impactlab.bodies.geometry import lever_arms
from impactlab.dynamics.simulate_many import _fastest

ROD = il.Rod.paper()


def _warned(run: object) -> list[str]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with contextlib.suppress(ValueError):  # simulate warns, then refuses (the law's limit)
            run()  # type: ignore[operator]
    return [str(w.message) for w in caught if issubclass(w.category, ImplausibleInputWarning)]


@pytest.mark.parametrize("batch", [il.simulate_batch, il.simulate_drops])
def test_a_fast_contact_point_warns_as_simulate_does(batch: object) -> None:
    one = _warned(lambda: il.simulate(ROD, angle=0.35, velocity=(0, -1.41), spin=700.0))
    assert one and "110.244 m/s" in one[0]
    many = _warned(lambda: batch(ROD, angle=0.35, vy=-1.41, spin=700.0))  # type: ignore[operator]
    assert len(many) == 1
    assert "the largest impact speed of the batch (110.244 m/s) exceeds 100 m/s" in many[0]


def test_a_case_that_does_not_approach_draws_no_speed_warning() -> None:
    """A batch warned of a 123 m/s impact whose only case was refused: its tip recedes."""
    assert _warned(lambda: il.simulate_batch(ROD, angle=0.3, vy=-1, spin=-800.0)) == []


def test_a_case_that_is_not_finite_draws_no_speed_warning() -> None:
    said = _warned(lambda: il.simulate_batch(ROD, angle=0.35, vy=[-np.inf, -1.0, np.nan]))
    assert said == []
    said = _warned(lambda: il.simulate_drops(ROD, angle=0.35, vy=[-1.0, -1.0], spin=[np.inf, 0]))
    assert said == []


@settings(deadline=None, max_examples=60)
@given(
    angle=st.floats(0.01, 0.5 * math.pi),
    vx=st.floats(-200.0, 200.0),
    vy=st.floats(-200.0, 0.0),
    spin=st.floats(-2000.0, 2000.0),
)
def test_the_batch_takes_the_speed_simulate_takes(
    angle: float, vx: float, vy: float, spin: float
) -> None:
    a, b = lever_arms(ROD.half_length, ROD.tip_radius, angle)
    expected = max(math.hypot(vx, vy), math.hypot(vx + spin * b, vy - spin * a))
    if not vy - spin * a < 0.0:  # refused, not approaching: said in its status, not warned of
        expected = 0.0
    cols = {k: np.array([v]) for k, v in (("angle", angle), ("vx", vx), ("vy", vy), ("spin", spin))}
    assert _fastest(cols, ROD) == pytest.approx(expected, rel=1e-12, abs=1e-12)
