"""Thornton (1997): closed-form restitution, yield velocity, and the law behind them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import get_law, quasi_static_rebound
from impactlab.contact.base import ContactModel
from impactlab.contact.thornton import (
    thornton_restitution,
    thornton_yield_interference,
    thornton_yield_velocity,
)
from impactlab.materials import ContactPair

R = 8.8e-3
MASS = 0.4607


def test_restitution_is_one_at_yield_and_decreasing() -> None:
    assert thornton_restitution(1.0) == pytest.approx(1.0, abs=1e-14)
    assert thornton_restitution(0.3) == 1.0
    r = np.geomspace(1.0, 1e4, 400)
    e = thornton_restitution(r)
    assert np.all(np.diff(e) < 0.0)
    assert np.all((e > 0.0) & (e <= 1.0))
    # high-speed asymptote e ~ (6 sqrt3 / 5)^(1/2) (1 / (2 sqrt(6/5)))^(1/4) (V/V_y)^(-1/4)
    c = math.sqrt(6 * math.sqrt(3) / 5) * (1 / (2 * math.sqrt(6 / 5))) ** 0.25
    assert float(e[-1]) == pytest.approx(c * 1e4**-0.25, rel=2e-3)


def test_closed_form_matches_the_quasi_static_law(paper_pair: ContactPair) -> None:
    model = get_law("thornton").build(paper_pair, R)
    vy = thornton_yield_velocity(model.E_star, R, MASS, model.details["p_y"])
    for v in (1.5 * vy, 10 * vy, 1.41, 3.45):
        res = quasi_static_rebound(model, MASS, v)
        assert res.restitution == pytest.approx(thornton_restitution(v / vy), rel=1e-8)


def test_yield_velocity_by_energy_and_sphere_formula() -> None:
    E, py, rho = 115e9, 1.0e9, 7800.0
    m = 4 / 3 * math.pi * R**3 * rho
    vy = thornton_yield_velocity(E, R, m, py)
    dy = thornton_yield_interference(E, R, py)
    fy = 4 / 3 * E * math.sqrt(R) * dy**1.5
    assert 0.5 * m * vy**2 == pytest.approx(0.4 * fy * dy, rel=1e-12)
    assert vy == pytest.approx(1.56 * math.sqrt(py**5 / (E**4 * rho)), rel=2e-3)


def test_loading_and_unloading_keep_the_contact_radius(
    paper_models: dict[str, ContactModel],
) -> None:
    model = paper_models["thornton"]
    dy, fy = model.yield_onset
    py = model.details["p_y"]
    for dm in (2 * dy, 50e-6, 200e-6):
        f = float(model.force(dm))
        assert f == pytest.approx(fy + math.pi * py * R * (dm - dy), rel=1e-12)
        br = model.unload(dm)
        a_m = math.sqrt(R * dm)
        assert br.R_r == pytest.approx(4 * model.E_star * a_m**3 / (3 * f), rel=1e-10)
        assert float(br.contact_radius(dm)) == pytest.approx(a_m, rel=1e-10)


def test_invalid_inputs() -> None:
    with pytest.raises(ValueError, match="v_ratio"):
        thornton_restitution(-1.0)
    with pytest.raises(ValueError, match="v_ratio"):
        thornton_restitution(float("nan"))
    with pytest.raises(ValueError, match="v_ratio"):
        thornton_restitution("fast")
    with pytest.raises(ValueError, match="mass"):
        thornton_yield_velocity(1e11, R, 0.0, 1e9)
    with pytest.raises(ValueError, match="p_y"):
        thornton_yield_velocity(1e11, R, 1.0, -1e9)
