"""Hertz: an elastic sphere's normal impact against the closed forms (Johnson, *Contact Mechanics*
(1985) Sec. 11.4, doi:10.1017/CBO9781139171731)."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
from scipy.special import beta

from impactlab.bodies import Sphere
from impactlab.dynamics import simulate
from impactlab.materials import AISI_1010, ContactPair, Material
from impactlab.verification.table import TOLERANCES, VerificationTable, columns, worst_of

__all__ = ["HERTZ_CASES", "body_mass", "hertz_closed_form", "hertz_convergence", "verify_hertz"]


def hertz_closed_form(
    mass: float, E_star: float, radius: float, v: float
) -> tuple[float, float, float]:
    """Hertz normal impact of a sphere on a flat: (delta_max [m], F_max [N], T [s]).

    delta_m = (15 m v^2 / (16 E* sqrt(R)))^(2/5), F_m = 4/3 E* sqrt(R) delta_m^(3/2),
    T = (4/5) B(2/5, 1/2) delta_m / v = 2.9432 delta_m / v (Johnson 1985, Sec. 11.4).
    """
    dm = (15.0 * mass * v * v / (16.0 * E_star * math.sqrt(radius))) ** 0.4
    fm = 4.0 / 3.0 * E_star * math.sqrt(radius) * dm**1.5
    return dm, fm, 0.8 * float(beta(0.4, 0.5)) * dm / v


def body_mass(body: Any) -> float:
    """The body's mass [kg] (``Sphere.mass`` is typed optional but always set)."""
    m = body.mass
    if m is None:  # pragma: no cover - Sphere.__post_init__ always sets it
        raise ValueError("the body has no mass")
    return float(m)


def _soft_flat() -> Material:
    """A soft polymer flat (E = 5 GPa): the second flat of the Hertz cases."""
    return Material("soft polymer", E=5e9, nu=0.4, yield_strength=1e8, density=1200.0)


#: (sphere radius [m], impact speed [m/s], flat: "aisi-1010" or "soft").
HERTZ_CASES: tuple[tuple[float, float, str], ...] = (
    (0.010, 1.0, "aisi-1010"),
    (0.002, 0.05, "aisi-1010"),
    (0.030, 4.0, "aisi-1010"),
    (0.005, 0.7, "soft"),
)


def verify_hertz(
    cases: Sequence[tuple[float, float, str]] = HERTZ_CASES, rtol: float | None = None
) -> VerificationTable:
    """Hertz normal impact of a steel sphere (AISI 201), no gravity, no friction, against the
    closed forms of :func:`hertz_closed_form` (relative errors; e and e* must equal 1). Each
    case's flat is ``"aisi-1010"`` or ``"soft"`` (ValueError naming them otherwise)."""
    flats = {"aisi-1010": AISI_1010, "soft": _soft_flat()}
    for case in cases:
        if case[2] not in flats:
            raise ValueError(
                f"flat: {case[2]!r} in case {tuple(case)!r} is not one of the Hertz cases' "
                f"flats; allowed: {', '.join(map(repr, flats))}"
            )
    records: list[dict[str, Any]] = []
    for radius, v, flat_name in cases:
        flat = flats[flat_name]
        s = Sphere(radius)
        r = simulate(
            s,
            flat,
            law="hertz",
            friction="coulomb",
            mu=0.0,
            velocity=(0.0, -v),
            gravity=False,
            rtol=rtol,
            history=False,
        )
        dm, fm, T = hertz_closed_form(body_mass(s), ContactPair(s.material, flat).E_star, radius, v)
        rec = {
            "radius": radius,
            "v": v,
            "flat": flat.name,
            "T": T,
            "F": fm,
            "delta": dm,
            "err_T": abs(r.duration / T - 1.0),
            "err_F": abs(r.max_force / fm - 1.0),
            "err_delta": abs(r.delta_max / dm - 1.0),
            "err_e": abs(r.e - 1.0),
            "err_e_energy": abs(r.e_energy - 1.0),
        }
        records.append(rec)
    keys = ("err_T", "err_F", "err_delta", "err_e", "err_e_energy")
    worst = worst_of([r[k] for r in records for k in keys])
    tol = TOLERANCES["hertz"]
    cols = columns(
        """
        radius       | R [m]                 | .3g
        v            | v [m/s]               | .3g
        flat         | flat
        T            | T closed form [s]     | .5g
        err_T        | rel. error T          | .1e
        F            | F_max closed form [N] | .5g
        err_F        | rel. error F_max      | .1e
        err_delta    | rel. error delta_max  | .1e
        err_e        | abs(e - 1)            | .1e
        err_e_energy | abs(e* - 1)           | .1e
        """
    )
    text = """
An elastic steel sphere (AISI 201, radius R, I = 2/5 m R^2) hits a flat normally at speed v
with the elastic `hertz` law, no gravity and no friction; both bodies deform (E* of the pair,
1/E* = (1 - nu_s^2)/E_s + (1 - nu_f^2)/E_f). Hertz theory gives the peak penetration
delta_m = (15 m v^2 / (16 E* sqrt(R)))^(2/5), the peak force F_m = 4/3 E* sqrt(R) delta_m^(3/2)
and the duration T = (4/5) B(2/5, 1/2) delta_m / v = 2.9432 delta_m / v (Johnson, *Contact
Mechanics* (1985) Sec. 11.4, doi:10.1017/CBO9781139171731); the impact is elastic, e = e* = 1.
Engine at its default tolerance; the cases span speeds of 0.05-4 m/s (a factor of 80), radii
of 2-30 mm (a factor of 15) and two flats (AISI 1010 and a soft polymer, E = 5 GPa, nu = 0.4).
In the units delta_m and delta_m / v the problem is the same for every case, so equal errors
across the rows show that the engine's step control is scale-free.
"""
    return VerificationTable(
        "hertz",
        "Hertz: elastic sphere, normal impact",
        text,
        cols,
        tuple(records),
        "relative errors of T, F_max, delta_max; abs(e - 1), abs(e* - 1)",
        worst,
        tol,
        worst <= tol,
    )


def hertz_convergence(
    rtols: Sequence[float] = (1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10),
) -> dict[str, np.ndarray]:
    """Relative errors of T, F_max and delta_max against the closed forms as the engine's
    ``rtol`` tightens (sphere R = 10 mm at 1 m/s on AISI 1010); for the figure."""
    s = Sphere(0.01)
    E_star = ContactPair(s.material, AISI_1010).E_star
    dm, fm, T = hertz_closed_form(body_mass(s), E_star, 0.01, 1.0)
    out: dict[str, list[float]] = {"rtol": [], "T": [], "F": [], "delta": []}
    for rt in rtols:
        r = simulate(
            s,
            AISI_1010,
            law="hertz",
            mu=0.0,
            velocity=(0.0, -1.0),
            gravity=False,
            rtol=rt,
            history=False,
        )
        out["rtol"].append(rt)
        out["T"].append(abs(r.duration / T - 1.0))
        out["F"].append(abs(r.max_force / fm - 1.0))
        out["delta"].append(abs(r.delta_max / dm - 1.0))
    return {k: np.array(v) for k, v in out.items()}
