"""A tip that bounces, flies clear and comes back down after the rod turned in free flight
starts a new impact (``next_end`` the tip itself), as the other end's landing does: the drop's
sequence, e and flags are the bounce's. Before, the return 150 ms later was merged into the
sequence (e 1.77, GRAVITY_DOMINATED, 155 ms long). A ringing rod's re-contacts, within a few
periods of its lowest mode, stay in the sequence (the paper's drops: 4 and 3 contacts)."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.dynamics.flexcore import layout as F

ROD = il.FlexibleRod.paper()
KW = {"law": "ghaednia", "mu": 0.2, "history": False}


def test_a_return_after_a_clear_flight_is_a_new_impact() -> None:
    r = il.simulate_drop(ROD, il.AISI_1010, angle=math.radians(60.7), velocity=(0.0, -1.09), **KW)
    assert r.ok and r.n_contacts == 3 and r.sequence_duration < 1e-3
    assert r.next_end == 0 and 0.1 < r.next_time < 0.2  # the tip lands again after ~150 ms
    rigid = il.simulate(il.Rod.paper(), il.AISI_1010, angle=math.radians(60.7),
                        velocity=(0.0, -1.09), mu=0.2, law="ghaednia")  # fmt: skip
    assert r.e == pytest.approx(rigid.e, abs=0.05)  # one bounce of the tip: near the rigid e
    followed = il.simulate_drop(ROD, il.AISI_1010, angle=math.radians(60.7),
                                velocity=(0.0, -1.09), stop="flight", **KW)  # fmt: skip
    assert followed.n_contacts > r.n_contacts and followed.sequence_duration > 0.1


def test_ringing_re_contacts_stay_in_the_sequence() -> None:
    r = il.simulate_drop(ROD, il.AISI_1010, angle=math.radians(20), velocity=(0.0, -1.41), **KW)
    assert r.n_contacts == 4 and r.next_end == 1  # the other end lands next, 38 ms later
    assert F.NEW_IMPACT_CHECKS == 100.0  # 10 periods of the basis's first mode (0.1 each)
