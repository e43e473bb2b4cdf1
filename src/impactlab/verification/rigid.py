"""Rigid-body limits: the rod with frozen lever arms against the rigid-body impulse
(``impactlab.bodies.rigid_impulse``; Stronge, *Impact Mechanics* (2000) Ch. 5,
doi:10.1017/CBO9780511626432), and the engine's slip/stick boundary against
``impactlab.analytic.critical_friction``."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np

from impactlab.analytic import critical_friction
from impactlab.bodies import PAPER_ROD, rigid_impulse
from impactlab.dynamics import REGIME_NAMES, simulate, simulate_batch
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["engine_boundary", "regime_codes", "verify_critical_friction", "verify_rigid_limits"]

_PAPER_ANGLE = math.radians(20.0)


def verify_rigid_limits(
    factors: Sequence[float] = (0.25, 0.5, 0.9, 1.1, 1.5, 3.0),
    *,
    angle: float = _PAPER_ANGLE,
    v: float = 1.41,
) -> VerificationTable:
    """The paper's rod at ``angle`` [rad], mu = factor * mu_c, Hertz contact, Coulomb friction,
    lever arms frozen (``constant_angle=True``), no gravity, against
    ``impactlab.bodies.rigid_impulse`` with e = 1."""
    mu_c = float(critical_friction(angle, PAPER_ROD))
    records: list[dict[str, Any]] = []
    for f in factors:
        mu = f * mu_c
        rig = rigid_impulse(PAPER_ROD, angle, (0.0, -v), e=1.0, mu=mu)  # elastic: e = e* = 1
        r = simulate(
            PAPER_ROD,
            law="hertz",
            friction="coulomb",
            mu=mu,
            angle=angle,
            velocity=(0.0, -v),
            gravity=False,
            constant_angle=True,
            history=False,
        )
        P, vt = rig.normal_impulse, rig.contact_velocity_out[0]
        rec = {
            "factor": f,
            "mu": mu,
            "regime_rigid": rig.regime,
            "regime": r.regime,
            "P": P,
            "err_P": abs(r.normal_impulse / P - 1.0),
            "err_Pt": abs(r.tangential_impulse / rig.tangential_impulse - 1.0),
            "err_vt": abs(r.vt_out - vt) / v,
            "vt": vt,
            "err_e": abs(r.e - 1.0),
            "match": r.regime == rig.regime,
        }
        records.append(rec)
    worst = worst_of([r[k] for r in records for k in ("err_P", "err_Pt", "err_vt", "err_e")])
    tol = TOLERANCES["rigid"]
    cols = columns(
        """
        factor       | mu/mu_c             | .3g
        mu           | mu                  | .4f
        regime_rigid | rigid regime
        regime       | engine regime
        match        | same
        P            | P rigid [N s]       | .5g
        err_P        | rel. error P        | .1e
        err_Pt       | rel. error P_t      | .1e
        vt           | v_t,out rigid [m/s] | .4f
        err_vt       | abs(dv_t)/abs(v_n0) | .1e
        err_e        | abs(e - 1)          | .1e
        """
    )
    R_mm = PAPER_ROD.tip_radius * 1e3
    text = f"""
The paper's rod (m = {PAPER_ROD.mass} kg, L = {PAPER_ROD.L} m, R = {R_mm:g} mm, I_C = m L^2/12)
dropped at {math.degrees(angle):g} deg with v = {v} m/s, no spin, on an elastic
(`hertz`) contact with Coulomb friction, the lever arms frozen (`constant_angle=True`) and no
gravity. Then the velocities are linear in the impulses and the rigid-body solution is exact
(Stronge, *Impact Mechanics* (2000) Ch. 5, doi:10.1017/CBO9780511626432): below
mu_c = a b / (k^2 + b^2) = {mu_c:.6f} the tip slides throughout with P_t = mu P (the
[analytic](../analytic.md) K_x, K_y), above it the tip sticks from the start; the elastic contact
ends when the normal work returns to zero (P = 2 abs(v_n0) / K_y in slip), so e = 1.
"""
    passed = worst <= tol and all(r["match"] for r in records)
    return VerificationTable(
        "rigid",
        "Rigid-body limit: rod in slip and in stick",
        text,
        cols,
        tuple(records),
        "relative errors of P, P_t; abs(dv_t)/abs(v_n0); abs(e - 1); regimes equal",
        worst,
        tol,
        passed,
    )


def regime_codes() -> dict[str, int]:
    """The engine's regime codes by name."""
    return {name: code for code, name in REGIME_NAMES.items()}


