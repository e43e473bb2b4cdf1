"""Which body yields first: the one whose first-yield pressure C(nu) S_y is the smaller
(C(nu) = 1.295 exp(0.736 nu), Jackson & Green 2005; the paper's Eq. 15), not the one with the
smaller S_y. A ball (S_y 310 MPa, nu 0.2) on a flat (S_y 300 MPa, nu 0.45) yields first
(C S_y 465 against 541 MPa): the laws take the ball's S_y and nu, and an impact past the ball's
first yield dents it (or is marked)."""

from __future__ import annotations

import dataclasses
import itertools
import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import impactlab as il
from impactlab.bodies import Sphere
from impactlab.contact import get_law
from impactlab.contact._common import jg_C, jg_critical
from impactlab.contact.indentation_data import yielding_body
from impactlab.contact.rate import rate_materials
from impactlab.contact.rate_factor import BODY_MARGIN, RateLimit
from impactlab.materials import (
    AISI_201,
    AISI_1010,
    PRESETS,
    ContactPair,
    Material,
    body_yields_first,
    first_yield_factor,
)
from impactlab.materials.inputs import from_values

BALL = from_values({"E": "200 GPa", "nu": 0.20, "Sy": "310 MPa", "rho": "7800 kg/m^3"}, "ball")
FLAT = from_values({"E": "200 GPa", "nu": 0.45, "Sy": "300 MPa", "rho": "7800 kg/m^3"}, "flat")
R = 5e-3


def test_the_ball_with_the_larger_sy_but_smaller_c_sy_yields_first() -> None:
    pair = ContactPair(BALL, FLAT)
    assert body_yields_first(BALL, FLAT) and not body_yields_first(FLAT, BALL)
    assert pair.weaker is BALL
    assert (pair.yield_strength, pair.nu) == (310e6, 0.2)
    assert yielding_body(pair) == "sphere"
    model = get_law("ghaednia").build(pair, R)
    dc = jg_critical(pair.E_star, R, 310e6, 0.2)[0]
    assert model.details["delta_c"] == dc
    assert dc == pytest.approx(0.2061e-6, rel=1e-3)  # the flat's values gave 0.2789 um
    assert model.details["C"] == pytest.approx(jg_C(0.2))


def test_the_defaults_of_brake_and_thornton_follow_the_body_that_yields_first() -> None:
    ball = dataclasses.replace(BALL, meyer_index=2.3, brinell_hardness=250.0)
    flat = dataclasses.replace(FLAT, meyer_index=2.1, brinell_hardness=240.0)
    pair = ContactPair(ball, flat)
    thornton = get_law("thornton").build(pair, R)
    assert thornton.details["p_y"] == pytest.approx(first_yield_factor(0.2) * 310e6)
    brake = get_law("brake").build(pair, R)
    assert brake.details["meyer_index"] == 2.3


def test_an_impact_past_the_balls_first_yield_dents_or_is_marked() -> None:
    r = il.simulate(
        Sphere(radius=R, material=BALL), FLAT, law="ghaednia", velocity=(0.0, -0.0075),
        gravity=False,
    )  # fmt: skip
    peak = 2.0 * ContactPair(BALL, FLAT).E_star * math.sqrt(r.delta_max / R) / math.pi
    assert peak > first_yield_factor(0.2) * 310e6  # past the ball's first yield (502 > 465 MPa)
    assert r.delta_p > 0.0 or int(r.flags) != 0
    assert r.delta_p > 0.0  # Ghaednia's law yields from 0.1 delta_c on


def test_the_tabulated_law_takes_no_flat_curves_for_a_ball_that_yields_first() -> None:
    """E*/S_y and nu of the ball match the paper's shipped case (a yielding flat): refused,
    naming the pressures, as the S_y alone would point the other way."""
    E = 360.3 * 310e6 * (2 - 0.29**2 - 0.45**2)  # E*/S_y = 360.3 with the ball's S_y
    pair = ContactPair(Material("ball", E, 0.29, 310e6), Material("flat", E, 0.45, 295e6))
    with pytest.raises(ValueError, match=r"^law 'tabulated': the sphere yields first") as info:
        get_law("tabulated").build(pair, R)
    assert (
        "(S_y 310 MPa for the sphere, 295 MPa for the flat; with nu 0.29 and 0.45, C(nu) S_y "
        "497 and 532 MPa), but the indentation curves for its E*/S_y = 360.3, nu = 0.29 "
        "('paper-aisi201-on-aisi1010') are for a yielding flat" in str(info.value)
    )


