"""impactlab.bodies: lever arms and the rigid-body impulse against independent constructions (the
impulse-velocity matrix of a rigid body built from vectors, and a step-by-step march in the normal
impulse)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab.analytic import critical_friction, impulse_coefficients
from impactlab.bodies import PAPER_ROD, Rod, Sphere, lever_arms, rigid_impulse


def delassus(body, angle):
    """W with dv_O = W @ (P_t, P_n), from the kinematics of a rigid body (no closed forms)."""
    axis = np.array([math.cos(angle), math.sin(angle)])  # from the tip towards C
    r = -body.half_length * axis - np.array([0.0, body.tip_radius])  # C -> O
    J = np.array([[1.0, 0.0, -r[1]], [0.0, 1.0, r[0]]])  # v_O = v_C + spin k x r
    Minv = np.diag([1.0 / body.mass, 1.0 / body.mass, 1.0 / body.inertia])
    return J @ Minv @ J.T, r


def march(body, angle, velocity, spin, e, mu, n=200_000):
    """Coulomb friction followed along the normal impulse in small steps (P_t opposes the slip;
    at rest it sticks when it can; the stop of a slip is located): an independent check of the
    phases."""
    W, _ = delassus(body, angle)
    r = -body.half_length * np.array([math.cos(angle), math.sin(angle)]) - np.array(
        [0.0, body.tip_radius]
    )
    v = np.array([velocity[0] - spin * r[1], velocity[1] + spin * r[0]])
    target = -e * v[1]
    stick_ratio = W[0, 1] / W[0, 0]
    dp = (1 + e) * abs(v[1]) / (W[1, 1] - mu * abs(W[0, 1])) / n * 4
    P = np.zeros(2)
    while v[1] < target:
        if abs(v[0]) < 1e-9 * abs(velocity[1]) and abs(stick_ratio) <= mu:
            ratio = stick_ratio
        else:
            slip = v[0] if abs(v[0]) > 1e-9 * abs(velocity[1]) else np.sign(W[0, 1])
            ratio = -mu * np.sign(slip)
        step = min(dp, (target - v[1]) / (W[1, 1] + ratio * W[1, 0]))
        rate_t = W[0, 0] * ratio + W[0, 1]
        if v[0] * rate_t < 0:  # locate the stop of the slip (an event, as an ODE solver would)
            step = min(step, -v[0] / rate_t)
        dP = np.array([ratio, 1.0]) * step
        P += dP
        v = v + W @ dP
    return P, v


def test_lever_arms_hand_numbers_and_broadcasting():
    a, b = lever_arms(0.1524, 0.0088, math.radians(20))
    assert a == pytest.approx(0.1524 * 0.93969262, rel=1e-8)
    assert b == pytest.approx(0.1524 * 0.34202014 + 0.0088, rel=1e-8)
    a, b = lever_arms(np.array([[0.1], [0.2]]), 0.01, np.radians([0.0, 90.0]))
    assert a.shape == b.shape == (2, 2)
    assert a[1, 0] == pytest.approx(0.2) and b[1, 1] == pytest.approx(0.21)


@settings(max_examples=80, deadline=None)
@given(
    angle=st.floats(0.02, math.pi / 2 - 0.02),
    mu=st.floats(0.0, 1.5),
    e=st.floats(0.0, 1.0),
    vy=st.floats(-4.0, -0.1),
    ratio=st.floats(0.02, 0.25),  # I_C / (m L^2) <= 1/4: all the mass at the ends
)
def test_rod_at_rest_tangentially_against_the_impulse_matrix(angle, mu, e, vy, ratio):
    rod = Rod(length=0.3048, tip_radius=0.0088, mass=0.4607, inertia=ratio * 0.4607 * 0.3048**2)
    r = rigid_impulse(rod, angle, (0.0, vy), e=e, mu=mu)
    W, arm = delassus(rod, angle)
    dv = W @ np.array([r.tangential_impulse, r.normal_impulse])
    assert r.contact_velocity_out[0] == pytest.approx(dv[0], abs=1e-12 * abs(vy))
    assert r.contact_velocity_out[1] == pytest.approx(vy + dv[1], rel=1e-12)
    assert r.contact_velocity_out[1] == pytest.approx(-e * vy, rel=1e-12, abs=1e-14 * abs(vy))
    mu_c = float(critical_friction(angle, rod))
    assert r.mu_critical == mu_c
    if mu < mu_c:
        assert r.regime == "slip" and r.mu_effective == pytest.approx(mu, rel=1e-12, abs=1e-15)
        assert r.contact_velocity_out[0] <= 0.0  # slides towards -x
        _, K_y = impulse_coefficients(angle, mu, rod)
        assert r.normal_impulse == pytest.approx((1 + e) * -vy / K_y, rel=1e-12)
    else:
        assert r.regime == "stick" and r.mu_effective == pytest.approx(mu_c, rel=1e-12)
        assert abs(r.contact_velocity_out[0]) < 1e-12 * abs(vy)
    # momentum and angular momentum about O are consistent with the impulse
    assert r.velocity_out[0] * rod.mass == pytest.approx(r.tangential_impulse, rel=1e-12)
    dspin = r.spin_out * rod.inertia
    assert dspin == pytest.approx(
        arm[0] * r.normal_impulse - arm[1] * r.tangential_impulse, rel=1e-9, abs=1e-15
    )
    # no energy gain (no slip reversal here)
    ke = lambda v, w: 0.5 * rod.mass * (v[0] ** 2 + v[1] ** 2) + 0.5 * rod.inertia * w * w  # noqa: E731
    assert ke(r.velocity_out, r.spin_out) <= ke((0.0, vy), 0.0) * (1 + 1e-12)


@pytest.mark.parametrize(
    ("velocity", "spin", "mu", "regime"),
    [
        ((0.5, -1.41), 0.0, 0.2, "reversal"),  # slides +x, stops, slides -x (mu < mu_c)
        ((0.5, -1.41), 0.0, 0.9, "stick"),
        ((-0.5, -1.41), 0.0, 0.2, "slip"),
        ((-0.3, -1.41), 0.0, 0.9, "stick"),
        ((0.0, -1.0), 4.0, 0.3, "reversal"),
        ((0.2, -2.0), 3.0, 0.0, "reversal"),
        ((0.2, -2.0), -3.0, 0.0, "slip"),
    ],
)
def test_phases_against_a_march_in_the_normal_impulse(velocity, spin, mu, regime):
    th = math.radians(35.0)
    r = rigid_impulse(PAPER_ROD, th, velocity, spin, e=0.6, mu=mu)
    assert r.regime == regime
    P, v = march(PAPER_ROD, th, velocity, spin, 0.6, mu)
    assert r.normal_impulse == pytest.approx(P[1], rel=1e-4)
    assert r.tangential_impulse == pytest.approx(P[0], rel=1e-4, abs=1e-6 * P[1])
    assert r.contact_velocity_out[0] == pytest.approx(v[0], abs=1e-4)


def test_sphere_rolls_off_and_bounces_normally():
    s = Sphere(0.01)
    r = rigid_impulse(s, 1.0, (0.5, -1.0), e=0.5, mu=1.0)
    assert r.regime == "stick" and r.mu_critical == 0.0
    assert r.velocity_out[0] == pytest.approx(5.0 / 7.0 * 0.5, rel=1e-12)  # rolling
    assert r.velocity_out[1] == pytest.approx(0.5, rel=1e-12)
    assert r.spin_out * s.radius == pytest.approx(-r.velocity_out[0], rel=1e-12)
    frictionless = rigid_impulse(s, 1.0, (0.5, -1.0), e=0.5, mu=0.0)
    assert frictionless.velocity_out == pytest.approx((0.5, 0.5), rel=1e-12)
    assert frictionless.spin_out == 0.0


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"angle": -0.1}, "angle"),
        ({"e": 1.5}, "e"),
        ({"mu": -0.1}, "mu"),
        ({"velocity": (0.0, 0.5)}, "approach"),
        ({"velocity": (-1.0, -1.0), "mu": 5.0}, "jam"),
    ],
)
def test_invalid_inputs(kwargs, name):
    base = {"angle": 0.5, "velocity": (0.0, -1.0), "e": 0.5, "mu": 0.2}
    base.update(kwargs)
    with pytest.raises(ValueError, match=name):
        rigid_impulse(PAPER_ROD, base.pop("angle"), base.pop("velocity"), **base)
