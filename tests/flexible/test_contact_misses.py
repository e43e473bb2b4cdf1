"""No contact of the flexible drop is missed: a grazing separation followed by a re-contact is
located (the event search arms the touch that restarts a hair inside its dent), and the drop's
contact invariant refuses any miss it could not locate (docs/flexible.md, "Contact invariant").
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.flexcore import layout as F

#: A Mindlin drop near the paper's 20 deg case whose third contact ends grazing: the tip leaves
#: its dent with almost no normal speed and comes back within one step.
GRAZING = {
    "friction": "mindlin",
    "mu": 0.2,
    "angle": math.radians(18.09047091554801),
    "velocity": (0.0, -1.4718640078156635),
}


def _deepest_miss(r: il.DropResult) -> float:
    """How far [m] the tip lay below its deepest dent while its force was zero (history)."""
    h = r.history
    assert h is not None
    dr = max(d.delta_p for d in r.dents if d.end == 0)
    return float(((h["penetration_0"] - dr) * (h["normal_force_0"] == 0.0)).max(initial=0.0))


def test_grazing_recontact_is_located() -> None:
    r = simulate_drop(FlexibleRod.paper(), history=True, **GRAZING)
    ref = simulate_drop(FlexibleRod.paper(), rtol=1e-9, **GRAZING)
    assert r.n_contacts == ref.n_contacts == 6
    assert r.e == pytest.approx(ref.e, rel=1e-4)
    assert r.dent_depth == pytest.approx(ref.dent_depth, rel=1e-4)
    assert r.ok
    # the tip never lies below its dent's surface with zero force (beyond round-off)
    assert _deepest_miss(r) < 1e-6 * r.delta_max


def test_grazing_recontact_through_simulate() -> None:
    r = il.simulate(il.FlexibleRod.paper(), friction="mindlin", mu=0.2,
                    angle="18.09047091554801 deg", velocity=(0.0, -1.4718640078156635))  # fmt: skip
    assert r.n_contacts == 6
    assert r.e == pytest.approx(0.72391, abs=2e-4)


def test_paper_drop_impulse_ratio_rate_has_no_false_law_limit() -> None:
    """A missed re-contact let the tip fall through its dent until the law's validity limit."""
    r = simulate_drop(FlexibleRod.paper(), friction="impulse_ratio", mu=0.2, rate="cowper-symonds",
                      angle=math.radians(20), velocity=(0.0, -1.41), history=True)  # fmt: skip
    assert r.dent_depth < 60e-6
    assert _deepest_miss(r) < 1e-6 * r.delta_max


def test_coarse_rod_slow_drop_has_no_false_law_limit() -> None:
    r = il.simulate(il.FlexibleRod.paper(n_axial=2, n_bending=4), friction="coulomb", mu=0.2,
                    angle="45 deg", velocity=(0, -0.5))  # fmt: skip
    ref = il.simulate(il.FlexibleRod.paper(n_axial=2, n_bending=4), friction="coulomb", mu=0.2,
                      angle="45 deg", velocity=(0, -0.5), rtol=1e-10)  # fmt: skip
    assert r.n_contacts == ref.n_contacts
    assert r.e == pytest.approx(ref.e, rel=1e-3)
    assert np.isfinite(r.dent_depth) and 0.0 <= r.dent_depth <= r.delta_max


def test_missed_contact_status_is_a_clear_error() -> None:
    """The invariant's status has a message that names the tolerance, in the one status table
    every engine and the sweep share."""
    from impactlab.dynamics import STATUS_MESSAGES
    from impactlab.dynamics.drop_checks import status_error
    from impactlab.dynamics.models import contact_model
    from impactlab.materials import AISI_1010

    model = contact_model(il.Rod.paper(), AISI_1010, "ghaednia")
    err = status_error(F.ST_MISSED_CONTACT, model)
    assert err.status == F.ST_MISSED_CONTACT
    assert "missed contact" in str(err) and "rtol" in str(err)
    assert STATUS_MESSAGES[F.ST_MISSED_CONTACT] == F.STATUS_MESSAGES[F.ST_MISSED_CONTACT]