_nu = st.floats(-0.95, 0.49)
_sy = st.floats(1e6, 5e9)


@settings(max_examples=300, deadline=None)
@given(_nu, _sy, _nu, _sy)
def test_the_chosen_body_has_the_smaller_first_yield_pressure(
    nu_b: float, sy_b: float, nu_f: float, sy_f: float
) -> None:
    body = Material("b", 1e12, nu_b, sy_b)
    flat = Material("f", 1e12, nu_f, sy_f)
    pair = ContactPair(body, flat)
    chosen, other = (body, flat) if body_yields_first(body, flat) else (flat, body)
    assert pair.weaker is chosen
    assert yielding_body(pair) == ("sphere" if chosen is body else "flat")
    p_chosen = first_yield_factor(chosen.nu) * chosen.yield_strength
    p_other = first_yield_factor(other.nu) * other.yield_strength
    assert p_chosen <= p_other
    if nu_b == nu_f:  # equal C: the S_y decide as before, the flat on a tie
        assert (chosen is body) == (sy_b < sy_f)


def test_ties_keep_the_smaller_sy_and_then_the_flat() -> None:
    steel = Material("hard steel", 205e9, 0.29, 1379e6)
    assert yielding_body(ContactPair(steel, steel)) == "flat"
    twin = dataclasses.replace(steel, name="twin")
    assert ContactPair(steel, twin).weaker is twin


def test_library_pairs_keep_the_smaller_sy_choice() -> None:
    """No library pair has the two orderings swapped: every law's parameters are unchanged."""
    for body, flat in itertools.product(PRESETS.values(), repeat=2):
        old = body if body.yield_strength < flat.yield_strength else flat
        assert ContactPair(body, flat).weaker is old, (body.name, flat.name)


def test_a_rate_raised_flat_still_yields_first() -> None:
    """The rate factor raises the body's S_y where the raised flat would make the body yield
    first, by C(nu) S_y; at k = 1 the pair is the one without a rate law."""
    flat = dataclasses.replace(FLAT, E=400e9, yield_strength=250e6)  # the flat yields first
    assert not body_yields_first(BALL, flat)
    assert rate_materials(BALL, flat, 1.0)[0] == BALL
    assert rate_materials(BALL, flat, 1.02)[0] == BALL  # the flat still yields first
    for k in (1.02, 1.5, 3.0):
        body_k, flat_k = rate_materials(BALL, flat, k)
        assert not body_yields_first(body_k, flat_k)
        if body_k != BALL:  # raised where the order turned: with the margin
            assert first_yield_factor(0.2) * body_k.yield_strength >= (
                BODY_MARGIN * first_yield_factor(0.45) * flat_k.yield_strength * (1 - 1e-12)
            )
    assert rate_materials(BALL, flat, 1.5)[0] != BALL


def test_a_body_that_yields_first_is_not_made_hard_by_the_flat_s_rate() -> None:
    """A ball that yields before the flat statically (C(nu) S_y) keeps its S_y under any rate
    factor: it was raised to 1.5 times the flat's (a copper rod on steel: 10.8 times its own),
    and the result turned from the rod's flattening into a dent in the flat."""
    flat = dataclasses.replace(FLAT, E=400e9)
    assert body_yields_first(BALL, flat)
    for k in (1.0, 1.13, 3.0):
        body_k, flat_k = rate_materials(BALL, flat, k)
        assert body_k == BALL and flat_k.yield_strength == k * flat.yield_strength
    # equal nu: the former 1.5 times the flat's S_y, bit for bit
    body_k, flat_k = rate_materials(AISI_201, AISI_1010, 3.0)
    assert body_k.yield_strength == BODY_MARGIN * (3.0 * 305e6) / 760e6 * 760e6
    assert RateLimit.of(AISI_201, AISI_1010).k_max == min(
        AISI_1010.E / 305e6, AISI_201.E / (BODY_MARGIN * 305e6)
    )
