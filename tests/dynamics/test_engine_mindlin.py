"""Mindlin-type tangential compliance: the oblique elastic impact of a sphere.

Known behaviour (Maw, Barber & Fawcett, Wear 38 (1976) 101, doi:10.1016/0043-1648(76)90201-5;
Di Renzo & Di Maio, Chem. Eng. Sci. 59 (2004) 525, doi:10.1016/j.ces.2003.09.037): with
psi1 = 2(1-nu)/(mu(2-nu)) v_t/v_n the normalised incidence and psi2 = -(same) v_t,out/v_n,out
the normalised recoil angle, psi2 ~ -c psi1 for small psi1 (the contact point rebounds forward,
linearly in psi1, no gross slip), psi2 > 0 below the gross-slip limit psi1 = 4 chi (the
tangential velocity of the contact point is REVERSED, which rigid Coulomb theory cannot give:
it predicts rolling, v_t,out = 0), and psi2 = 4 chi - psi1 in gross slip, as for Coulomb.
chi = (1-nu)/(2-nu) (1 + R^2/k^2) = 1.441 for a solid sphere with nu = 0.3.
"""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.bodies import Sphere
from impactlab.dynamics import simulate_batch

MU = 0.3
NU = 0.3
SCALE = 2 * (1 - NU) / (MU * (2 - NU))  # psi = SCALE * v_t / v_n
CHI = (1 - NU) / (2 - NU) * 3.5


def _psi2(psi1: np.ndarray, friction: str) -> tuple[np.ndarray, np.ndarray]:
    vt = psi1 / SCALE
    b = simulate_batch(
        Sphere(0.01), law="hertz", friction=friction, mu=MU, vx=vt, vy=-1.0, gravity=False
    )
    assert np.all(b.ok)
    return -SCALE * b.vt_out / b.vn_out, b.regime


def test_small_angles_linear_forward_rebound() -> None:
    psi1 = np.array([0.01, 0.02, 0.05])
    psi2, _regime = _psi2(psi1, "mindlin")
    ratio = psi2 / psi1
    assert np.all(ratio < 0.0)  # forward rebound of the contact point
    assert np.ptp(ratio) < 1e-3 * abs(ratio.mean())  # linear in psi1: no gross slip yet
    # Coulomb: the sphere rolls off (v_t,out = 0)
    c2, _ = _psi2(psi1, "coulomb")
    assert np.all(np.abs(c2) < 1e-6)


def test_tangential_velocity_reversal_below_gross_slip() -> None:
    psi1 = np.linspace(2.0, 4.0, 5)
    psi2, regime = _psi2(psi1, "mindlin")
    assert np.all(psi2 > 0.1)  # reversed tangential velocity of the contact point
    assert np.all(regime == 3)  # reported as a slip reversal
    c2, _ = _psi2(psi1, "coulomb")
    assert np.all(np.abs(c2) < 1e-6)


def test_gross_slip_equals_coulomb() -> None:
    psi1 = np.array([1.2, 2.0, 4.0]) * 4 * CHI
    m2, _ = _psi2(psi1, "mindlin")
    c2, _ = _psi2(psi1, "coulomb")
    np.testing.assert_allclose(m2, 4 * CHI - psi1, rtol=0, atol=1e-5)
    np.testing.assert_allclose(m2, c2, rtol=0, atol=1e-5)


def test_normal_restitution_unaffected_for_a_sphere() -> None:
    b = simulate_batch(
        Sphere(0.01),
        law="hertz",
        friction="mindlin",
        mu=MU,
        vx=np.array([0.01, 0.5, 3.0]),
        vy=-1.0,
        gravity=False,
    )
    np.testing.assert_allclose(b.e, 1.0, atol=1e-6)
    assert np.all(b.energy_dissipated >= -1e-9)


@pytest.mark.parametrize("vx", [0.0, 0.3])
def test_mindlin_tends_to_coulomb_for_a_stiff_tangential_contact(vx: float) -> None:
    """With mu small the cap dominates and Mindlin reduces to Coulomb sliding."""
    m = simulate_batch(
        Sphere(0.01), law="hertz", friction="mindlin", mu=0.01, vx=vx + 0.2, vy=-1.0, gravity=False
    )
    c = simulate_batch(
        Sphere(0.01), law="hertz", friction="coulomb", mu=0.01, vx=vx + 0.2, vy=-1.0, gravity=False
    )
    np.testing.assert_allclose(m.vt_out, c.vt_out, atol=1e-6)
