"""Coulomb friction of the flexible drop across a slip reversal: where the slip velocity v_t
reaches zero and the contact slips back, the rod's modes can swing v_t through zero and back
within one step; the slip direction then follows v_t, so friction never pushes along the slip
(no positive friction work in any contact)."""

from __future__ import annotations

import math

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.flags import ResultFlag

#: The drop (2 deg, vy = -1.41 m/s, mu = 0.4, ghaednia) whose third contact reverses its slip
#: with v_t oscillating about zero right after the reversal.
KW = {
    "law": "ghaednia",
    "friction": "coulomb",
    "mu": 0.4,
    "angle": math.radians(2.0),
    "velocity": (0.0, -1.41),
}


def test_friction_opposes_slip_after_reversal() -> None:
    """Every contact's friction work W_t [J] is negative (none above 1e-9 of E0), the slip
    path covers the net slip [m], the largest friction power F_t v_t [W] stays at the
    tolerance level (1e-6 of the largest |F_t| |v_t| of the drop) and the drop has no energy
    gain."""
    r = simulate_drop(FlexibleRod.paper(), **KW)
    e0 = r.initial_energy
    for c in r.contacts:
        assert c.work_friction <= 1e-9 * e0, c
        assert c.slip_path >= abs(c.sliding_length) * (1.0 - 1e-6), c
    df = r.history.to_dataframe()
    power = df.tangential_force_0 * df.slip_velocity_0
    assert power.max() <= 1e-6 * power.abs().max()
    assert not r.flags & ResultFlag.ENERGY_GAIN


def test_slip_reversal_converged_in_tolerance() -> None:
    """The default tolerance gives the sequence of rtol = 1e-10: the same number of contacts,
    e to 1e-5."""
    r = simulate_drop(FlexibleRod.paper(), **KW)
    r_fine = simulate_drop(FlexibleRod.paper(), rtol=1e-10, **KW)
    assert r.n_contacts == r_fine.n_contacts
    assert abs(r.e - r_fine.e) <= 1e-5
