"""``impactlab.simulate`` with a FlexibleRod: the flexible drop, a DropResult with
the summary attributes of ImpactResult; the drop's options pass through; simulate_batch refuses
a FlexibleRod clearly."""

from __future__ import annotations

import math

import pytest

import impactlab
from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.drop_result import DropResult
from impactlab.flags import ResultFlag

BODY = FlexibleRod.paper(n_axial=2, n_bending=4, axial_residual=False)
KW = {"law": "ghaednia", "friction": "coulomb", "mu": 0.2, "velocity": (0.0, -1.41)}
#: ImpactResult's summary attributes a drop reads over its sequence (the totals of another
#: meaning under names of their own: impactlab.schema.SEQUENCE_FIELDS).
SUMMARY = ("e", "dent_depth", "sequence_sliding_length", "sequence_duration", "delta_max")
SUMMARY += ("sequence_mean_force",)
SUMMARY += ("max_force", "flags", "warnings", "ok", "references")


def test_simulate_dispatches_to_the_drop() -> None:
    """simulate(FlexibleRod, ...) is simulate_drop with the same inputs (units as strings
    accepted as in simulate)."""
    r = impactlab.simulate(BODY, angle="20 deg", spin="0 rad/s", **KW)
    ref = simulate_drop(BODY, angle=math.radians(20), history=True, **KW)
    assert isinstance(r, DropResult)
    assert r.e == ref.e and r.dent_depth == ref.dent_depth and r.n_contacts == ref.n_contacts
    assert r.history is not None  # simulate's default history=True
    for name in SUMMARY:
        assert hasattr(r, name), name
    want = r.normal_impulse / r.sequence_duration
    assert r.sequence_mean_force == pytest.approx(want, rel=1e-15)
    assert r.ok and r.flags == ref.flags and not r.flags & ~ResultFlag.LAW_EXTRAPOLATED
    assert "10.1007/s00419-015-1108-2" in r.dois()


def test_drop_options_pass_through() -> None:
    """rate, stop and time_limit reach the drop."""
    a = impactlab.simulate(BODY, angle=0.6, stop="flight", time_limit=0.3, history=False, **KW)
    b = simulate_drop(BODY, angle=0.6, stop="flight", time_limit=0.3, **KW)
    assert a.n_contacts == b.n_contacts and a.e == b.e
    with pytest.raises(ValueError, match="time_limit"):
        impactlab.simulate(BODY, angle=0.6, time_limit=1e-6, **KW)
    r = impactlab.simulate(BODY, angle=0.6, rate="cowper-symonds", history=False, **KW)
    assert r.rate == "cowper-symonds" and r.rate_factor > 1.0


def test_bad_combinations() -> None:
    """A drop option with a rigid body or an unknown keyword: TypeError naming it;
    constant_angle or a missing angle with a FlexibleRod: ValueError."""
    with pytest.raises(TypeError, match="got time_limit: options of a FlexibleRod's drop"):
        impactlab.simulate(Rod.paper(), angle=0.3, time_limit=0.1, **KW)
    with pytest.raises(TypeError, match="n_modes; it takes angle"):
        impactlab.simulate(BODY, angle=0.3, n_modes=3, **KW)
    for body in (Rod.paper(), BODY):  # a typo is named with the keyword it resembles
        with pytest.raises(TypeError, match=r"mue \(did you mean 'mu'\?\)"):
            impactlab.simulate(body, angle=0.3, mue=0.2, velocity=(0.0, -1.41))
    for body in (Rod.paper(), BODY):  # simulate_batch's velocity names: simulate's is named
        with pytest.raises(ValueError, match=r"velocity=\(vx, vy\) \[m/s\], not vy="):
            impactlab.simulate(body, angle=0.3, vy=-1.41)
    with pytest.raises(ValueError, match="constant_angle"):
        impactlab.simulate(BODY, angle=0.3, constant_angle=True, **KW)
    with pytest.raises(ValueError, match="angle"):
        impactlab.simulate(BODY, **KW)


def test_rigid_bodies_unchanged() -> None:
    """A rigid Rod still gets the rigid engine's ImpactResult."""
    r = impactlab.simulate(Rod.paper(), angle=math.radians(20), **KW)
    assert isinstance(r, impactlab.ImpactResult) and round(r.e, 2) == 0.42


def test_simulate_batch_refuses_a_flexible_rod() -> None:
    """simulate_batch runs the rigid engine: a FlexibleRod is refused, pointing to
    simulate_drops and study files."""
    with pytest.raises(ValueError, match=r"simulate_batch.*simulate_drops.*flexible_rod"):
        impactlab.simulate_batch(BODY, vy=-1.41, angle=0.3)
