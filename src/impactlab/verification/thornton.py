"""Thornton's elastic-perfectly plastic law: e(V/V_y) against Thornton's closed form
(J. Appl. Mech. 64 (1997) 383, doi:10.1115/1.2787319)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.bodies import Sphere
from impactlab.contact import thornton_restitution, thornton_yield_velocity
from impactlab.dynamics import contact_model, simulate_batch
from impactlab.materials import AISI_1010, ContactPair
from impactlab.verification.hertz import body_mass
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["verify_thornton"]


def verify_thornton(n: int = 13, *, radius: float = 0.01) -> VerificationTable:
    """Thornton's law, steel sphere on AISI 1010, no gravity: the engine's e against Thornton's
    closed form at ``n`` speeds V/V_y = 10^(3 i/(n-1)) (1 ... 1000) and at V/V_y = 0.5 (elastic).
    Absolute error of e (and e*)."""
    if n < 2:
        raise ValueError(f"n must be >= 2, got {n!r}")
    s = Sphere(radius)
    model = contact_model(s, AISI_1010, "thornton")
    p_y = float(model.details["p_y"])
    v_y = thornton_yield_velocity(
        ContactPair(s.material, AISI_1010).E_star, s.radius, body_mass(s), p_y
    )
    ratios = np.concatenate([[0.5], np.logspace(0.0, 3.0, n)])
    b = simulate_batch(
        s, AISI_1010, law="thornton", friction="coulomb", mu=0.0, vy=-ratios * v_y, gravity=False
    )
    expected = np.asarray(thornton_restitution(ratios), dtype=float)
    e = np.asarray(b["e"], dtype=float)
    ee = np.asarray(b["e_energy"], dtype=float)
    records: list[dict[str, Any]] = []
    for i, q in enumerate(ratios):
        records.append(
            {
                "ratio": float(q),
                "V": float(q * v_y),
                "e_closed": float(expected[i]),
                "e_engine": float(e[i]),
                "err": abs(float(e[i] - expected[i])),
                "err_energy": abs(float(ee[i] - expected[i])),
                "ok": bool(b.status[i] == 0),
            }
        )
    worst = worst_of([max(r["err"], r["err_energy"]) for r in records])
    if not all(r["ok"] for r in records):
        worst = math.inf
    tol = TOLERANCES["thornton"]
    cols = columns(
        """
        ratio      | V/V_y         | .4g
        V          | V [m/s]       | .4g
        e_closed   | e Thornton    | .6f
        e_engine   | e engine      | .6f
        err        | abs. error e  | .1e
        err_energy | abs. error e* | .1e
        """
    )
    text = f"""
A steel sphere (AISI 201, R = {radius * 1e3:g} mm) hits AISI 1010 normally with the `thornton`
law (limiting pressure p_y = {p_y / 1e6:.4g} MPa, the default C(nu) S_y), no gravity. Thornton's
closed form (J. Appl. Mech. 64 (1997) 383, doi:10.1115/1.2787319, as derived in
[the law's page](../laws/thornton.md)) is
e^2 = (6 sqrt3 / 5) (1 - s^2/6) [s / (s + 2 sqrt(6/5 - s^2/5))]^(1/2) with s = V_y/V, and e = 1
below V_y = sqrt(pi^5 p_y^5 R^3 / (30 E*^4 m)) = {v_y:.4g} m/s
(`impactlab.contact.thornton_restitution`, `thornton_yield_velocity`). For a normal sphere
impact the energetic e* equals e.
"""
    return VerificationTable(
        "thornton",
        "Thornton: e against the closed form, V/V_y = 1 to 1000",
        text,
        cols,
        tuple(records),
        "abs(e - e_Thornton), abs(e* - e_Thornton)",
        worst,
        tol,
        worst <= tol,
        figure="thornton_restitution.png",
        extra={"v_y": v_y, "p_y": p_y, "ratios": ratios, "e": e, "expected": expected},
    )
