"""The rate-dependent flat: the rate laws, the strain-rate estimate, the self-consistent factor
and the drop with a rate-dependent flat."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact.rate import (
    COWPER_SYMONDS_MILD_STEEL,
    JOHNSON_COOK_1006_STEEL,
    cowper_symonds,
    get_rate_law,
    johnson_cook,
    rate_materials,
    self_consistent_factor,
    tabor_strain_rate,
)
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.models import build_contact_model
from impactlab.materials import AISI_201, AISI_1010


def test_cowper_symonds() -> None:
    """1 + (rate / 40.4)^(1/5): 1 at rest, 2 at D, 3 at 32 D."""
    assert cowper_symonds(0.0) == 1.0
    assert cowper_symonds(40.4) == pytest.approx(2.0, rel=1e-15)
    assert cowper_symonds(40.4 * 32) == pytest.approx(3.0, rel=1e-15)
    assert COWPER_SYMONDS_MILD_STEEL.factor(500.0) == cowper_symonds(500.0, 40.4, 5.0)


def test_johnson_cook() -> None:
    """1 + 0.022 ln(rate / 1 s^-1), floored at 1."""
    assert johnson_cook(0.5) == 1.0
    assert johnson_cook(math.e**10) == pytest.approx(1.22, rel=1e-15)
    assert JOHNSON_COOK_1006_STEEL.factor(math.e) == pytest.approx(1.022, rel=1e-15)


def test_tabor_rate() -> None:
    """0.2 |v| / a, and v / a with factor 1."""
    assert tabor_strain_rate(-1.0, 1e-3) == pytest.approx(200.0, rel=1e-15)
    assert tabor_strain_rate(1.0, 1e-3, factor=1.0) == pytest.approx(1000.0, rel=1e-15)
    with pytest.raises(ValueError, match="a"):
        tabor_strain_rate(1.0, 0.0)


def test_fixed_point() -> None:
    """k = f(0.2 |v| / a_m(k)) with a_m(k) = a0 / sqrt(k) (a harder flat, a smaller contact)."""
    a0 = 5e-4
    f = self_consistent_factor(lambda k: a0 / math.sqrt(k), COWPER_SYMONDS_MILD_STEEL, 1.41)
    assert f.k == pytest.approx(cowper_symonds(0.2 * 1.41 / (a0 / math.sqrt(f.k))), rel=1e-4)
    assert f.iterations < 12 and f.contact_radius == pytest.approx(a0 / math.sqrt(f.k), rel=1e-3)


def test_flat_yield_is_the_law_yield() -> None:
    """The rate-raised flat's yield strength is the law's, above the rod's static one."""
    body, flat = rate_materials(AISI_201, AISI_1010, 3.0)
    assert flat.yield_strength == pytest.approx(3 * 305e6, rel=1e-15)
    assert body.yield_strength > flat.yield_strength
    model = build_contact_model("ghaednia", body, flat, 0.0088)
    assert model.params[2] == pytest.approx(3 * 305e6, rel=1e-15)
    assert rate_materials(AISI_201, AISI_1010, 1.0)[0] is AISI_201


def test_get_rate_law() -> None:
    assert get_rate_law("cowper-symonds") is COWPER_SYMONDS_MILD_STEEL
    assert get_rate_law(JOHNSON_COOK_1006_STEEL) is JOHNSON_COOK_1006_STEEL
    with pytest.raises(ValueError, match="rate"):
        get_rate_law("zerilli-armstrong")


def test_drop_with_rate_dependent_flat() -> None:
    """The paper's 20 deg drop on a Cowper-Symonds flat: the self-consistent k = 2.64 at
    486 1/s (prototype study) makes the dent shallower (32 -> 23 um); Johnson-Cook barely
    moves it (k = 1.13)."""
    kw = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}
    rod = FlexibleRod.paper()
    plain = simulate_drop(rod, **kw)
    cs = simulate_drop(rod, rate="cowper-symonds", **kw)
    jc = simulate_drop(rod, rate="johnson-cook", **kw)
    assert cs.rate == "cowper-symonds" and cs.rate_factor == pytest.approx(2.64, abs=0.01)
    assert cs.strain_rate == pytest.approx(486, rel=0.01)
    assert (
        cs.dent_depth == pytest.approx(23e-6, rel=0.02) and plain.dent_depth > 1.3 * cs.dent_depth
    )
    assert jc.rate_factor == pytest.approx(1.13, abs=0.005)
    assert abs(jc.dent_depth / plain.dent_depth - 1) < 0.05
    assert any("Cowper" in str(ref) for ref in cs.references)
    assert plain.rate is None and plain.rate_factor == 1.0
