"""Ghaednia et al. (paper Eqs. 15-19) and Jackson-Green 2005: jumps, area, residual depth."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.materials import ContactPair

R = 8.8e-3


def _hand_ep(dstar: float, k1: float, k2: float, m: float, h: float, C: float) -> float:
    """F/F_c of the family at delta*, with a given hardness ratio h = H_G/S_y."""
    return (
        math.exp(-k1 * dstar ** (5 / 12)) * dstar**1.5
        + 4.0 * h / C * (1.0 - math.exp(-k2 * dstar ** (5 / 9))) * dstar**m
    )


def test_published_jump_of_eq16_is_minus_ten_percent(paper_pair: ContactPair) -> None:
    model = get_law("ghaednia").build(paper_pair, R, published_switch=1)
    dc = model.details["delta_c"]
    C, B = model.details["C"], model.details["B"]
    # hand: r = sqrt(R delta (delta/(1.9 delta_c))^B) = sqrt(R 1.9 delta_c) at delta* = 1.9
    r = math.sqrt(R * 1.9 * dc)
    h = 2.84 - 0.92 * (1.0 - math.cos(math.pi * r / R))
    ratio = _hand_ep(1.9, 0.17, 1 / 78, 1.1, h, C) / 1.9**1.5
    assert ratio - 1.0 == pytest.approx(-0.1005, abs=5e-4)
    assert model.details["published_jump"] == pytest.approx(ratio - 1.0, rel=1e-9)
    assert B == pytest.approx(0.14 * math.exp(23 * 305e6 / paper_pair.E_star), rel=1e-12)
    f_before = float(model.force(1.9 * dc * (1 - 1e-9)))
    f_after = float(model.force(1.9 * dc))
    assert f_after / f_before - 1.0 == pytest.approx(ratio - 1.0, abs=1e-6)


def test_jackson_green_2005_jump_is_half_a_percent(paper_pair: ContactPair) -> None:
    jg = get_law("jackson-green").build(paper_pair, R, published_switch=1)
    assert jg.details["published_jump"] == pytest.approx(0.0047, abs=3e-4)
    # with Ghaednia's 0.17 in place of JG's 1/4 the jump would be +8.4 % (the physics notes'
    # "8 % the other way")
    alt = get_law("jackson-green").build(paper_pair, R, published_switch=1, elastic_decay=0.17)
    assert alt.details["published_jump"] == pytest.approx(0.084, abs=2e-3)


def test_jackson_green_hardness_formula(paper_pair: ContactPair) -> None:
    model = get_law("jackson-green").build(paper_pair, R)
    p = model.params
    dc, C = model.details["delta_c"], model.details["C"]
    for dstar in (3.0, 30.0, 300.0):
        d = dstar * dc
        a = math.sqrt(R * d * (d / (1.9 * dc)) ** model.details["B"])
        h = 2.84 * (1.0 - math.exp(-0.82 * (a / R) ** -0.7))
        want = model.details["F_c"] * _hand_ep(dstar, 0.25, 1 / 25, 1.0, h, C)
        assert k.jg_ep_force(p, d) == pytest.approx(want, rel=1e-12)


@pytest.mark.parametrize("name", ["ghaednia", "jackson-green"])
def test_contact_radius_fit_and_its_continuity(name: str, paper_pair: ContactPair) -> None:
    model = get_law(name).build(paper_pair, R)
    dc, B = model.details["delta_c"], model.details["B"]
    d = np.array([0.5, 1.9 * (1 - 1e-12), 1.9, 10.0, 300.0]) * dc
    a = model.contact_radius(d)
    want = np.where(d > 1.9 * dc, np.sqrt(R * d * (d / (1.9 * dc)) ** B), np.sqrt(R * d))
    np.testing.assert_allclose(a, want, rtol=1e-12)
    assert a[2] == pytest.approx(a[1], rel=1e-9)  # continuous at delta* = 1.9


@pytest.mark.parametrize("name", ["ghaednia", "jackson-green"])
def test_residual_depth_eq19(name: str, paper_models: dict[str, ContactModel]) -> None:
    model = paper_models[name]
    dc = model.details["delta_c"]
    assert model.unload(0.99 * dc).delta_r == 0.0
    for dstar in (1.0 + 1e-9, 2.0, 50.0, 400.0):
        dm = dstar * dc
        want = dm * 0.8 * (1.0 - ((dstar + 5.5) / 6.5) ** -2)
        assert model.unload(dm).delta_r == pytest.approx(want, rel=1e-12, abs=1e-20)
    # Eq. 18: R_r = (3 F_m / (4 E*))^2 / (delta_m - delta_r)^3
    br = model.unload(100 * dc)
    assert br.R_r == pytest.approx(
        (3 * br.F_m / (4 * model.E_star)) ** 2 / (br.delta_m - br.delta_r) ** 3, rel=1e-12
    )


def test_ghaednia_default_leaves_hertz_below_yield(paper_models: dict[str, ContactModel]) -> None:
    """Eq. 16 crosses Hertz once, near delta* = 0.1: the continuous default leaves Hertz there,
    and is then below Hertz by at most 10 % up to delta* = 1.9."""
    model = paper_models["ghaednia"]
    ratio = model.details["switch_ratio"]
    assert 0.05 < ratio < 0.15
    dc = model.details["delta_c"]
    d = np.geomspace(ratio * dc * 1.0001, 1.9 * dc, 200)
    rel = model.force(d) / (4 / 3 * model.E_star * math.sqrt(R) * d**1.5)
    assert np.all(rel <= 1.0) and rel.min() > 0.89


def test_published_and_default_agree_far_beyond_yield(paper_pair: ContactPair) -> None:
    for name in ("ghaednia", "jackson-green", "kogut-komvopoulos"):
        a = get_law(name).build(paper_pair, R)
        b = get_law(name).build(paper_pair, R, published_switch=1)
        d = np.array([5e-6, 50e-6, 200e-6])
        np.testing.assert_array_equal(a.force(d), b.force(d))
