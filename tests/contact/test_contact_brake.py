"""Brake (paper Eqs. 23-27): yield function, Eq. 26 closed form, transition, unloading."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy.optimize import brentq

from impactlab.contact import get_law
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.contact.brake import (
    brake_eq26_residual,
    brake_plastic_interference,
    brake_yield_function,
)
from impactlab.materials import G0, ContactPair, Material

R = 8.8e-3


@pytest.mark.parametrize("nu", np.linspace(0.2, 0.4, 11))
def test_yield_function_matches_jackson_green_c(nu: float) -> None:
    """With (1 + nu), delta_y(Brake) / delta_c(JG) = 1 / (C(nu)^2 F(nu)) is within 0.5 %."""
    fnu, _ = brake_yield_function(float(nu))
    C = 1.295 * math.exp(0.736 * nu)
    assert abs(1.0 / (C * C * fnu) - 1.0) < 5e-3


def test_printed_one_minus_nu_does_not_match() -> None:
    """The printed (1 - nu) would put yield far from Jackson-Green (the test can fail)."""
    nu = 0.3
    s = np.linspace(1e-4, 5.0, 200001)
    g = -(1 - nu) * (1 - s * np.arctan(1 / s)) + 1.5 / (1 + s * s)
    C = 1.295 * math.exp(0.736 * nu)
    assert abs(1.0 / (C * C * float(g.max()) ** 2) - 1.0) > 0.2


@pytest.mark.parametrize("n", [2.05, 2.2, 2.5, 2.8, 2.95])
@pytest.mark.parametrize("P0_over_E", [1e-3, 3.5e-3, 1e-2])
def test_eq26_closed_form_is_the_root_of_the_printed_equation(n: float, P0_over_E: float) -> None:
    E = 110e9
    P0 = P0_over_E * E
    dp = brake_plastic_interference(E, R, P0)
    root = brentq(brake_eq26_residual, dp * 1e-3, dp * 1e3, args=(E, R, P0, n), rtol=1e-14)
    assert root == pytest.approx(dp, rel=1e-10)
    assert dp == pytest.approx(R * (3 * math.pi * P0 / (2 * E)) ** 2, rel=1e-15)


def test_paper_values_and_unit_conversion(paper_models: dict[str, ContactModel]) -> None:
    d = paper_models["brake"].details
    H = 1.0 / (2.0 / 327.0 + 2.0 / 105.0)  # printed combination, kgf/mm^2
    assert d["hardness_HB"] == pytest.approx(H, rel=1e-12)
    assert H == pytest.approx(39.740, rel=1e-4)
    assert d["P0"] == pytest.approx(1e6 * H * G0, rel=1e-12)  # 389.7 MPa
    assert d["delta_p"] == pytest.approx(2.4577e-6, rel=1e-4)
    assert d["delta_p"] / d["delta_y"] == pytest.approx(5.649, abs=2e-3)


def test_eq24_transition_by_hand(paper_models: dict[str, ContactModel]) -> None:
    model = paper_models["brake"]
    d = model.details
    dy, dp, P0, n = d["delta_y"], d["delta_p"], d["P0"], d["meyer_index"]
    ap = math.sqrt(2 * R * dp)
    for delta in (1.5 * dy, dp, 10 * dp, 100e-6):
        x = (delta - dy) / (dp - dy)
        a = math.sqrt(2 * R * delta)
        hz = 4 / 3 * model.E_star * math.sqrt(R) * delta**1.5
        want = (1 / math.cosh((n - 1) * x)) * hz + (1 - 1 / math.cosh((3 - n) * x)) * (
            P0 * math.pi * a**n / ap ** (n - 2)
        )
        assert float(model.force(delta)) == pytest.approx(min(want, hz), rel=1e-10)
    # at delta_p the Meyer force equals Hertz (definition of delta_p)
    hz_p = 4 / 3 * model.E_star * math.sqrt(R) * dp**1.5
    assert P0 * math.pi * ap**2 == pytest.approx(hz_p, rel=1e-12)


def test_unloading_rule(paper_models: dict[str, ContactModel]) -> None:
    model = paper_models["brake"]
    for dm in (1e-6, 2e-5, 2e-4):
        br = model.unload(dm)
        hz = 4 / 3 * model.E_star * math.sqrt(R) * dm**1.5
        assert br.delta_r == pytest.approx(dm * (1 - br.F_m / hz), rel=1e-12)
        assert br.R_r == pytest.approx(
            br.F_m**2 / ((4 * model.E_star / 3) ** 2 * (dm - br.delta_r) ** 3), rel=1e-12
        )
        assert float(br.force(dm)) == pytest.approx(br.F_m, rel=1e-12)


def test_meyer_index_sensitivity(paper_pair: ContactPair) -> None:
    """F(200 um) grows with n (the paper gives no n): 4.4 kN at n = 2.01 ... 12.9 kN at 2.5."""
    forces = [
        float(get_law("brake").build(paper_pair, R, meyer_index=n).force(200e-6))
        for n in (2.01, 2.1, 2.2, 2.3, 2.5)
    ]
    assert np.all(np.diff(forces) > 0)
    assert forces[0] == pytest.approx(4405.4, rel=1e-3)
    assert forces[2] == pytest.approx(6691.0, rel=1e-3)
    assert forces[-1] == pytest.approx(12944.3, rel=1e-3)


def test_hertz_cap_only_bites_for_small_n(paper_pair: ContactPair) -> None:
    m22 = get_law("brake").build(paper_pair, R, meyer_index=2.2)
    assert m22.details["max_eq24_over_hertz"] <= 1.0 + 1e-9
    m201 = get_law("brake").build(paper_pair, R, meyer_index=2.01)
    assert m201.details["max_eq24_over_hertz"] == pytest.approx(1.0293, abs=1e-3)
    d = np.linspace(m201.yield_onset[0], 10 * m201.details["delta_p"], 500)
    hz = 4 / 3 * m201.E_star * math.sqrt(R) * d**1.5
    assert np.all(m201.force(d) <= hz * (1 + 1e-12))
    assert np.all(np.array([m201.unload(x).delta_r for x in d[1:]]) >= 0.0)


def test_invalid_inputs_name_the_parameter(paper_pair: ContactPair) -> None:
    law = get_law("brake")
    with pytest.raises(ValueError, match="meyer_index"):
        law.build(paper_pair, R, meyer_index=3.0)
    with pytest.raises(ValueError, match="meyer_index"):
        law.build(paper_pair, R, meyer_index=2.95)  # Eq. 24 not monotone
    with pytest.raises(ValueError, match="hardness"):
        law.build(paper_pair, R, hardness=-3.0)
    with pytest.raises(ValueError, match="hardness"):
        law.build(paper_pair, R, hardness=5.0)  # P0 too small: delta_p < delta_y
    # P0 so large that delta_p passes the hard limit R/2 (1e300: an OverflowError before)
    for hb in (1e300, 1e12, 1700.0):
        with pytest.raises(ValueError, match=r"beyond the law's hard limit R/2.*hardness < 16"):
            law.build(paper_pair, R, hardness=hb)
    assert law.build(paper_pair, R, hardness=1600.0).params[k.P_BR_DP] < 0.5 * R
    soft = Material("no hardness", 200e9, 0.3, 305e6)
    with pytest.raises(ValueError, match="hardness"):
        law.build(ContactPair(soft, soft), R)
    ok = law.build(ContactPair(soft, soft), R, hardness=105.0, meyer_index=2.3)
    assert ok.details["hardness_HB"] == 105.0
    for text in ("105 HB", "HBW 105", "105 kgf/mm^2"):  # as a material takes it
        built = law.build(ContactPair(soft, soft), R, hardness=text, meyer_index=2.3)
        assert built.details["hardness_HB"] == 105.0
    assert k.brake_eq24_force(ok.params, 2 * ok.yield_onset[0]) > 0.0
