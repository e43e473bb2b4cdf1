"""The closed forms against independent constructions: the rigid-body 2x2 impulse relations
built from vectors and a mass matrix, and a direct ODE integration of a rod on a plastic spring."""

from __future__ import annotations

import math
from types import SimpleNamespace

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.integrate import solve_ivp

from impactlab import analytic as an
from impactlab.bodies import Rod


def rigid_body_delassus(angle, length, tip_radius, mass, inertia):
    """W with dv_O = W @ (P_x, P_y), from the kinematics of a rigid body (no closed forms):
    the tip O is found by walking from C down the rod axis to the tip sphere's centre S and then
    R straight down; dv = M^-1 J^T p and dv_O = J dv with J the velocity Jacobian of O."""
    C = np.zeros(2)
    axis = np.array([math.cos(angle), math.sin(angle)])  # from the tip towards C
    S = C - 0.5 * length * axis
    O = S - np.array([0.0, tip_radius])
    r = O - C
    J = np.array([[1.0, 0.0, -r[1]], [0.0, 1.0, r[0]]])  # v_O = v_C + omega k x r
    Minv = np.diag([1.0 / mass, 1.0 / mass, 1.0 / inertia])
    return J @ Minv @ J.T


geometry = st.fixed_dictionaries(
    {
        "angle": st.floats(0.02, math.pi / 2 - 0.02),
        "length": st.floats(0.02, 2.0),
        "tip_radius": st.floats(1e-4, 0.05),
        "mass": st.floats(0.01, 10.0),
        "ratio": st.floats(0.02, 0.25),  # I_C / (m L^2): a slender rod to all mass at the ends
    }
).filter(lambda g: g["tip_radius"] <= 0.5 * g["length"])  # a Rod refuses a wider tip


@settings(max_examples=60, deadline=None)
@given(geo=geometry, mu=st.floats(0.0, 1.5))
def test_alpha_and_K_from_the_rigid_body_matrix(geo, mu):
    rod = Rod(
        length=geo["length"],
        tip_radius=geo["tip_radius"],
        mass=geo["mass"],
        inertia=geo["ratio"] * geo["mass"] * geo["length"] ** 2,
    )
    W = rigid_body_delassus(geo["angle"], rod.length, rod.tip_radius, rod.mass, rod.inertia)
    dv = W @ np.array([mu, 1.0])  # unit normal impulse, friction impulse mu towards +x
    K_x, K_y = an.impulse_coefficients(geo["angle"], mu, rod)
    assert K_x == pytest.approx(dv[0], rel=1e-9, abs=1e-12 * abs(dv[1]))
    assert K_y == pytest.approx(dv[1], rel=1e-9)
    assert an.alpha(geo["angle"], mu, rod) == pytest.approx(dv[0] / dv[1], rel=1e-9, abs=1e-12)


@settings(max_examples=60, deadline=None)
@given(geo=geometry)
def test_alpha_changes_sign_exactly_at_mu_c(geo):
    rod = Rod(
        length=geo["length"],
        tip_radius=geo["tip_radius"],
        mass=geo["mass"],
        inertia=geo["ratio"] * geo["mass"] * geo["length"] ** 2,
    )
    th = geo["angle"]
    mu_c = an.critical_friction(th, rod)
    # at mu_c the friction impulse exactly cancels the tip's tangential velocity (matrix form)
    W = rigid_body_delassus(th, rod.length, rod.tip_radius, rod.mass, rod.inertia)
    assert W[0, 0] * mu_c + W[0, 1] == pytest.approx(0.0, abs=1e-9 * abs(W[0, 1]))
    assert abs(an.alpha(th, mu_c, rod)) < 1e-9
    assert an.alpha(th, mu_c * (1 - 1e-6), rod) < 0 < an.alpha(th, mu_c * (1 + 1e-6), rod)
    # K_y stays positive throughout the sliding regime
    _, K_y = an.impulse_coefficients(th, np.linspace(0, mu_c, 7), rod)
    assert np.all(K_y > 0)


def test_vectorised_and_paper_rod_default():
    th = np.radians([20.0, 45.0, 70.0])
    mu = np.array([[0.0], [0.2]])
    a = an.alpha(th, mu)
    assert a.shape == (2, 3)
    for i in range(2):
        for j in range(3):
            assert a[i, j] == pytest.approx(an.alpha(th[j], mu[i, 0]))
    a_, b_ = an.lever_arms(0.1524, 0.0088, th)  # (L/2, R, angle)
    assert a_[0] == pytest.approx(0.1524 * math.cos(th[0]))
    assert b_[2] == pytest.approx(0.1524 * math.sin(th[2]) + 0.0088)


