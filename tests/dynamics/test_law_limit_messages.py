"""Why an impact's interference ran to the law's limit, said in its error. Painleve's paradox
under the paper's impulse_ratio friction (F_t = mu F_n throughout): once mu reaches
(k^2 + a^2) / (a b), the friction force's moment pushes the slipping contact point into the
flat faster than the normal force pushes it out; the error names it and gives the bound, the
rigid-body closed form. The tabulated law ends where its curves end, and says so."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.bodies.geometry import lever_arms
from impactlab.bodies.impulse import impulse_response, jam_ratio
from impactlab.flags import ResultFlag

ROD = il.Rod.paper()
ANGLE = math.radians(45)


def _jam(angle: float) -> float:
    a, b = lever_arms(ROD.half_length, ROD.tip_radius, angle)
    return jam_ratio(float(a), float(b), ROD.inertia / ROD.mass)


def test_jam_ratio_is_where_the_normal_response_changes_sign() -> None:
    a, b = (float(x) for x in lever_arms(ROD.half_length, ROD.tip_radius, ANGLE))
    k2 = ROD.inertia / ROD.mass
    jam = jam_ratio(a, b, k2)
    assert impulse_response(a, b, k2, jam)[1] == pytest.approx(0.0, abs=1e-15)
    assert (
        impulse_response(a, b, k2, 0.99 * jam)[1] > 0.0 > impulse_response(a, b, k2, 1.01 * jam)[1]
    )
    assert jam_ratio(0.0, b, k2) == math.inf  # a vertical rod never jams
    assert _jam(ANGLE) == pytest.approx(1.54, abs=0.005) and _jam(math.radians(20)) > 3.0


@pytest.mark.parametrize("history", [False, True])  # the fast path and the full path
def test_a_jammed_impulse_ratio_names_paradox_and_bound(history: bool) -> None:
    jam = _jam(ANGLE)
    with pytest.raises(ValueError, match="Painleve's paradox") as info:
        il.simulate(ROD, friction="impulse_ratio", mu=1.05 * jam, angle=ANGLE,
                    velocity=(0.0, -1.41), history=history)  # fmt: skip
    text = str(info.value)
    assert f"{jam:.3g}" in text and "lower mu below" in text and "coulomb" in text
    assert "lower the impact velocity" not in text


def test_below_the_bound_or_with_stick_there_is_no_jam() -> None:
    jam = _jam(ANGLE)
    r = il.simulate(ROD, friction="impulse_ratio", mu=0.9 * jam, angle=ANGLE,
                    velocity=(0.0, -1.41))  # fmt: skip
    assert r.e > 0.0  # it separates (its energy gain is flagged as for any such impact)
    for friction in ("coulomb", "mindlin"):  # the contact point sticks: no jam
        s = il.simulate(ROD, friction=friction, mu=2.0 * jam, angle=ANGLE, velocity=(0.0, -1.41))
        assert not s.flags & ResultFlag.ENERGY_GAIN


def test_a_law_limit_without_friction_keeps_its_message() -> None:
    with (
        pytest.raises(ValueError, match="lower the impact velocity"),
        pytest.warns(il.ImplausibleInputWarning, match="with mu = 0 is frictionless"),
    ):
        il.simulate(ROD, friction="impulse_ratio", mu=0.0, angle=ANGLE, velocity=(0.0, -60.0))


def test_the_tabulated_law_says_where_its_curves_end() -> None:
    with pytest.raises(ValueError, match=r"where the tabulated law's curves end \(1000 delta_c"):
        il.simulate(ROD, law="tabulated", angle=math.radians(70), velocity=(0.0, -40.0), mu=0.2)
