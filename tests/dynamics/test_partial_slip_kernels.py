"""Kernels of the partial-slip engine's hot path: the cell limits without a division against
the shared ``cells.limits``, and the event search's bracket (Anderson-Bjorck regula falsi with
a closing step) on functions with known roots."""

from __future__ import annotations

import math

from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.dynamics.kernels.cells import limits, limits_inv
from impactlab.dynamics.kernels.roots import anderson_bjorck, anderson_bjorck_point

TOL = 1e-13
DX = 1e-5


@settings(deadline=None, max_examples=300)
@given(
    i=st.integers(0, 16),
    a_cells=st.floats(1e-6, 17.0),
    fn=st.floats(1e-3, 1e4),
    fd=st.floats(-1e8, 1e8),
    ad=st.floats(-10.0, 10.0),
)
def test_limits_without_division_equal_the_shared_limits(i, a_cells, fn, fd, ad) -> None:
    ar = a_cells * DX
    mu = 0.3
    lim0, rate0 = limits(i, DX, mu, fn, fd, ar, ad)
    lim1, rate1 = limits_inv(i, DX, mu, fn, fd, ar, ad, 1.0 / ar)
    assert lim1 >= 0.0
    assert abs(lim1 - lim0) <= 4e-15 * mu * fn
    # the rate's scale: each of its two terms
    assert abs(rate1 - rate0) <= 4e-15 * mu * (abs(fd) + 3.0 * fn * abs(ad) / ar)


def test_limits_of_a_contact_sum_to_the_coulomb_limit() -> None:
    for a_cells in (0.3, 1.0, 5.5, 16.0):
        ar = a_cells * DX
        total = sum(limits_inv(i, DX, 0.3, 2.0, 0.0, ar, 0.0, 1.0 / ar)[0] for i in range(17))
        assert math.isclose(total, 0.3 * 2.0, rel_tol=1e-14)


def test_edge_cell_limit_is_quadratic_in_its_length() -> None:
    """Near its inner end the edge cell's limit is mu F_n x^2 (1.5 - 0.5 x), x = l / a, to
    round-off of itself (the form of ``limits`` cancels its O(x) terms: an error of order
    1e-16 mu F_n, larger than the limit itself for x < 1e-8)."""
    lo = 7 * DX
    for x0 in (1e-12, 1e-9, 1e-6, 0.1):
        ar = lo / (1.0 - x0)
        x = (ar - lo) / ar  # the length the engine sees (ar - lo is exact here)
        L, _ = limits_inv(7, DX, 1.0, 1.0, 0.0, ar, 0.0, 1.0 / ar)
        assert math.isclose(L, x * x * (1.5 - 0.5 * x), rel_tol=1e-14)


def _search(g, lo=0.0, hi=0.5):
    """(bracket end where g > 0, the other end, evaluations) of the engine's search."""
    a, fa, b, fb, side = lo, g(lo), hi, g(hi), 0
    n = 0
    while b - a > TOL and n < 60:
        th = anderson_bjorck_point(a, fa, b, fb, side, 0.5 * TOL)
        assert a < th < b
        n += 1
        a, fa, b, fb, side = anderson_bjorck(a, fa, b, fb, side, th, g(th))
    return b, a, n


def test_search_closes_the_bracket_on_smooth_functions() -> None:
    cases = {
        0.3: lambda t: (t - 0.3) ** 3 + 0.01 * (t - 0.3),
        0.25: lambda t: math.exp(8.0 * t) - math.exp(2.0),
        math.sqrt(0.0123): lambda t: t * t - 0.0123,
        0.2: lambda t: t - 0.2,
        math.asin(0.5) / 3.0: lambda t: math.sin(3.0 * t) - 0.5,
    }
    for root, g in cases.items():
        b, a, n = _search(g)
        assert g(b) > 0.0 and g(a) <= 0.0
        assert b - a <= TOL
        assert a - 1e-15 <= root <= b + 1e-15
        assert n <= 10  # the Illinois iteration took 10-43 on these


@settings(deadline=None, max_examples=200)
@given(root=st.floats(1e-3, 0.499), curv=st.floats(0.0, 1e3), scale=st.floats(1e-6, 1e6))
def test_search_brackets_the_root_of_a_monotone_function(root, curv, scale) -> None:
    def g(t: float) -> float:
        d = t - root
        return scale * d * (1.0 + curv * d * d)

    b, a, n = _search(g)
    assert b - a <= TOL
    assert g(b) > 0.0 and g(a) <= 0.0
    assert n < 60