def test_hand_numbers_20_deg():
    """Written out by hand for the paper's rod: m = 0.4607, L = 0.3048, R = 0.0088, k^2 = L^2/12."""
    a = 0.1524 * 0.9396926  # 0.143209
    b = 0.1524 * 0.3420201 + 0.0088  # 0.060924
    k2 = 0.3048**2 / 12  # 0.0077419
    assert an.critical_friction(math.radians(20)) == pytest.approx(a * b / (k2 + b * b), rel=1e-6)
    assert an.critical_friction(math.radians(20)) == pytest.approx(0.7618, abs=1e-4)
    assert an.alpha(math.radians(20), 0.2) == pytest.approx(-0.2427, abs=1e-4)
    assert an.alpha(math.radians(45), 0.13) == pytest.approx(-0.5523, abs=1e-4)
    assert an.critical_friction(math.radians(70)) == pytest.approx(0.2568, abs=1e-4)


# ---------------------------------------------------------------------------------------------
# A rod integrated in time on an elastic-plastic spring: Eq. 12, the F T identity and Eq. 28
# ---------------------------------------------------------------------------------------------


def integrate_rod(angle, mu, v_i, rod, *, g=0.0, k=2e9, residual=0.4):
    """Rigid rod at constant angle, tip force F = k d^1.5 on loading, a stiffer power law down to
    a residual depth on unloading; friction F_x = mu F_y towards +x. Returns the measurements."""
    r = np.array(
        [-0.5 * rod.length * math.cos(angle), -0.5 * rod.length * math.sin(angle) - rod.tip_radius]
    )  # C -> O
    m, inertia = rod.mass, rod.inertia
    state = {"dm": 0.0, "fm": 0.0}

    def force(d, loading):
        if loading:
            return k * max(d, 0.0) ** 1.5
        dr = residual * state["dm"]
        return state["fm"] * (max(d - dr, 0.0) / (state["dm"] - dr)) ** 1.5

    def rhs(loading):
        def f(t, y):
            vcx, vcy, w, _xo, yo, _imp, _xs = y
            fy = force(-yo, loading)
            fx = mu * fy
            return [
                fx / m,
                fy / m - g,
                (r[0] * fy - r[1] * fx) / inertia,
                vcx - w * r[1],
                vcy + w * r[0],
                fy,
                vcx - w * (r[1] + rod.tip_radius),
            ]

        return f

    def vmax(t, y):  # tip normal velocity crosses zero: maximum depth
        return y[1] + y[2] * r[0]

    vmax.terminal = True
    vmax.direction = 1
    y0 = [0.0, v_i, 0.0, 0.0, 0.0, 0.0, 0.0]
    s1 = solve_ivp(rhs(True), (0, 1.0), y0, events=vmax, rtol=1e-11, atol=1e-15, max_step=1e-6)
    y1 = s1.y[:, -1]
    state["dm"] = -y1[4]
    state["fm"] = force(state["dm"], True)

    def sep(t, y):
        return -y[4] - residual * state["dm"]

    sep.terminal = True
    sep.direction = -1
    s2 = solve_ivp(
        rhs(False), (s1.t[-1], 1.0), y1, events=sep, rtol=1e-11, atol=1e-15, max_step=1e-6
    )
    yT = s2.y[:, -1]
    vox = np.concatenate([s1.y[0] - s1.y[2] * r[1], s2.y[0] - s2.y[2] * r[1]])
    return {
        "T": s2.t[-1],
        "delta_p": yT[4],
        "L_s": yT[3],
        "impulse": yT[5],
        "dv_cx": yT[0],
        "dv_cy": yT[1] - v_i,
        "e": (yT[1] + yT[2] * r[0]) / abs(v_i),
        "max_vox": float(vox[1:].max()),
        "travel": yT[6],
    }


