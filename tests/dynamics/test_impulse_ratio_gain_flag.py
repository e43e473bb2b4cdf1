"""The paper's ``impulse_ratio`` (F_t = s mu F_n, s fixed over the contact) is flagged
ENERGY_GAIN wherever its contact point slid along that force: the force then did positive work
and created energy, even where the slip's earlier losses leave friction's net work negative
(docs/engine/index.md, "Result flags"). ``coulomb`` and ``mindlin`` on the same inputs are not.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics import OUTPUT_FIELDS, contact_model
from impactlab.dynamics.batch import run_arrays
from impactlab.flags import FLAG_ENERGY_GAIN, ResultFlag
from impactlab.friction import FRICTION_IDS
from impactlab.materials import AISI_1010

O = {n: i for i, n in enumerate(OUTPUT_FIELDS)}

#: A spinning sphere whose contact point reverses (-2.27 -> +2.25 m/s): friction does +0.50 E0
#: of positive work, its net work is -0.006 E0, and the total energy falls.
SPHERE: dict[str, Any] = {
    "law": "ghaednia",
    "mu": 0.8981207197103932,
    "velocity": (-1.2111249266200161, -1.0),
    "spin": -105.45911382192352,
}
#: The paper's rod with initial slip and spin, thornton: +0.008 E0 of positive work, net -0.049.
ROD: dict[str, Any] = {
    "law": "thornton",
    "mu": 0.092,
    "angle": 1.0096,
    "velocity": (-0.263, -1.206),
    "spin": 16.2,
}


def _friction_works(r: il.ImpactResult) -> tuple[float, float]:
    """(positive, net) work of friction over the contact [J], from the history."""
    h = r.history
    assert h is not None
    t = np.asarray(h.t)
    power = np.asarray(h.tangential_force) * np.asarray(h.slip_velocity)
    return float(np.trapezoid(np.clip(power, 0.0, None), t)), float(np.trapezoid(power, t))


@pytest.mark.parametrize(("body", "case"), [(il.Sphere(0.01), SPHERE), (il.Rod.paper(), ROD)])
def test_sliding_along_the_fixed_force_is_flagged(
    body: il.Sphere | il.Rod, case: dict[str, Any]
) -> None:
    r = il.simulate(body, friction="impulse_ratio", **case)
    positive, net = _friction_works(r)
    assert r.history is not None
    e0 = float(r.history.energy[0])
    # energy created during the contact, lost in friction's net work and in the total
    assert positive > 1e-3 * e0 and net < 0.0 and r.energy_dissipated > 0.0
    assert r.regime == "reversal" and np.sign(r.vt_out) != np.sign(r.vt_in)
    assert ResultFlag.ENERGY_GAIN in r.flags and not r.ok
    assert r.warnings[0].startswith("energy gain")
    for friction in ("coulomb", "mindlin"):
        c = il.simulate(body, friction=friction, **case)
        assert ResultFlag.ENERGY_GAIN not in c.flags and c.ok, friction


def test_impulse_ratio_sliding_one_way_is_not_flagged() -> None:
    """Below mu_c the paper's model is Coulomb's slip branch: no flag (the paper's 20 deg case)."""
    r = il.simulate(il.Rod.paper(), friction="impulse_ratio", mu=0.2, angle="20 deg",
                    velocity=(0.0, -1.41))  # fmt: skip
    assert r.regime == "slip" and ResultFlag.ENERGY_GAIN not in r.flags and r.ok


def test_flag_and_reversal_coincide_for_impulse_ratio() -> None:
    """Random spinning spheres through the batch runner: impulse_ratio is flagged ENERGY_GAIN
    exactly where its regime is ``reversal`` (the same slip-velocity tolerance); coulomb never."""
    rng = np.random.default_rng(3)
    n = 200
    body = il.Sphere(0.01)
    init = np.stack(
        [
            np.full(n, 0.5 * np.pi),
            rng.uniform(-2.0, 2.0, n),
            rng.uniform(-2.5, -0.2, n),
            rng.uniform(-200.0, 200.0, n),
        ],
        axis=1,
    )
    mu = rng.uniform(0.01, 1.0, n)
    model = contact_model(body, AISI_1010, "ghaednia")
    params = body.to_params(AISI_1010)
    out, status = run_arrays(model.law_id, FRICTION_IDS["impulse_ratio"], model.params, params,
                             init, mu)  # fmt: skip
    ok = status == 0
    gained = (out[ok, O["flags"]].astype(np.int64) & FLAG_ENERGY_GAIN) != 0
    reversal = out[ok, O["regime"]] == 3
    assert reversal.sum() > 50
    assert np.array_equal(gained, reversal)
    out, status = run_arrays(model.law_id, FRICTION_IDS["coulomb"], model.params, params, init, mu)
    assert not np.any(out[status == 0, O["flags"]].astype(np.int64) & FLAG_ENERGY_GAIN)


@pytest.mark.parametrize(("vx", "spin"), [(0.3, -60.0), (0.7, -140.0), (1.1, -220.0)])
def test_a_sphere_arriving_rolling_gets_no_tangential_impulse(vx: float, spin: float) -> None:
    """vx + spin R is 0 or 1.1e-16 m/s by round-off alone: the second gave the full mu F_n in
    the round-off's direction (the ball left at +1.30 m/s)."""
    sphere = il.Sphere(0.005, material=il.AISI_1010)
    r = il.simulate(sphere, il.AISI_1010, law="hertz", friction="impulse_ratio", mu=0.3,
                    velocity=(vx, -1.0), spin=spin, gravity=False)  # fmt: skip
    assert r.tangential_impulse == 0.0 and r.velocity_out[0] == vx and r.spin_out == spin