def engine_boundary(angles: np.ndarray, *, iterations: int = 30, v: float = 1.0) -> np.ndarray:
    """The friction coefficient where the engine's regime changes from slip to stick, by
    bisection on mu in [0, 1] (paper's rod, Hertz, Coulomb, constant angle, no gravity)."""
    slip = regime_codes()["slip"]
    angles = np.asarray(angles, dtype=float)
    lo = np.zeros_like(angles)
    hi = np.ones_like(angles)
    for _ in range(iterations):
        mid = 0.5 * (lo + hi)
        b = simulate_batch(
            PAPER_ROD,
            law="hertz",
            friction="coulomb",
            mu=mid,
            angle=angles,
            vy=-v,
            gravity=False,
            constant_angle=True,
        )
        if not np.all(b.computed):
            raise RuntimeError(f"engine failed in the bisection: {set(b.messages)}")
        is_slip = np.asarray(b["regime"]) == slip
        lo = np.where(is_slip, mid, lo)
        hi = np.where(is_slip, hi, mid)
    return 0.5 * (lo + hi)


def _angles_deg(angles_deg: Any) -> np.ndarray:
    """``angles_deg`` as a 1-D float array [deg], every angle in (0, 90) deg; a one-line
    ValueError in degrees otherwise (they are degrees already: no radians advice)."""
    try:
        a = np.atleast_1d(np.asarray(angles_deg, dtype=float))
    except (TypeError, ValueError):
        raise ValueError(
            f"angles_deg must be numbers in degrees, each in (0, 90), got {angles_deg!r}"
        ) from None
    if a.ndim != 1 or a.size == 0:
        raise ValueError(f"angles_deg: give one or more angles in (0, 90) deg, got {angles_deg!r}")
    bad = a[~((a > 0.0) & (a < 90.0))]  # NaN too
    if bad.size:
        raise ValueError(
            "angles_deg: every angle must lie in (0, 90) deg, got "
            + ", ".join(f"{x:g}" for x in bad)
            + " deg"
        )
    return a


def verify_critical_friction(
    angles_deg: Sequence[float] = (5, 10, 20, 30, 45, 60, 70, 80, 85), *, iterations: int = 30
) -> VerificationTable:
    """The engine's slip/stick boundary (bisection, :func:`engine_boundary`) against
    ``impactlab.analytic.critical_friction`` at each angle (relative difference); ``angles_deg``
    in degrees, each in (0, 90) (ValueError otherwise, in degrees)."""
    deg = _angles_deg(angles_deg)
    ang = np.radians(deg)
    found = engine_boundary(ang, iterations=iterations)
    mu_c = np.asarray(critical_friction(ang, PAPER_ROD), dtype=float)
    resolution = 2.0 ** -(iterations + 1)
    records = [
        {
            "angle": float(d),
            "mu_c": float(m),
            "engine": float(f),
            "err": abs(float(f) / float(m) - 1.0),
        }
        for d, m, f in zip(deg, mu_c, found, strict=True)
    ]
    worst = worst_of([r["err"] for r in records])
    tol = max(TOLERANCES["critical_friction"], 4.0 * resolution / float(np.min(mu_c)))
    cols = columns(
        """
        angle  | angle [deg]     | .4g
        mu_c   | mu_c analytic   | .8f
        engine | engine boundary | .8f
        err    | rel. difference | .1e
        """
    )
    text = f"""
The slip/stick boundary of the paper's rod (no spin, no tangential velocity, constant angle, no
gravity, Hertz contact, Coulomb friction): the engine's regime is found by bisection on mu in
[0, 1] ({iterations} halvings, resolution {resolution:.1e}) and compared with the closed form
mu_c = a b / (k^2 + b^2), a = (L/2) cos theta, b = (L/2) sin theta + R, k^2 = I_C/m
(`impactlab.analytic.critical_friction`, derived in [the analytic method](../analytic.md)).
mu_c is not monotonic in the angle: it peaks near 24 deg.
"""
    return VerificationTable(
        "critical_friction",
        "Critical friction mu_c: engine vs closed form",
        text,
        cols,
        tuple(records),
        "relative difference of the boundary",
        worst,
        tol,
        worst <= tol,
        figure="critical_friction.png",
        extra={"angles": ang, "engine": found, "mu_c": mu_c},
    )