@pytest.mark.parametrize(("angle_deg", "mu"), [(20, 0.2), (45, 0.13), (70, 0.1), (30, 0.0)])
def test_equation_12_and_identities_against_ode(angle_deg, mu):
    rod = Rod(length=0.3048, tip_radius=0.0088, mass=0.4607)
    th = math.radians(angle_deg)
    v_i = -1.5
    sim = integrate_rod(th, mu, v_i, rod)
    assert sim["max_vox"] < 0  # the tip slides towards -x throughout
    assert sim["delta_p"] < 0 and sim["L_s"] < 0
    # Eq. 12 (sign fixed): L_s = alpha (delta_p - v_i T)
    ls = an.sliding_length(-sim["delta_p"], v_i, sim["T"], th, mu, rod)  # depth >= 0
    assert ls == pytest.approx(sim["L_s"], rel=1e-6)
    # inversion recovers the duration
    T = an.impact_duration(-sim["delta_p"], -sim["L_s"], v_i, an.alpha(th, mu, rod))
    assert T == pytest.approx(sim["T"], rel=1e-6)
    # the contact patch (tip sphere centre) travels less than the material point slips
    travel = an.sliding_length(-sim["delta_p"], v_i, sim["T"], th, mu, rod, measure="travel")
    assert travel == pytest.approx(sim["travel"], rel=1e-6)
    assert abs(sim["travel"]) < abs(sim["L_s"])
    r = an.invert(
        angle=th,
        v_i=v_i,
        mu=mu,
        delta_p=-sim["delta_p"],
        sliding_length=-sim["travel"],
        e=sim["e"],
        rod=rod,
        measure="travel",
        n_samples=100,
    )
    assert r.duration == pytest.approx(sim["T"], rel=1e-6)
    # F T = (1 + e)|v_i| / K_y and F T = m dv_Cy
    _, K_y = an.impulse_coefficients(th, mu, rod)
    assert (1 + sim["e"]) * abs(v_i) / K_y == pytest.approx(sim["impulse"], rel=1e-6)
    assert an.mean_force_rigid(T, sim["e"], v_i, K_y) * T == pytest.approx(sim["impulse"], rel=1e-6)
    assert an.mean_force_momentum(T, rod.mass, sim["dv_cy"]) * T == pytest.approx(
        sim["impulse"], rel=1e-6
    )
    # Eq. 28
    if mu > 0:
        assert an.friction_from_velocities(sim["dv_cx"], sim["dv_cy"]) == pytest.approx(
            mu, rel=1e-6
        )


def test_gravity_forms_against_ode():
    rod = Rod(length=0.3048, tip_radius=0.0088, mass=0.4607)
    th, mu, v_i, g = math.radians(20), 0.2, -1.41, 9.80665
    sim = integrate_rod(th, mu, v_i, rod, g=g, k=5e7)  # soft: long contact, gravity matters
    al = an.alpha(th, mu, rod)
    T_g = an.impact_duration(-sim["delta_p"], -sim["L_s"], v_i, al, gravity=True, g=g)
    T_0 = an.impact_duration(-sim["delta_p"], -sim["L_s"], v_i, al)
    assert T_g == pytest.approx(sim["T"], rel=1e-6)
    assert T_0 > T_g * 1.001  # neglecting gravity overestimates T
    _, K_y = an.impulse_coefficients(th, mu, rod)
    F = an.mean_force_rigid(T_g, sim["e"], v_i, K_y, gravity=True, g=g)
    assert F * T_g == pytest.approx(sim["impulse"], rel=1e-6)
    Fm = an.mean_force_momentum(T_g, rod.mass, sim["dv_cy"], gravity=True, g=g)
    assert Fm * T_g == pytest.approx(sim["impulse"], rel=1e-6)
    mu_est = an.friction_from_velocities(sim["dv_cx"], sim["dv_cy"], duration=T_g, g=g)
    assert mu_est == pytest.approx(mu, rel=1e-6)
    r = an.invert(
        angle=th,
        v_i=v_i,
        mu=mu,
        delta_p=-sim["delta_p"],
        sliding_length=-sim["L_s"],
        e=sim["e"],
        dv_cy=sim["dv_cy"],
        rod=rod,
        gravity=True,
        n_samples=200,
    )
    assert r.duration == pytest.approx(sim["T"], rel=1e-6)
    assert r.mean_force == pytest.approx(sim["impulse"] / sim["T"], rel=1e-6)
    assert r.F_rigid == pytest.approx(r.mean_force, rel=1e-6)


def test_sticking_regime_errors():
    th = math.radians(70)
    mu_c = an.critical_friction(th)
    with pytest.raises(ValueError, match="sticking"):
        an.invert(angle=th, v_i=-3.45, e=0.05, mu=mu_c, delta_p=105e-6, sliding_length=200e-6)
    with pytest.raises(ValueError, match="sticking"):
        an.invert(angle=th, v_i=-3.45, e=0.05, mu=0.5, delta_p=105e-6, sliding_length=200e-6)
    with pytest.raises(ValueError, match="alpha"):
        an.impact_duration(1e-5, 1e-4, -1.0, an.alpha(th, 0.5))
    with pytest.raises(ValueError, match="sticking"):
        an.sliding_length(1e-5, -1.0, 1e-3, th, 0.3)


