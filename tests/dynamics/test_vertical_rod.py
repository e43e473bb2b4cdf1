"""A head-on impact with no initial slip has no tangential impulse, whatever the friction
model: a vertical rod (whose lever arm a = (L/2) cos(pi/2) is 6e-17 (L/2), not 0, in floating
point) as a sphere; the paper's impulse_ratio took the sign of that round-off and applied
mu F_n. The compiled engine, the solve_ivp reference and the drop agree."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.dynamics.reference import simulate_reference

ROD = il.Rod.paper()
HEAD_ON = {"mu": 0.3, "angle": math.pi / 2, "velocity": (0.0, -1.41)}


@pytest.mark.parametrize("friction", ["impulse_ratio", "coulomb", "mindlin", "partial_slip"])
def test_a_vertical_rod_gets_no_tangential_impulse(friction: str) -> None:
    r = il.simulate(ROD, friction=friction, **HEAD_ON)
    assert abs(r.tangential_impulse) < 1e-12 * r.normal_impulse
    assert abs(r.spin_out) < 1e-9 and r.ok


def test_impulse_ratio_without_a_tangential_force_is_frictionless() -> None:
    """No tangential force ever: the regime says so (a sphere head-on too), and the reference
    and the drop give the same."""
    r = il.simulate(ROD, friction="impulse_ratio", **HEAD_ON)
    ball = il.simulate(il.Sphere(radius=0.005), friction="impulse_ratio", mu=0.3,
                       velocity=(0.0, -1.41))  # fmt: skip
    assert r.regime == ball.regime == "frictionless" and ball.tangential_impulse == 0.0
    ref = simulate_reference(ROD, friction="impulse_ratio", rtol=1e-10, **HEAD_ON)
    assert ref["regime"] == "frictionless" and abs(ref["tangential_impulse"]) < 1e-12
    drop = il.simulate_drop(ROD, friction="impulse_ratio", **HEAD_ON)
    assert abs(drop.tangential_impulse) < 1e-12 * drop.normal_impulse


def test_a_rod_just_off_vertical_keeps_its_friction() -> None:
    """The round-off tolerance is 1e-12 of the lever arms: at 89.9 deg impulse_ratio acts."""
    r = il.simulate(ROD, friction="impulse_ratio", mu=0.3, angle=math.radians(89.9),
                    velocity=(0.0, -1.41))  # fmt: skip
    assert abs(r.tangential_impulse) > 0.1
