"""Kogut-Komvopoulos (paper Eqs. 20-22): elastic prefactor, switch, residual, limits."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import get_law
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.materials import ContactPair

R = 8.8e-3


def test_elastic_branch_equals_hertz_with_the_corrected_prefactor(
    paper_models: dict[str, ContactModel],
) -> None:
    model = paper_models["kogut-komvopoulos"]
    E, Sy = model.E_star, 305e6
    for d in (1e-9, 1e-8, 2e-7):
        rp = math.sqrt(d * (2 * R - d))  # = sqrt(R^2 - (R - d)^2) without cancellation
        assert rp == pytest.approx(math.sqrt(R**2 - (R - d) ** 2), rel=1e-6)
        a_trunc = math.pi * rp**2
        corrected = a_trunc * Sy * 2 * math.sqrt(2) / (3 * math.pi) * (E * d / (Sy * rp))
        printed = a_trunc * Sy * 4 * math.sqrt(2) / (3 * math.pi) * (E * d / (Sy * rp))
        hertz = 4 / 3 * E * math.sqrt(R) * d**1.5
        assert corrected == pytest.approx(hertz * math.sqrt(1 - d / (2 * R)), rel=1e-12)
        assert corrected == pytest.approx(hertz, rel=d / (2 * R))
        assert printed == pytest.approx(2.0 * hertz, rel=d / (2 * R))
        assert float(model.force(d)) == pytest.approx(corrected, rel=1e-12)


def test_eq21_by_hand_and_published_jump(paper_pair: ContactPair) -> None:
    model = get_law("kogut-komvopoulos").build(paper_pair, R, published_switch=1)
    eps = model.E_star / 305e6
    for d in (1e-6, 20e-6, 200e-6):
        rp = math.sqrt(d * (2 * R - d))
        t = d / rp
        want = (
            math.pi
            * rp**2
            * 305e6
            * (0.839 + math.log(eps**0.656 * t**0.651))
            / (2.192 - math.log(eps**0.394 * t**0.419))
        )
        assert float(model.force(d)) == pytest.approx(want, rel=1e-12)
    # at the published switch Eq. 21 is 11 % above the elastic branch for the paper's pair
    assert model.details["published_jump"] == pytest.approx(0.110, abs=2e-3)


def test_default_switch_and_limits(paper_models: dict[str, ContactModel]) -> None:
    model = paper_models["kogut-komvopoulos"]
    assert model.details["switch_ratio"] == pytest.approx(1.957, abs=5e-3)
    assert model.max_interference < model.details["pole_interference"] < R
    # the hard limit is the minimum of F/F_elastic
    p = model.params
    d = model.max_interference
    r = [k.kk_ep_force(p, x) / k.kk_elastic_force(p, x) for x in (0.98 * d, d, 1.02 * d)]
    assert r[1] <= r[0] and r[1] <= r[2]
    assert model.max_interference > 200e-6  # the paper's interferences are inside


def test_residual_eq22(paper_models: dict[str, ContactModel]) -> None:
    model = paper_models["kogut-komvopoulos"]
    eps = model.E_star / 305e6
    frac = 1.0 - 0.591 * eps**-0.156
    assert frac == pytest.approx(0.7641, abs=1e-4)
    dy = model.yield_onset[0]
    assert model.unload(0.9 * dy).delta_r == 0.0
    for dm in (1.01 * dy, 1e-5, 1e-4):
        assert model.unload(dm).delta_r == pytest.approx(frac * dm, rel=1e-12)


def test_eq21_pole_gives_inf_not_nan(paper_models: dict[str, ContactModel]) -> None:
    p = paper_models["kogut-komvopoulos"].params
    d_pole = paper_models["kogut-komvopoulos"].details["pole_interference"]
    assert k.kk_ep_force(p, d_pole * 1.01) == math.inf
    assert np.isfinite(k.kk_ep_force(p, d_pole * 0.99))
