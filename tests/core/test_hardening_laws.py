"""The flat's strain-hardening laws (``impactlab.materials.hardening``): Swift's law through a
grade's yield and tensile strength by Considere's criterion, and the tables the FE program takes."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.fe.problem import check_hardening
from impactlab.materials.hardening import (
    AISI_1010_HARDENING,
    AISI_1010_TENSILE_STRENGTH,
    AISI_1010_WITH_1006_HARDENING,
    PowerLawHardening,
    SwiftHardening,
)
from impactlab.materials.library import AISI_1010

SOURCES = ("swift-1952", "sae-j1397", "dieter-1961")
KSI = 6.894757293168361e6  # Pa per ksi (1000 lbf / in^2)


def test_aisi_1010_law_is_the_sae_cold_drawn_row_through_considere() -> None:
    """S_y = 305 MPa (the paper's rounding of SAE J1397's 44 ksi), S_u = 365 MPa (53 ksi):
    n and K checked against the closed form (n / eps0)^n = (S_u / S_y) exp(n - eps0)."""
    h = AISI_1010_HARDENING
    assert 44 * KSI == pytest.approx(303.4e6, abs=0.05e6)
    assert 53 * KSI == pytest.approx(365.4e6, abs=0.05e6)
    assert AISI_1010_TENSILE_STRENGTH == 365e6
    assert h.yield_strength == pytest.approx(AISI_1010.yield_strength, rel=1e-12)
    assert h.eps0 == 0.002 and h.source == SOURCES
    assert (h.n / h.eps0) ** h.n == pytest.approx(365 / 305 * math.exp(h.n - h.eps0), rel=1e-12)
    assert h.n == pytest.approx(0.06964, abs=1e-5)
    assert h.K == pytest.approx(470.16e6, rel=1e-4)
    assert h.tensile_strength == pytest.approx(365e6, rel=1e-12)


def test_aisi_1010_law_against_the_tables_other_columns() -> None:
    """Consistency, nothing fitted: the uniform strain lies below the 20 % total elongation;
    at the true fracture strain of the 40 % reduction of area, ln(1 / 0.6) = 0.511, the law
    gives 449 MPa (the 1006 stand-in 521 MPa)."""
    h = AISI_1010_HARDENING
    assert h.uniform_strain == pytest.approx(0.0676, abs=1e-4)
    assert h.uniform_strain < math.log(1.20)
    eps_f = math.log(1.0 / 0.6)
    assert float(h.stress(eps_f)) == pytest.approx(448.8e6, rel=1e-3)
    assert float(AISI_1010_WITH_1006_HARDENING.stress(eps_f)) == pytest.approx(520.8e6, rel=1e-3)


def test_the_1006_stand_in_is_kept_for_comparison() -> None:
    j = AISI_1010_WITH_1006_HARDENING
    assert (j.yield_strength, j.B, j.n, j.source) == (305e6, 275e6, 0.36, "johnson-cook-1983")
    assert float(j.stress(1.0)) == pytest.approx(305e6 + 275e6)


@settings(max_examples=80, deadline=None)
@given(
    sy=st.floats(50e6, 2e9),
    ratio=st.floats(1.001, 2.5),
    eps0=st.floats(1e-4, 1e-2),
)
def test_swift_from_tensile_meets_its_two_conditions(sy: float, ratio: float, eps0: float) -> None:
    """sigma(0) = S_y; at eps_u = n - eps0 the slope equals the stress (Considere) and the
    true stress over exp(eps_u) is S_u; the flow stress rises with the strain."""
    su = ratio * sy
    h = SwiftHardening.from_tensile("x", sy, su, SOURCES, eps0=eps0)
    assert float(h.stress(0.0)) == pytest.approx(sy, rel=1e-12)
    eu = h.uniform_strain
    assert eu > 0.0
    assert float(h.slope(eu)) == pytest.approx(float(h.stress(eu)), rel=1e-9)
    assert float(h.stress(eu)) * math.exp(-eu) == pytest.approx(su, rel=1e-9)
    # past eps_u the slope falls below the stress (the neck grows), before it lies above
    assert float(h.slope(2 * eu)) < float(h.stress(2 * eu))
    assert float(h.slope(eu / 2)) > float(h.stress(eu / 2))
    e = np.linspace(0.0, 3.0, 301)
    assert np.all(np.diff(h.stress(e)) > 0.0)


@settings(max_examples=40, deadline=None)
@given(ratio_a=st.floats(1.01, 2.0), ratio_b=st.floats(1.01, 2.0))
def test_a_higher_tensile_strength_gives_a_higher_exponent(ratio_a: float, ratio_b: float) -> None:
    lo, hi = sorted((ratio_a, ratio_b))
    a = SwiftHardening.from_tensile("a", 300e6, lo * 300e6, SOURCES)
    b = SwiftHardening.from_tensile("b", 300e6, hi * 300e6, SOURCES)
    assert a.n <= b.n


def test_table_rows_strain_zero_first_then_geometric() -> None:
    h = AISI_1010_HARDENING
    rows = check_hardening("flat_hardening", h.table())  # starts at strain 0, monotonic
    assert len(rows) == 40
    s, e = np.array(rows).T
    assert e[0] == 0.0 and e[1] == 1e-5 and e[-1] == h.max_strain
    ratios = e[2:] / e[1:-1]
    np.testing.assert_allclose(ratios, ratios[0], rtol=1e-5)
    np.testing.assert_allclose(s, h.stress(e), rtol=1e-6)
    assert s[0] == pytest.approx(305e6, rel=1e-7)
    assert all(float(f"{v:.7g}") == v for v in (*s, *e))
    assert len(h.table(5)) == 5
    with pytest.raises(ValueError, match="points must be >= 3"):
        h.table(2)


@pytest.mark.parametrize(
    ("sy", "su", "eps0", "match"),
    [
        (305e6, 305e6, 0.002, "tensile_strength must exceed yield_strength"),
        (305e6, 200e6, 0.002, "tensile_strength must exceed yield_strength"),
        (-1.0, 365e6, 0.002, "yield_strength must be a positive stress"),
        (305e6, math.nan, 0.002, "tensile_strength must be a positive stress"),
        (305e6, 365e6, 0.0, "eps0 must lie in"),
        (305e6, 365e6, 1.5, "eps0 must lie in"),
        (1e6, 1e9, 0.002, "needs a Swift exponent n > 1"),
    ],
)
def test_bad_tensile_inputs_are_refused(sy: float, su: float, eps0: float, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        SwiftHardening.from_tensile("x", sy, su, SOURCES, eps0=eps0)


def test_bad_law_inputs_are_refused() -> None:
    with pytest.raises(ValueError, match="K must be a positive stress"):
        SwiftHardening("x", -1.0, 0.002, 0.1, SOURCES)
    with pytest.raises(ValueError, match="n must lie in"):
        SwiftHardening("x", 5e8, 0.002, 1.5, SOURCES)
    with pytest.raises(ValueError, match="max_strain must be > 0"):
        SwiftHardening("x", 5e8, 0.002, 0.1, SOURCES, max_strain=0.0)
    with pytest.raises(ValueError, match="unknown reference key"):
        SwiftHardening("x", 5e8, 0.002, 0.1, ("nobody-2099",))
    with pytest.raises(ValueError, match="plastic_strain"):
        AISI_1010_HARDENING.stress(-0.1)
    with pytest.raises(ValueError, match="n must lie in"):
        PowerLawHardening("x", 1e8, 1e8, 1.5, "johnson-cook-1983")
