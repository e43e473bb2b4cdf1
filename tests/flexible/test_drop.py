"""The flexible drop: the rigid limit, the energy balance, the contact bookkeeping, the end
criterion, convergence with the number of modes and the result object."""

from __future__ import annotations

import json
import math
from typing import Any

import numpy as np
import pytest
from paper_drops import CASES

from impactlab.bodies import Rod, Sphere
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics import simulate
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.dynamics.flexcore import drop
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.flight import flight
from impactlab.dynamics.flexcore.kinematics import end_kinematics
from impactlab.dynamics.flexcore.model import constants, model_tuple
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010

G = 9.80665


def flex_drop(th: float, vy: float, mu: float, body: FlexibleRod | Rod, **kw: Any) -> DropResult:
    return simulate_drop(body, angle=math.radians(th), velocity=(0.0, vy), mu=mu, **kw)


@pytest.mark.parametrize("law", ["ghaednia", "brake", "thornton", "hertz"])
@pytest.mark.parametrize(("th", "vy", "mu"), [*CASES, (45, -2.18, 0.0), (20, -1.41, 0.9)])
def test_rigid_limit(th: float, vy: float, mu: float, law: str) -> None:
    """A rigid Rod (no modes): every output of its one contact equals the rigid engine's to
    1e-6 (relative to the output's natural scale); slip, stick and frictionless covered."""
    rod = Rod.paper()
    r0 = simulate(
        rod,
        law=law,
        friction="coulomb",
        mu=mu,
        angle=math.radians(th),
        velocity=(0, vy),
        rtol=1e-10,
    )
    r = flex_drop(th, vy, mu, rod, law=law, rtol=1e-10)
    assert r.n_contacts == 1 and r.n_modes == 0
    c = r.contacts[0]
    pairs = {
        "e": (r.e_raw, r0.e, 1.0),
        "vx": (r.velocity_out[0], r0.velocity_out[0], abs(vy)),
        "vy": (r.velocity_out[1], r0.velocity_out[1], abs(vy)),
        "spin": (r.spin_out, r0.spin_out, abs(vy) / 0.15),
        "delta_p": (r.dent_depth, r0.delta_p, r0.delta_max),
        "delta_max": (r.delta_max, r0.delta_max, r0.delta_max),
        "duration": (r.sequence_duration, r0.duration, r0.duration),
        "slip": (r.sequence_sliding_length, r0.sliding_length, r0.delta_max),
        "travel": (c.x_end, r0.contact_travel, r0.delta_max),
        "max_force": (r.max_force, r0.max_force, r0.max_force),
        "Pn": (c.normal_impulse, r0.normal_impulse, r0.normal_impulse),
        "Pt": (c.tangential_impulse, r0.tangential_impulse, r0.normal_impulse),
        "stick": (c.stick_time, r0.stick_time, r0.duration),
        "angle": (r.angle_out, r0.angle_out, 1.0),
        "dissipated": (-(r.work_normal + r.work_friction), r0.energy_dissipated, r.initial_energy),
    }
    for name, (a, b, scale) in pairs.items():
        assert abs(a - b) <= 1e-6 * abs(scale), (name, a, b)


def test_rigid_limit_without_gravity() -> None:
    """Without gravity e and e_raw coincide and equal the rigid engine's e."""
    rod = Rod.paper()
    kw = {"mu": 0.2, "angle": math.radians(30), "velocity": (0.1, -1.5), "spin": 2.0}
    r0 = simulate(rod, gravity=False, rtol=1e-10, **kw)
    r = simulate_drop(rod, gravity=False, rtol=1e-10, **kw)
    assert r.e == r.e_raw
    assert r.e == pytest.approx(r0.e, abs=1e-6)


def test_stiff_rod_limit() -> None:
    """A rod 1e6 and 1e8 times stiffer: the deviation from the rigid engine is the
    quasi-static compliance of the modes, ~1/E; at 1e8 every output agrees to 1e-6."""
    th, vy, mu = CASES[0]
    r0 = simulate(Rod.paper(), mu=mu, angle=math.radians(th), velocity=(0, vy), rtol=1e-10)
    devs = []
    for f in (1e6, 1e8):
        stiff = FlexibleRod.paper(
            material=AISI_1010.__class__(
                "stiff", E=200e9 * f, nu=0.3, yield_strength=760e6, density=7800.0
            ),
            n_axial=2,
            n_bending=3,
            axial_residual=False,
            theory="euler-bernoulli",
        )
        r = flex_drop(
            th, vy, mu, stiff, law=contact_model(Rod.paper(), AISI_1010, "ghaednia"), rtol=1e-10
        )
        assert r.n_contacts == 1
        d = (
            np.array(
                [
                    r.e_raw / r0.e,
                    r.dent_depth / r0.delta_p,
                    r.sequence_duration / r0.duration,
                    r.sequence_sliding_length / r0.sliding_length,
                    r.velocity_out[1] / r0.velocity_out[1],
                    r.spin_out / r0.spin_out,
                ]
            )
            - 1.0
        )
        devs.append(np.abs(d))
    assert np.all(devs[1] < 1e-6)
    np.testing.assert_allclose(devs[0] / devs[1], 100.0, rtol=0.05)


