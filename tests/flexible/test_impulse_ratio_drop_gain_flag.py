"""A drop with the paper's ``impulse_ratio`` is flagged ENERGY_GAIN when, in one of its
contacts, the contact point slid along that contact's fixed friction force (positive work),
although every contact's net friction work is negative and the drop loses energy in total
(docs/flexible.md, "Flags"); ``coulomb`` and ``mindlin`` on the same inputs are not."""

from __future__ import annotations

from typing import Any

import impactlab as il
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_batch import simulate_drops
from impactlab.flags import ResultFlag

#: The flexible rod with initial slip and spin: three contacts; the first one's contact point
#: reverses onto the fixed force's direction.
DROP: dict[str, Any] = {
    "law": "thornton",
    "mu": 0.10336556571184946,
    "angle": 0.7591907578907198,
    "vx": 0.6581333055379617,
    "vy": -1.760278036349637,
    "spin": 26.34270118504491,
}
#: The rigid rod's case of tests/dynamics/test_impulse_ratio_gain_flag.py.
ROD: dict[str, Any] = {
    "law": "thornton",
    "mu": 0.092,
    "angle": 1.0096,
    "velocity": (-0.263, -1.206),
    "spin": 16.2,
}


def _single(case: dict[str, Any]) -> dict[str, Any]:
    kw = dict(case)
    kw["velocity"] = (kw.pop("vx"), kw.pop("vy"))
    return kw


def test_drop_flags_a_contact_that_slid_along_the_fixed_force() -> None:
    body = il.FlexibleRod.paper()
    r = simulate_drop(body, friction="impulse_ratio", **_single(DROP))
    assert r.n_contacts >= 2 and max(c.work_friction for c in r.contacts) < 0.0
    balance = r.energy_balance
    final = balance["rigid_kinetic"] + balance["vibration"] + balance["potential"]
    assert final < 0.9 * balance["initial"]  # no gain in total
    assert ResultFlag.ENERGY_GAIN in r.flags and not r.ok
    assert simulate_drops(body, friction="impulse_ratio", **DROP).flags[0] == int(r.flags)
    for friction in ("coulomb", "mindlin"):
        c = simulate_drop(body, friction=friction, **_single(DROP))
        assert ResultFlag.ENERGY_GAIN not in c.flags, friction


def test_rigid_limit_flags_equal_the_rigid_engine() -> None:
    for friction in ("impulse_ratio", "coulomb"):
        r0 = il.simulate(il.Rod.paper(), friction=friction, **ROD)
        r = simulate_drop(il.Rod.paper(), friction=friction, **ROD)
        assert r.flags == r0.flags
        assert (ResultFlag.ENERGY_GAIN in r.flags) == (friction == "impulse_ratio")
