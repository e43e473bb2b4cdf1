"""A flexible drop records what was dropped and runs again from that record; its repr and the
synthetic truth's are one line."""

from __future__ import annotations

import json
import math

import impactlab as il
from impactlab.bodies.flexible_rod import FlexibleRod


def test_drop_record_reruns_and_repr_is_one_line() -> None:
    rod = FlexibleRod.paper(n_axial=1, n_bending=2)
    r = il.simulate(rod, angle=math.radians(45), velocity=(0.0, -1.0), mu=0.1, history=False,
                    stop="flight")  # fmt: skip
    d = json.loads(json.dumps(r.to_dict()))
    rec = d["input"]
    assert rec["body"]["type"] == "FlexibleRod" and rec["body"]["n_bending"] == 2
    assert rec["stop"] == "flight" and rec["impactlab_version"] == il.__version__
    again = il.rerun(d, history=False)
    assert (again.e, again.dent_depth, again.n_contacts) == (r.e, r.dent_depth, r.n_contacts)
    text = repr(r)
    assert "\n" not in text and len(text) < 300 and "ContactRecord" not in text
    assert r.to_pint()["dent_depth"].to("um").magnitude == r.dent_depth * 1e6
