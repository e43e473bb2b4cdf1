"""A chunk of flexible-rod cases runs as one compiled batch per body
(``impactlab.sweep.flexible.evaluate_flexible`` on ``simulate_drops``): every output and status
equals that of ``simulate_drop`` case by case, over bodies that differ in their modes, damping
and length, interleaved in the chunk, with a bad body and refused kinematics among them."""

from __future__ import annotations

import math

import numpy as np

from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.kernels import status as S
from impactlab.sweep.flexible import DROP_OUTPUTS, evaluate_flexible, flexible_body
from impactlab.sweep.inputs import INPUTS
from impactlab.sweep.models import Statics, material_for
from impactlab.sweep.status import STATUS_BAD_BODY, STATUS_BAD_INPUT

OUTPUTS = (*DROP_OUTPUTS, "regime")


def _chunk() -> dict[str, np.ndarray]:
    """Twelve cases: three bodies (two n_bending, two damping, one length) interleaved, one
    body with too many modes, an angle outside (0, pi/2], a receding tip and a NaN mu."""
    n = 12
    c = {
        k: np.full(n, np.nan if s.default is None else float(s.default))
        for k, s in INPUTS.items()
        if s.kind == "float"
    }
    c |= {k: np.full(n, np.nan) for k in ("length", "tip_radius", "mass", "n_axial")}
    c["n_bending"] = np.array([2, 3, 2, 3, 2, 3, 300, 2, 2, 2, 3, 2], dtype=float)
    c["damping"] = np.array([0, 0.01, 0, 0.01, 0, 0.01, 0, 0, 0, 0, 0.01, 0], dtype=float)
    c["length"][[8, 11]] = 0.25
    c["n_axial"][:] = 1.0
    c["angle"] = np.radians([20, 20, 45, 45, 70, 70, 30, -10, 30, 30, 10, 30])
    c["vy"] = np.array([-1.41, -1.41, -2.18, -2.18, -3.45, -1.0, -1, -1, -1, 1.0, -0.7, -1])
    c["vx"] = np.array([0, 0.2, 0, -0.2, 0, 0, 0, 0, 0.1, 0, 0, 0], dtype=float)
    c["spin"] = np.zeros(n)
    c["mu"] = np.array([0.2, 0.2, 0.13, 0.13, 0.1, 0.1, 0.2, 0.2, 0.2, 0.2, 0.3, np.nan])
    return c


def test_chunk_equals_drop_by_drop() -> None:
    cases = _chunk()
    cat = {k: str(s.default) for k, s in INPUTS.items() if s.kind == "category"}
    cat |= {"body": "flexible_rod", "friction": "coulomb", "law": "ghaednia"}
    statics = Statics(cat)
    res, status = evaluate_flexible(cases, statics, OUTPUTS)
    assert status[6] == STATUS_BAD_BODY and status[7] == S.ST_BAD_ANGLE
    assert status[9] == S.ST_NOT_APPROACHING and status[11] == STATUS_BAD_INPUT
    ok = [i for i in range(12) if i not in (6, 7, 9, 11)]
    assert (status[ok] == 0).all()
    assert np.isnan(res["regime"]).all()
    for i in range(12):
        row = {k: float(v[i]) for k, v in cases.items()}
        if i not in ok:
            assert all(math.isnan(res[o][i]) for o in OUTPUTS)
            continue
        body = flexible_body(row, material_for("body", cat["body_material"], row))
        flat = material_for("flat", cat["flat_material"], row)
        r = simulate_drop(
            body, flat, law="ghaednia", friction="coulomb", mu=row["mu"],
            angle=row["angle"], velocity=(row["vx"], row["vy"]), spin=row["spin"],
        )  # fmt: skip
        for o, read in DROP_OUTPUTS.items():
            assert res[o][i] == float(read(r)), (i, o)