@pytest.mark.parametrize("theory", ["timoshenko", "euler-bernoulli"])
@pytest.mark.parametrize(("th", "vy", "mu"), CASES)
def test_energy_balance(th: float, vy: float, mu: float, theory: str) -> None:
    """T + V - E0 = W_normal + W_friction (+ W_damping) over the whole sequence to 1e-6 of E0,
    with zero damping and with 2 % modal damping."""
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False, theory=theory)
    r = flex_drop(th, vy, mu, body, rtol=1e-9)
    assert r.energy_error < 1e-6
    assert abs(r.energy_balance["residual"]) < 1e-6 * r.initial_energy
    assert r.n_contacts >= 2  # the flexible rod re-contacts
    assert r.work_normal < 0 and r.work_friction <= 0 and r.work_damping == 0.0
    damped = FlexibleRod.paper(
        n_axial=4, n_bending=8, axial_residual=False, theory=theory, damping=0.02
    )
    rd = flex_drop(th, vy, mu, damped, rtol=1e-9)
    assert rd.energy_error < 1e-6 and rd.work_damping < 0


def test_energy_balance_geometric() -> None:
    """With the geometric stiffness (a cubic potential) the balance still closes to 1e-6."""
    th, vy, mu = CASES[2]
    body = FlexibleRod.paper(n_axial=4, n_bending=8, geometric=True)
    assert flex_drop(th, vy, mu, body, rtol=1e-9).energy_error < 1e-6


def test_bookkeeping() -> None:
    """Impulses, contact order, the plastic history and Coulomb's bound."""
    th, vy, mu = CASES[0]
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False)
    r = flex_drop(th, vy, mu, body, rtol=1e-9, history=True)
    m = body.mass
    pn = sum(c.normal_impulse for c in r.contacts)
    assert pn == pytest.approx(m * (r.velocity_out[1] - vy + G * r.sequence_duration), rel=1e-7)
    pt = sum(c.tangential_impulse for c in r.contacts)
    assert pt == pytest.approx(m * r.velocity_out[0], rel=1e-7)
    t0 = np.array([c.start for c in r.contacts])
    t1 = t0 + np.array([c.duration for c in r.contacts])
    assert np.all(np.diff(t0) > 0) and np.all(t0[1:] >= t1[:-1])
    assert t1[-1] == pytest.approx(r.sequence_duration, rel=1e-12)
    dr = np.array([c.delta_r for c in r.contacts])
    assert np.all(np.diff(dr) >= -1e-15)  # delta_r never decreases
    assert r.dent_depth == pytest.approx(dr.max(), rel=1e-12)
    assert all(c.reload and c.dent == 0 for c in r.contacts[1:])  # all in the first dent
    for i in range(1, len(r.contacts)):  # a reload below delta_m leaves delta_r unchanged
        if r.contacts[i].delta_max < max(c.delta_max for c in r.contacts[:i]):
            assert r.contacts[i].delta_r == pytest.approx(r.contacts[i - 1].delta_r, rel=1e-12)
    h = r.history
    assert h is not None and np.all(np.abs(h.tangential_force) <= mu * h.normal_force * (1 + 1e-9))
    assert np.max(np.abs(h["energy_balance_error"])) < 1e-6


def _raw_drop(
    th: float, vy: float, mu: float, body: FlexibleRod
) -> tuple[tuple[Any, ...], np.ndarray, np.ndarray]:
    """The compiled drop with its final state (the state where the end test passed)."""
    b = body.basis()
    model = contact_model(body.rigid(), AISI_1010, "ghaednia")
    p = kernel_params(model)
    c = constants(
        body.half_length, body.tip_radius, body.mass, b.inertia, G, math.radians(th), mu, p
    )
    mdl = model_tuple(model.law_id, p, c, b.omega, np.zeros(b.n_modes), b.U, b.W, b.Psi)
    out = np.empty(F.N_DROP_OUT)
    yfinal = np.zeros(6 + 2 * b.n_modes + F.NQUAD)
    st, *_ = drop(
        mdl,
        0.0,
        vy,
        0.0,
        F.DROP_DEFAULT_RTOL,
        0.5,
        0,
        False,
        out,
        np.zeros((F.MAX_CONTACTS, F.NCR)),
        np.zeros((F.MAX_DENTS, F.NDT)),
        yfinal,
    )
    assert st == F.ST_OK
    return mdl, out, yfinal


