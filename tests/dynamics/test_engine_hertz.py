"""Elastic sphere (Hertz), normal impact, no gravity: the closed forms of Hertz theory.

delta_m = (15 m v^2 / (16 E* sqrt(R)))^(2/5), F_m = 4/3 E* sqrt(R) delta_m^(3/2),
T = 2 (delta_m / v) int_0^1 (1 - x^(5/2))^(-1/2) dx = (4/5) B(2/5, 1/2) delta_m / v
(Johnson, Contact Mechanics (1985) Sec. 11.4, doi:10.1017/CBO9781139171731).
All must hold to 1e-6 relative at the default tolerance; e = 1 within 1e-6.
"""

from __future__ import annotations

import math

import pytest
from scipy.special import beta

from impactlab.bodies import Sphere
from impactlab.dynamics import simulate
from impactlab.materials import AISI_201, AISI_1010, ContactPair, Material

REL = 1e-6


def hertz_closed_form(m: float, E_star: float, R: float, v: float) -> tuple[float, float, float]:
    dm = (15.0 * m * v * v / (16.0 * E_star * math.sqrt(R))) ** 0.4
    Fm = 4.0 / 3.0 * E_star * math.sqrt(R) * dm**1.5
    T = 0.8 * beta(0.4, 0.5) * dm / v
    return dm, Fm, T


@pytest.mark.parametrize(
    ("radius", "v", "flat"),
    [
        (0.01, 1.0, AISI_1010),
        (0.002, 0.05, AISI_1010),
        (0.03, 4.0, AISI_1010),
        (0.005, 0.7, Material("soft", E=5e9, nu=0.4, yield_strength=1e8, density=1200.0)),
    ],
)
def test_hertz_closed_forms(radius: float, v: float, flat: Material) -> None:
    s = Sphere(radius)
    r = simulate(
        s, flat, law="hertz", friction="coulomb", mu=0.0, velocity=(0.0, -v), gravity=False
    )
    E_star = ContactPair(AISI_201, flat).E_star
    dm, Fm, T = hertz_closed_form(s.mass, E_star, radius, v)
    assert r.delta_max == pytest.approx(dm, rel=REL)
    assert r.max_force == pytest.approx(Fm, rel=REL)
    assert r.duration == pytest.approx(T, rel=REL)
    assert abs(r.e - 1.0) < REL
    assert abs(r.e_energy - 1.0) < REL
    assert r.delta_p == 0.0
    assert r.t_max == pytest.approx(T / 2, rel=1e-5)
    # the normal impulse is 2 m v exactly (no gravity)
    assert r.normal_impulse == pytest.approx(2.0 * s.mass * v, rel=REL)


def test_hertz_tighter_tolerance_converges() -> None:
    s = Sphere(0.01)
    dm, _Fm, T = hertz_closed_form(s.mass, ContactPair(AISI_201, AISI_1010).E_star, 0.01, 1.0)
    r = simulate(s, law="hertz", velocity=(0.0, -1.0), gravity=False, rtol=1e-11)
    assert r.duration == pytest.approx(T, rel=1e-9)
    assert r.delta_max == pytest.approx(dm, rel=1e-9)
    assert abs(r.e - 1.0) < 1e-9


def test_gravity_changes_the_impulse_by_m_g_T() -> None:
    s = Sphere(0.01)
    r0 = simulate(s, law="hertz", velocity=(0.0, -0.05), gravity=False)
    r1 = simulate(s, law="hertz", velocity=(0.0, -0.05), gravity=True)
    # momentum balance: m (vy_out - vy_in) = P_n - m g T
    assert r1.normal_impulse == pytest.approx(
        s.mass * (r1.velocity_out[1] + 0.05) + s.mass * 9.80665 * r1.duration, rel=1e-12
    )
    # elastic and back at the height of first touch: the same rebound speed (energy), so the
    # flat supplies the weight's impulse m g T on top (g T = 8e-4 of v: far above the error)
    assert r1.velocity_out[1] == pytest.approx(r0.velocity_out[1], rel=1e-7)
    gain = r1.normal_impulse - r0.normal_impulse
    assert gain == pytest.approx(s.mass * 9.80665 * r1.duration, rel=1e-4)
