"""Partial slip (Mindlin-Deresiewicz cells) in the flexible drop: the rigid limit equals the
rigid engine's ``partial_slip``, the energy balance closes over the whole sequence, and the
paper's flexible drop runs with finite outputs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from paper_drops import CASES

import impactlab
from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics import simulate
from impactlab.dynamics.drop import simulate_drop

#: (angle [deg], vx [m/s], vy [m/s], mu): the paper's drops, a large mu (the cells stick and
#: re-slip) and an initial slip against the rotation.
RIGID_CASES = [(th, 0.0, vy, mu) for th, vy, mu in CASES] + [
    (20, 0.0, -1.41, 0.9),
    (30, 0.4, -1.5, 0.3),
]


@pytest.mark.parametrize(("th", "vx", "vy", "mu"), RIGID_CASES)
def test_rigid_limit(th: float, vx: float, vy: float, mu: float) -> None:
    """A rigid Rod through the drop integrator with partial slip equals the rigid engine's
    partial slip to 1e-6 in e, delta_p, sliding_length, duration, P_t and the spin (each
    relative to its natural scale); the stick time (counted per accepted step) to 1e-5."""
    kw = {"friction": "partial_slip", "mu": mu, "angle": math.radians(th), "velocity": (vx, vy)}
    r0 = simulate(Rod.paper(), rtol=1e-10, **kw)
    r = simulate_drop(Rod.paper(), rtol=1e-10, **kw)
    assert r.n_contacts == 1 and r.friction == "partial_slip"
    pairs = {
        "e": (r.e_raw, r0.e, 1.0, 1e-6),
        "delta_p": (r.dent_depth, r0.delta_p, r0.delta_max, 1e-6),
        "sliding_length": (r.sequence_sliding_length, r0.sliding_length, r0.delta_max, 1e-6),
        "duration": (r.sequence_duration, r0.duration, r0.duration, 1e-6),
        "Pt": (r.tangential_impulse, r0.tangential_impulse, r0.normal_impulse, 1e-6),
        "spin": (r.spin_out, r0.spin_out, abs(vy) / 0.15, 1e-6),
        "stick": (r.stick_time, r0.stick_time, r0.duration, 1e-5),
    }
    for name, (a, b, scale, tol) in pairs.items():
        assert abs(a - b) <= tol * abs(scale), (name, a, b)
    assert r.flags == r0.flags


@pytest.mark.parametrize(("th", "vy", "mu"), CASES)
def test_energy_balance(th: float, vy: float, mu: float) -> None:
    """The flexible rod, zero damping, partial slip: T + V - E0 = W_n + W_t over the whole
    sequence (several contacts, the cells reset at each touch) to 1e-6 of E0; friction only
    dissipates (the cells are unloaded at every separation)."""
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False)
    kw = {"mu": mu, "angle": math.radians(th), "velocity": (0.0, vy)}
    r = simulate_drop(body, friction="partial_slip", rtol=1e-9, **kw)
    assert r.friction == "partial_slip" and r.n_contacts >= 1
    assert r.energy_error < 1e-6
    assert abs(r.energy_balance["residual"]) < 1e-6 * r.initial_energy
    assert r.work_damping == 0.0
    assert r.work_friction <= 1e-9 * r.initial_energy


def test_partial_slip_is_used() -> None:
    """On the flexible rod with sticking, partial slip differs from mindlin (same drop), and
    with mu = 0 it is the frictionless drop."""
    body = FlexibleRod.paper(n_axial=4, n_bending=8, axial_residual=False)
    kw = {"angle": math.radians(20), "velocity": (0.0, -1.41)}
    ps = simulate_drop(body, friction="partial_slip", mu=0.2, **kw)
    mi = simulate_drop(body, friction="mindlin", mu=0.2, **kw)
    assert abs(ps.sequence_sliding_length - mi.sequence_sliding_length) > 1e-8
    assert ps.stick_time > 0.0
    free = simulate_drop(body, friction="partial_slip", mu=0.0, **kw)
    ref = simulate_drop(body, friction="coulomb", mu=0.0, **kw)
    assert free.e == ref.e and free.dent_depth == ref.dent_depth


def test_paper_flexible_drop() -> None:
    """The paper's flexible rod (default modes) with partial slip through ``impactlab.simulate``:
    the drop runs, its outputs are finite and its history holds the tip's tangential force."""
    r = impactlab.simulate(
        FlexibleRod.paper(),
        friction="partial_slip",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
    )
    assert r.friction == "partial_slip" and r.ok
    values = [
        r.e,
        r.dent_depth,
        r.sequence_sliding_length,
        r.sequence_duration,
        r.delta_max,
        r.max_force,
    ]
    values += [r.sequence_mean_force, r.tangential_impulse, r.vibration_energy, r.energy_error]
    assert all(math.isfinite(v) for v in values)
    assert r.n_contacts >= 1 and r.energy_error < 1e-5
    assert r.history is not None
    assert np.all(np.isfinite(r.history.data))


def test_other_end_has_cells() -> None:
    """With ``stop="flight"`` the other end lands too: its contacts run on its own cells, the
    energy balance closes over both ends' contacts."""
    r = simulate_drop(
        Rod.paper(),
        friction="partial_slip",
        mu=0.2,
        angle=math.radians(20),
        velocity=(0.0, -1.41),
        stop="flight",
        rtol=1e-9,
    )
    ends = [c.end for c in r.contacts]
    assert 0 in ends and 1 in ends
    assert all(abs(c.tangential_impulse) > 0.0 for c in r.contacts)
    assert r.energy_error < 1e-6 and r.work_friction < 0.0