@pytest.mark.parametrize(("th", "vy", "mu"), CASES)
def test_end_criterion_is_conservative(th: float, vy: float, mu: float) -> None:
    """From the state where the sequence was declared over, the exact force-free motion keeps
    the tip clear of the flat until the horizon (C back at its height, or the other end's
    landing ``next_time``), on a dense time grid."""
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False)
    mdl, out, y0 = _raw_drop(th, vy, mu, body)
    M = body.basis().n_modes
    horizon = 2 * y0[3 + M + 1] / G if y0[3 + M + 1] > 0 else math.inf
    if out[F.O_NEXT_END] >= 0:
        horizon = min(horizon, out[F.O_NEXT_TIME] - (out[F.O_T_FINAL] - out[F.O_DURATION]))
    assert math.isfinite(horizon) and horizon > 0
    Jn = np.zeros((2, 3 + M))
    Jt = np.zeros((2, 3 + M))
    yt = np.empty_like(y0)
    c, Ue, We, Pe = mdl[2], mdl[7], mdl[8], mdl[9]
    deltas = []
    for tau in np.concatenate([np.linspace(0, 2e-3, 4001), np.linspace(2e-3, horizon, 4001)]):
        flight(mdl, y0, tau, yt)
        deltas.append(end_kinematics(c, Ue, We, Pe, yt, 0, Jn, Jt)[0])
    assert max(deltas) < 0.0  # interference of the tip w.r.t. the original surface


def test_axial_residual_helps() -> None:
    """The axial residual pseudo-modes move a 4-axial-mode model towards 64 axial modes."""
    th, vy, mu = CASES[2]
    e = {}
    for na, aug in ((4, False), (4, True), (64, False)):
        body = FlexibleRod.paper(n_axial=na, n_bending=12, axial_residual=aug)
        e[(na, aug)] = flex_drop(th, vy, mu, body).e
    assert abs(e[(4, True)] - e[(64, False)]) < 0.25 * abs(e[(4, False)] - e[(64, False)])


def test_mode_count_convergence() -> None:
    """At 45 deg the default basis (8 + 2 axial, 12 bending) is within 1 % of a (24 + 2, 24)
    basis in e, delta_p and duration with the same contact sequence; (4 + 2, 6) is not."""
    th, vy, mu = CASES[1]
    fine = flex_drop(th, vy, mu, FlexibleRod.paper(n_axial=24, n_bending=24))
    default = flex_drop(th, vy, mu, FlexibleRod.paper())
    coarse = flex_drop(th, vy, mu, FlexibleRod.paper(n_axial=4, n_bending=6))
    for q in ("e", "dent_depth", "sequence_duration"):
        assert getattr(default, q) == pytest.approx(getattr(fine, q), rel=0.01), q
    assert default.n_contacts == fine.n_contacts
    assert abs(coarse.e / fine.e - 1) > 0.03


def test_flight_mode_other_end() -> None:
    """stop='flight' integrates through the other end's impact (at 20 deg the rod rotates flat
    and its far end lands ~38 ms later) until the rod flies off; 'sequence' announces it."""
    th, vy, mu = CASES[0]
    body = FlexibleRod.paper(n_axial=4, n_bending=8)
    r = flex_drop(th, vy, mu, body, stop="flight", rtol=1e-8)
    ends = np.array([c.end for c in r.contacts])
    assert (ends == 1).any() and (ends == 0).any()
    t1 = min(c.start for c in r.contacts if c.end == 1)
    rs = flex_drop(th, vy, mu, body)
    assert rs.next_end == 1 and t1 >= rs.sequence_duration + rs.next_time * (1 - 1e-9)
    assert r.energy_error < 1e-5


def test_result_object() -> None:
    """The DropResult: contacts, totals, JSON-ready dict, summary text, references."""
    th, vy, mu = CASES[0]
    r = flex_drop(th, vy, mu, FlexibleRod.paper(), history=True)
    assert r.n_contacts == len(r.contacts) == 4
    d = r.to_dict(include_history=True)
    json.dumps(d)
    assert d["contacts"][0]["end"] == 0 and len(d["history"]["t"]) == len(r.history)
    text = str(r)
    assert "contacts" in text and "dent_depth" in text and "contact 4 (end 0)" in text
    assert "10.1115/1.3625046" in r.dois()  # Cowper's shear coefficient
    assert "10.1007/s00419-015-1108-2" in r.dois()
    h = r.history
    assert h.t[0] == 0.0 and h.tip_height[0] == pytest.approx(0.0, abs=1e-15)
    assert 0.0 < r.vibration_energy < r.initial_energy and r.scar_length > 0


def test_bad_input() -> None:
    """One clear ValueError per invalid argument."""
    rod = FlexibleRod.paper()
    ok = {"angle": 0.3, "velocity": (0.0, -1.0)}
    cases = [
        ({"body": Sphere(0.01)}, "body"),
        ({"friction": "nonsense"}, "friction"),
        ({"mu": -0.1}, "mu"),
        ({"angle": 30.0}, "angle"),
        ({"velocity": (0.0, 1.0)}, "approach"),
        ({"rate": "zerilli"}, "rate"),
        ({"stop": "never"}, "stop"),
        ({"time_limit": 0.0}, "time_limit"),
        ({"rtol": 1.0}, "rtol"),
    ]
    for kw, word in cases:
        args = {"body": rod, **ok, **kw}
        body = args.pop("body")
        with pytest.raises(ValueError, match=word):
            simulate_drop(body, **args)
    with pytest.raises(ValueError, match="time_limit"):
        simulate_drop(rod, **ok, time_limit=1e-5)
