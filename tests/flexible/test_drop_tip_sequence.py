"""The tip's sequence of a drop, and what reads it: the gravity criterion stops where
``stop="sequence"`` would end (a tip that bounces, flies clear and lands again 154 ms later is
no resting rod), OTHER_END says whenever the other end touched (gravity-dominated or not), and
``dent_depth`` is the tip's deepest dent, ``dent().max_depth``, also when the other end dents
the flat deeper (docs/flexible.md, "Results" and "Flags")."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.dynamics.drop import simulate_drop
from impactlab.flags import ResultFlag, messages

ROD = il.FlexibleRod.paper()
RETURN = {"mu": 0.2, "angle": math.radians(60.7), "velocity": (0.0, -1.09), "history": False}


def test_a_flight_with_a_tip_return_is_not_gravity_dominated() -> None:
    """60.7 deg at 1.09 m/s: the tip bounces 3 times in 0.91 ms, lands again 155 ms later and
    the other end touches after it. Read up to the other end's first touch, m g T / P_n was
    1.20: GRAVITY_DOMINATED, and OTHER_END hidden behind it."""
    seq = simulate_drop(ROD, **RETURN)
    flight = simulate_drop(ROD, stop="flight", **RETURN)
    assert seq.n_contacts == 3 and seq.next_end == 0
    # the flight follows the sequence's path until stop="sequence" would end
    assert flight.contacts[:3] == seq.contacts
    assert flight.contacts[3].end == 0 and flight.contacts[3].start > 0.15
    assert sum(c.end == 1 for c in flight.contacts) == 11
    tip = flight.contacts[:3]
    t_tip = tip[-1].start + tip[-1].duration
    ratio = ROD.mass * flight.gravity * t_tip / sum(c.normal_impulse for c in tip)
    assert ratio < 0.01  # the tip's bounce: far from gravity's 0.1
    assert ResultFlag.GRAVITY_DOMINATED not in flight.flags
    assert ResultFlag.OTHER_END in flight.flags and not flight.ok


def test_the_batch_flags_a_tip_return_alike() -> None:
    """``simulate_drops`` reads the same tip's sequence (``flexcore.batch.sequence_flags``)."""
    one = simulate_drop(ROD, stop="flight", **RETURN)
    batch = il.simulate_drops(ROD, angle=RETURN["angle"], vy=-1.09, mu=0.2, stop="flight")
    assert int(batch.flags[0]) == int(one.flags)
    flags = ResultFlag(int(batch.flags[0]))
    assert ResultFlag.OTHER_END in flags and ResultFlag.GRAVITY_DOMINATED not in flags
    assert batch.dent_depth[0] == one.dent_depth and batch.e[0] == one.e


def test_other_end_is_set_on_a_gravity_dominated_drop() -> None:
    """A rigid rod dropped at 1 cm/s comes to rest on both ends: GRAVITY_DOMINATED, and the
    other end's touches are flagged as well."""
    r = simulate_drop(il.Rod.paper(), mu=0.2, angle=math.radians(20), velocity=(0.0, -0.01))
    assert any(c.end == 1 for c in r.contacts)
    assert ResultFlag.GRAVITY_DOMINATED in r.flags and ResultFlag.OTHER_END in r.flags


def test_dent_depth_is_the_tip_s_when_the_other_end_dents_deeper() -> None:
    """A rod landing at 0.3 deg: its other end's dent (59.7 um) is deeper than the tip's
    (51.5 um); dent_depth is the tip's, as the dent map's depth, the scar and the slip."""
    r = simulate_drop(ROD, mu=0.2, angle=math.radians(0.3), velocity=(0.0, -1.41))
    tip = max(d.delta_p for d in r.dents if d.end == 0)
    other = max(d.delta_p for d in r.dents if d.end == 1)
    assert other > tip
    assert r.dent_depth == tip == pytest.approx(51.49e-6, rel=1e-3)
    assert r.dent().max_depth == pytest.approx(r.dent_depth, rel=1e-9)
    assert ResultFlag.OTHER_END in r.flags


def test_a_flight_s_dent_depth_and_scar_are_the_tip_s() -> None:
    """45 deg, 2.18 m/s, mu 0.13, followed for 1 s: the other end's dent is the deepest
    (69.9 um); the tip's two dents, 11.8 mm apart, give dent_depth (63.9 um) and the scar,
    which spans both and the flat between them."""
    r = simulate_drop(ROD, mu=0.13, angle=math.radians(45), velocity=(0.0, -2.18),
                      stop="flight", time_limit=1.0, history=False)  # fmt: skip
    tips = [d for d in r.dents if d.end == 0]
    assert len(tips) == 2
    assert max(d.delta_p for d in r.dents) > r.dent_depth == max(d.delta_p for d in tips)
    lo = min(d.x_min for d in tips)
    hi = max(d.x_max for d in tips)
    assert r.scar_length == pytest.approx(hi - lo, rel=1e-9)
    assert r.scar_length > 10e-3 > sum(d.x_max - d.x_min for d in tips)


def test_other_end_message_names_the_tip_s_marks() -> None:
    (text,) = messages(ResultFlag.OTHER_END)
    assert "dent_depth" in text and "scar_length" in text and "dents" in text
    assert "\n" not in text