@pytest.mark.parametrize(
    ("kwargs", "name"),
    [
        ({"angle": 20.0}, "angle"),  # degrees passed as radians
        ({"angle": 0.0}, "angle"),
        ({"v_i": 0.0}, "v_i"),
        ({"mu": -0.1}, "mu"),
        ({"e": 1.2}, "e"),
        ({"sliding_length": 0.0}, "^sliding_length must be non-zero"),  # the keyword
        ({"delta_p": float("nan")}, "delta_p"),
        ({"mu": (0.2, -0.01)}, "mu"),
        ({"mu": (0.2, 0.01, 3)}, "mu"),
        ({"n_samples": 10}, "n_samples"),
        ({"rod": object()}, "rod"),
        ({"e": None}, "e or dv_cy"),
        ({"dv_cy": -0.5}, "dv_cy"),
    ],
)
def test_invalid_inputs_name_the_parameter(kwargs, name):
    base = dict(
        angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1400e-6
    )
    base.update(kwargs)
    with pytest.raises(ValueError, match=name):
        an.invert(**base)


def test_vectorised_inputs_validated():
    with pytest.raises(ValueError, match="angle"):
        an.alpha([0.1, 2.0], 0.2)
    with pytest.raises(ValueError, match="mu"):
        an.alpha(0.3, [0.1, -0.2])
    with pytest.raises(ValueError, match=r"rod\.mass"):
        an.alpha(0.3, 0.1, SimpleNamespace(mass=-1.0, length=0.3, tip_radius=0.01, inertia=None))
    with pytest.raises(ValueError, match="mass"):
        Rod(length=0.3, tip_radius=0.01, mass=-1.0)


def test_bodies_rod_is_accepted():
    rod = Rod.paper()
    assert an.alpha(0.4, 0.1, rod) == pytest.approx(an.alpha(0.4, 0.1))


@pytest.mark.parametrize(
    ("call", "name"),
    [
        (lambda: an.sliding_length(-1e-5, -1.0, 1e-3, 0.3, 0.1), "delta_p"),
        (lambda: an.impact_duration(-1e-5, 1e-4, -1.0, -0.2), "delta_p"),
        (
            lambda: an.invert(
                angle=0.35, v_i=-1.41, e=0.5, mu=0.2, delta_p=-22e-6, sliding_length=1400e-6
            ),
            "delta_p",
        ),
    ],
)
def test_paper_signs_are_refused_with_the_convention(call, name):
    """The paper prints delta_p negative (the final tip height); the library's is a depth."""
    with pytest.raises(ValueError, match=f"{name}.*magnitude.*paper's tables print it negative"):
        call()


def test_a_signed_sliding_length_and_either_sign_of_v_i_are_read_as_magnitudes():
    """The engine's sliding_length is signed (along +x, negative in gross sliding) and v_i's
    sign is ignored: the closed forms and ``invert`` take either sign, so that a simulated
    impact's own outputs invert as they come."""
    al = an.alpha(0.35, 0.2)
    T = an.impact_duration(22e-6, 1.4e-3, -1.41, al)
    assert an.impact_duration(22e-6, -1.4e-3, 1.41, al) == T
    L = an.sliding_length(22e-6, -1.41, T, 0.35, 0.2)
    assert an.sliding_length(22e-6, 1.41, T, 0.35, 0.2) == L and L == pytest.approx(-1.4e-3)
    kw = {"angle": 0.35, "v_i": -1.41, "e": 0.5, "mu": 0.2, "delta_p": 22e-6}
    a = an.invert(**kw, sliding_length=1400e-6)
    assert an.invert(**kw, sliding_length=-1400e-6).duration == a.duration
    with pytest.raises(ValueError, match="v_i must be non-zero"):
        an.sliding_length(22e-6, 0.0, T, 0.35, 0.2)


def test_closed_forms_take_units_and_refuse_text():
    assert an.alpha("20 deg", 0.2) == pytest.approx(an.alpha(math.radians(20), 0.2), rel=1e-15)
    T = an.impact_duration("22 um", "1.4 mm", "-1.41 m/s", an.alpha(math.radians(20), 0.2))
    assert T == pytest.approx(an.impact_duration(22e-6, 1.4e-3, -1.41, an.alpha(0.349066, 0.2)))
    with pytest.raises(ValueError, match=r"mu must be a real number, got the string '0.2'"):
        an.alpha(0.3, "0.2")
    with pytest.raises(ValueError, match="angle: the string '20' has no unit"):
        an.alpha("20", 0.2)
    with pytest.raises(ValueError, match="mu must hold real numbers, got an array of bools"):
        an.alpha(0.3, [True, False])
