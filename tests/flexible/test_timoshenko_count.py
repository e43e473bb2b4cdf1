"""The count of the Timoshenko bending frequencies below a frequency (Wittrick-Williams) and
the roots it recovers where the determinant scan misses a close pair."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.bodies import timoshenko as tim
from impactlab.bodies import timoshenko_solutions as solutions
from impactlab.bodies.rod_section import RodSection
from impactlab.bodies.timoshenko_count import _member_stiffness, bending_modes_below

#: A steel rod of the paper's size whose 59th and 60th bending modes (192.193 and 192.204 kHz,
#: above the shear cut-off) lie 10 Hz apart: the scan's grid for 69 modes steps over the pair.
D, L = 0.0157, 0.3048
CLOSE_PAIR = RodSection(
    length=L, mass=7800.0 * math.pi * D * D / 4 * L, density=7800.0, E=197e9, nu=0.3, diameter=D
)


def steel_rod(length: float, diameter: float) -> RodSection:
    mass = 7800.0 * math.pi * diameter**2 / 4 * length
    return RodSection(length=length, mass=mass, density=7800.0, E=197e9, nu=0.3, diameter=diameter)


def test_the_members_stiffness_tends_to_the_static_timoshenko_element() -> None:
    """At a low frequency the exact dynamic stiffness is the static element's (shear
    parameter phi = 12 E I / (kappa G A l^2)), to O(omega^2)."""
    _rho, A, I, E, kG = solutions.section_constants(CLOSE_PAIR)
    l = 0.02
    phi = 12 * E * I / (kG * A * l * l)
    K0 = (E * I / ((1 + phi) * l**3)) * np.array(
        [
            [12, 6 * l, -12, 6 * l],
            [6 * l, (4 + phi) * l * l, -6 * l, (2 - phi) * l * l],
            [-12, -6 * l, 12, -6 * l],
            [6 * l, (2 - phi) * l * l, -6 * l, (4 + phi) * l * l],
        ]
    )
    for om, tol in ((100.0, 1e-6), (10.0, 1e-8)):
        K = _member_stiffness(CLOSE_PAIR, l, om)
        assert np.max(np.abs(K - K0)) < tol * np.max(np.abs(K0))


def test_the_count_between_the_scans_roots_steps_by_one() -> None:
    om = tim.timoshenko_frequencies(CLOSE_PAIR, 40)  # to 1.2x the cut-off (120 kHz)
    assert bending_modes_below(CLOSE_PAIR, 0.5 * om[0]) == 0
    mids = 0.5 * (om[1:] + om[:-1])
    assert [bending_modes_below(CLOSE_PAIR, m) for m in mids] == list(range(1, 40))


def test_a_close_pair_between_grid_points_is_found() -> None:
    om = tim.timoshenko_frequencies(CLOSE_PAIR, 69)
    khz = om / (2e3 * math.pi)
    assert np.all(np.diff(om) > 0)
    assert np.count_nonzero(np.abs(khz - 192.198) < 0.01) == 2  # 192.193 and 192.204 kHz
    assert bending_modes_below(CLOSE_PAIR, om[-1] * (1 + 1e-9)) == 69
    for r in om[57:61]:  # roots of the boundary determinant, refined as the scan's
        assert abs(solutions.determinant(float(r), CLOSE_PAIR)) < 1e-6


def test_frequencies_do_not_depend_on_the_count_asked_for() -> None:
    few = tim.timoshenko_frequencies(CLOSE_PAIR, 69)
    more = tim.timoshenko_frequencies(CLOSE_PAIR, 76)
    np.testing.assert_allclose(few, more[:69], rtol=1e-12)


@settings(max_examples=10, deadline=None)
@given(
    slenderness=st.floats(4.0, 80.0),
    log_diameter=st.floats(-6.0, -0.5),
    n=st.integers(10, 60),
)
def test_no_bending_frequency_is_missed(slenderness: float, log_diameter: float, n: int) -> None:
    """Every frequency below the n-th is among the first n, for rods from 1 um to 0.3 m thick,
    stubby to slender, counts reaching far above the shear cut-off; the frequencies of rods of
    one shape scale as 1 / size (a thin rod's determinants are of 1e-22 and less)."""
    diameter = 10.0**log_diameter
    sec = steel_rod(slenderness * diameter, diameter)
    om = tim.timoshenko_frequencies(sec, n)
    assert np.all(np.diff(om) > 0)
    assert bending_modes_below(sec, om[-1] * (1 + 1e-9)) == n
    assert bending_modes_below(sec, om[-1] * (1 - 1e-9)) == n - 1
    centimetre = tim.timoshenko_frequencies(steel_rod(slenderness * 0.01, 0.01), n)
    np.testing.assert_allclose(om * diameter, centimetre * 0.01, rtol=1e-9)
