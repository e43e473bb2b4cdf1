"""Yield onset of every law against hand calculations, and the elastic branch below it."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import get_law, law_names
from impactlab.contact.base import ContactModel
from impactlab.materials import AISI_201, AISI_1010, ContactPair

E_STAR = 200e9 / (2.0 * (1.0 - 0.3**2))  # both steels E = 200 GPa, nu = 0.3
S_Y = 305e6  # the flat's yield strength
NU = 0.3
R = 8.8e-3


def hertz(delta: float) -> float:
    return 4.0 / 3.0 * E_STAR * math.sqrt(R) * delta**1.5


def test_reduced_modulus_of_the_paper_pair(paper_models: dict[str, ContactModel]) -> None:
    assert paper_models["hertz"].E_star == pytest.approx(109.89010989e9, rel=1e-9)


@pytest.mark.parametrize("name", ["ghaednia", "jackson-green"])
def test_jackson_family_critical_values_by_hand(
    name: str, paper_models: dict[str, ContactModel]
) -> None:
    # Eq. 15: C = 1.295 exp(0.736 * 0.3) = 1.61496; delta_c = (pi C S_y / (2 E*))^2 R
    C = 1.295 * math.exp(0.736 * 0.3)
    assert C == pytest.approx(1.61496, rel=1e-5)
    dc = (math.pi * C * S_Y / (2.0 * E_STAR)) ** 2 * R
    assert dc == pytest.approx(0.43624e-6, rel=1e-4)  # 0.436 um
    # Eq. 17: F_c = 4/3 (R/E*)^2 (pi C S_y / 2)^3 = 3.960 N, equal to Hertz at delta_c
    fc = 4.0 / 3.0 * (R / E_STAR) ** 2 * (math.pi * C * S_Y / 2.0) ** 3
    assert fc == pytest.approx(3.9603, rel=1e-4)
    assert fc == pytest.approx(hertz(dc), rel=1e-12)
    dy, fy = paper_models[name].yield_onset
    assert dy == pytest.approx(dc, rel=1e-12)
    assert fy == pytest.approx(fc, rel=1e-12)


def test_kogut_komvopoulos_yield_by_hand(paper_models: dict[str, ContactModel]) -> None:
    # delta/r' = 1.78 S_y/E*, r' = sqrt(delta (2R - delta)) -> delta_y = 2R t^2 / (1 + t^2)
    t = 1.78 * S_Y / E_STAR
    dy = 2.0 * R * t * t / (1.0 + t * t)
    assert dy == pytest.approx(0.42956e-6, rel=1e-4)
    rp = math.sqrt(dy * (2.0 * R - dy))
    assert dy / rp == pytest.approx(t, rel=1e-12)
    fy = 2.0 * math.sqrt(2.0) / 3.0 * E_STAR * dy * rp  # Eq. 20 with 2 sqrt2/(3 pi)
    got_dy, got_fy = paper_models["kogut-komvopoulos"].yield_onset
    assert got_dy == pytest.approx(dy, rel=1e-12)
    assert got_fy == pytest.approx(fy, rel=1e-12)
    assert got_fy == pytest.approx(3.8696, rel=1e-4)
    # the Hertz peak pressure there is 1.60 S_y: p0 = 2 E* sqrt(delta/R) / pi
    assert 2.0 * E_STAR * math.sqrt(dy / R) / math.pi / S_Y == pytest.approx(1.6023, rel=1e-3)


def test_brake_yield_by_hand(paper_models: dict[str, ContactModel]) -> None:
    # F(0.3) = [max_s {-(1.3)(1 - s atan(1/s)) + 1.5/(1 + s^2)}]^2; brute-force maximum:
    s = np.linspace(1e-4, 3.0, 300001)
    g = -(1.3) * (1.0 - s * np.arctan(1.0 / s)) + 1.5 / (1.0 + s * s)
    fnu = float(g.max()) ** 2
    assert fnu == pytest.approx(0.38445, rel=1e-4)
    assert float(s[np.argmax(g)]) == pytest.approx(0.481, abs=2e-3)
    dy = R * (math.pi * S_Y / (2.0 * E_STAR)) ** 2 / fnu
    assert dy == pytest.approx(0.43508e-6, rel=1e-4)
    got_dy, got_fy = paper_models["brake"].yield_onset
    assert got_dy == pytest.approx(dy, rel=1e-8)
    assert got_fy == pytest.approx(hertz(dy), rel=1e-8)


def test_thornton_yield_by_hand(paper_models: dict[str, ContactModel]) -> None:
    # default p_y = C(nu) S_y = 492.6 MPa; delta_y = R (pi p_y / (2 E*))^2
    py = 1.295 * math.exp(0.736 * 0.3) * S_Y
    assert py == pytest.approx(492.56e6, rel=1e-4)
    dy = R * (math.pi * py / (2.0 * E_STAR)) ** 2
    got_dy, got_fy = paper_models["thornton"].yield_onset
    assert got_dy == pytest.approx(dy, rel=1e-12)
    assert got_fy == pytest.approx(hertz(dy), rel=1e-12)
    # coincides with Jackson-Green's delta_c by construction of the default
    assert got_dy == pytest.approx(paper_models["jackson-green"].yield_onset[0], rel=1e-12)


def test_hertz_has_no_yield(paper_models: dict[str, ContactModel]) -> None:
    assert paper_models["hertz"].yield_onset == (math.inf, math.inf)
    assert paper_models["hertz"].switch_interference == math.inf


@pytest.mark.parametrize("name", law_names())
def test_elastic_branch_is_hertz(name: str, paper_models: dict[str, ContactModel]) -> None:
    model = paper_models[name]
    top = min(model.switch_interference, model.yield_onset[0], 1e-3)
    d = np.geomspace(1e-6 * top, top * (1.0 - 1e-9), 200)
    f = model.force(d)
    h = 4.0 / 3.0 * E_STAR * math.sqrt(R) * d**1.5
    # Kogut-Komvopoulos' elastic branch is Hertz * sqrt(1 - delta/(2R)) (truncated radius)
    tol = 1e-12 if name != "kogut-komvopoulos" else 1e-4
    np.testing.assert_allclose(f, h, rtol=tol)


@pytest.mark.parametrize("name", ["ghaednia", "jackson-green", "kogut-komvopoulos"])
def test_default_switch_is_a_crossing(name: str, paper_models: dict[str, ContactModel]) -> None:
    """The default switch sits where the elastic-plastic formula meets the elastic curve."""
    model = paper_models[name]
    dsw = model.switch_interference
    below = float(model.force(dsw * (1.0 - 1e-10)))
    above = float(model.force(dsw * (1.0 + 1e-10)))
    assert above == pytest.approx(below, rel=1e-8)
    # and the published switch (the same law built with published_switch=1) jumps there
    pub = get_law(name).build(_pair(), R, published_switch=1)
    d = pub.switch_interference
    jump = float(pub.force(d)) / float(pub.force(d * (1.0 - 1e-9))) - 1.0
    assert abs(jump) > 4e-3


def _pair() -> ContactPair:
    return ContactPair(AISI_201, AISI_1010)
