"""The core's float arithmetic without library calls: the exponent and significand
from the bits (``impactlab._floatbits``), read by the loading-curve table and the step-size
controller, and the rotation terms of the lever arms (``normal.rotation_terms``)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import example, given
from hypothesis import strategies as st
from numba import njit

from impactlab._floatbits import significand_exponent
from impactlab.bodies import PAPER_ROD
from impactlab.contact.kernels import NPARAM, P_DSW, loading_force
from impactlab.contact.table import table_force
from impactlab.dynamics.kernels.normal import SERIES_PHI, rotation_terms
from impactlab.dynamics.kernels.step_control import _G0, _G1, _G2, _G3, _POW2_FIFTH, growth
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010

POSITIVE_NORMAL = st.floats(min_value=2.3e-308, max_value=1.7e308, allow_nan=False)


@njit(cache=True)
def _split(x: float) -> tuple[float, int]:
    return significand_exponent(x)  # type: ignore[no-any-return]


@njit(cache=True)
def _table(p: np.ndarray, delta: float) -> float:
    return table_force(p, NPARAM, delta)  # type: ignore[no-any-return]


@njit(cache=True)
def _rotation(phi: float) -> tuple[float, float]:
    return rotation_terms(phi)  # type: ignore[no-any-return]


@given(POSITIVE_NORMAL)
@example(1.0)
@example(2.0**-1022)
@example(math.nextafter(2.0, 0.0))
@example(1.7976931348623157e308)
def test_significand_exponent_is_frexp_doubled(x: float) -> None:
    """x = s 2^e, s in [1, 2): frexp's (m, k) = (s/2, e + 1), exactly."""
    s, e = _split(x)
    m, k = math.frexp(x)
    assert (s, e) == (2.0 * m, k - 1)
    assert 1.0 <= s < 2.0


def test_significand_exponent_marks_what_is_not_positive_normal() -> None:
    """Zero and subnormals read exponent -1023, infinity and NaN 1024: out of every caller's
    range check."""
    assert _split(0.0)[1] == -1023
    assert _split(5e-324)[1] == -1023
    assert _split(math.inf)[1] == 1024
    assert _split(math.nan)[1] == 1024


@given(st.floats(min_value=1e-300, max_value=1e300, allow_nan=False))
@example(1.0)
@example(2.0**-65)
@example(2.0**64)
def test_growth_is_bit_identical_to_its_frexp_form(err: float) -> None:
    """The factor from the bits equals the former frexp form to the last bit."""
    m, e = math.frexp(err)
    if e < -64:
        before = 1e30
    elif e > 64:
        before = 0.0
    else:
        t = 4.0 * m - 3.0
        before = 0.9 * (_G0 + t * (_G1 + t * (_G2 + t * _G3))) * _POW2_FIFTH[e + 64]
    assert growth(err) == before


@pytest.mark.parametrize("law", ["ghaednia", "brake", "kogut-komvopoulos", "jackson-green"])
def test_table_force_is_unchanged_by_the_bit_reading(law: str) -> None:
    """The table's rows from the float's bits: the tabulated force at 20,000 interferences
    across the table equals the closed form within the table's 1e-13 (and is the same
    polynomial as with frexp: ``contact`` tests hold the rows)."""
    model = contact_model(PAPER_ROD, AISI_1010, law)
    p = kernel_params(model)
    deltas = np.geomspace(p[P_DSW] * 1.0001, 1e3 * p[P_DSW], 20_000)
    checked = 0
    for d in deltas:
        f = _table(p, d)
        if f < 0.0:  # not tabulated there: the closed form is used
            continue
        checked += 1
        assert f == pytest.approx(loading_force(model.law_id, p, d), rel=1e-13)
    assert checked > 10_000


@given(st.floats(min_value=-1.0, max_value=1.0, allow_nan=False))
@example(0.0)
@example(1e-300)
@example(math.nextafter(SERIES_PHI, 0.0))
@example(SERIES_PHI)
@example(-SERIES_PHI)
def test_rotation_terms_are_sin_and_cos_minus_one(phi: float) -> None:
    """(sin phi, cos phi - 1) within 4 ulp of the closed forms, on both sides of the series'
    limit (cos phi - 1 = -2 sin^2(phi/2) without cancellation)."""
    sp, cm = _rotation(phi)
    assert sp == pytest.approx(math.sin(phi), rel=4.5e-16, abs=1e-300)
    assert cm == pytest.approx(-2.0 * math.sin(0.5 * phi) ** 2, rel=4.5e-16, abs=1e-300)
