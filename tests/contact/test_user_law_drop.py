"""A contact law of one's own (``register_law``, sampled callables) in the drop: it runs in
``simulate_drop`` for a rigid rod and a small flexible rod and in ``simulate_drops``, the batch
equals the drops one by one to the last bit, and no drop gains energy."""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest

import impactlab as il
from impactlab.contact import register_law, unregister_law
from impactlab.contact._common import jg_critical
from impactlab.contact.registered import RegisteredLaw
from impactlab.flags import ResultFlag
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = il.Rod.paper().tip_radius
DC, FC = jg_critical(PAIR.E_star, R, PAIR.yield_strength, PAIR.nu)
NAME = "toy-drop-law"

#: The drops: steep and shallow, with Coulomb friction.
ANGLES = np.radians([20.0, 40.0])
KW = {"vy": -1.4, "mu": 0.2, "friction": "coulomb"}

#: The outputs compared between the batch and the drops one by one (DropResult's names).
COMPARED = (
    "e",
    "e_raw",
    "delta_max",
    "dent_depth",
    "max_force",
    "normal_impulse",
    "tangential_impulse",
    "sequence_duration",
    "n_contacts",
    "rigid_kinetic_energy",
    "vibration_energy",
    "potential_energy",
    "work_normal",
    "work_friction",
    "work_damping",
    "initial_energy",
    "max_delta_ratio",
)

BODIES = {
    "rigid rod": il.Rod.paper(),
    "flexible rod": il.FlexibleRod.paper(n_axial=1, n_bending=2),
}


def _loading(delta: float) -> float:
    """Hertz up to delta_c, then a softer power law (F/F_Hertz falls: energy is dissipated)."""
    if delta <= DC:
        return 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * delta**1.5
    return FC * (delta / DC) ** 1.3


def _unloading(delta_max: float) -> float:
    """delta_r: 0 up to delta_c, then a growing share of delta_max."""
    return 0.0 if delta_max <= DC else 0.6 * delta_max * (1.0 - math.sqrt(DC / delta_max))


@pytest.fixture(scope="module")
def toy() -> Iterator[RegisteredLaw]:
    law = register_law(
        NAME, loading=_loading, unloading=_unloading, pair=PAIR, radius=R, delta_max=400 * DC
    )
    yield law
    unregister_law(NAME)  # the other tests see the built-in laws only


@pytest.mark.parametrize("body", list(BODIES.values()), ids=list(BODIES))
def test_a_registered_law_drops_as_a_batch_and_alone(
    toy: RegisteredLaw, body: il.Rod | il.FlexibleRod
) -> None:
    drops = il.simulate_drops(body, AISI_1010, angle=ANGLES, law=NAME, **KW)
    assert drops.law == NAME and drops.computed.all(), drops.messages
    for i, angle in enumerate(ANGLES):
        one = il.simulate_drop(
            body,
            AISI_1010,
            angle=float(angle),
            velocity=(0.0, KW["vy"]),
            mu=KW["mu"],
            friction=KW["friction"],
            law=NAME,
        )
        assert one.law == NAME
        for name in COMPARED:
            assert drops[name][i] == getattr(one, name), (name, drops[name][i], getattr(one, name))
        assert drops.flags[i] == int(one.flags)
        # the law dissipates: a dent, negative work of the normal forces, and the energy after
        # the last contact below the initial one
        assert ResultFlag.ENERGY_GAIN not in one.flags
        assert one.dent_depth > 0.0 and one.work_normal < 0.0
        after = one.rigid_kinetic_energy + one.vibration_energy + one.potential_energy
        assert after < one.initial_energy
        assert abs(one.energy_balance["residual"]) <= 1e-6 * one.initial_energy
        # by name as by its model: the registry gives the drop the law's own model
        model = il.simulate_drop(
            body,
            AISI_1010,
            angle=float(angle),
            velocity=(0.0, KW["vy"]),
            mu=KW["mu"],
            friction=KW["friction"],
            law=toy.build(PAIR, R),
        )
        assert (model.e, model.dent_depth) == (one.e, one.dent_depth)
