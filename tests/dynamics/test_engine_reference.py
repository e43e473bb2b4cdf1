"""The compiled engine against the independent scipy ``solve_ivp`` implementation
(``impactlab.dynamics.reference``) of the same physics, on the same cases: every law and
friction model, rod and sphere, with gravity, spin and initial slip.

Quantities are compared relative to their natural scale (velocities to |v_n,in|, lengths to
delta_max, impulses to the normal impulse, energies to the initial kinetic energy, times to
the duration); agreement within 1e-6. The stick time is a sum of event times of transitions
whose event function can cross at a shallow angle (Mindlin's elastic -> slip), which amplifies
the integration error: 1e-4 of the duration there.
"""

from __future__ import annotations

import math
from typing import Any

import pytest

from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.contact import law_names
from impactlab.dynamics import simulate
from impactlab.dynamics.reference import simulate_reference
from impactlab.friction import FRICTION_IDS

REL = 1e-6
#: Laws held to a wider bound here: none (the tabulated law was, at 1e-5, while its loading
#: curve interpolated the scatter of its FE points; it is a smooth fit now).
REL_LAW: dict[str, float] = {}

ROD_CASE = {"angle": math.radians(35.0), "velocity": (0.1, -1.2), "spin": 2.0, "mu": 0.3}
SPHERE = Sphere(0.006)
SPHERE_CASE = {"velocity": (0.4, -1.0), "spin": -30.0, "mu": 0.25}


def _scaled_errors(r: Any, ref: dict[str, Any], body: Any) -> dict[str, float]:
    vn = abs(r.vn_in)
    e0 = (
        0.5 * body.mass * (r.velocity_in[0] ** 2 + r.velocity_in[1] ** 2)
        + 0.5 * body.inertia * r.spin_in**2
    )
    lever = body.half_length + body.tip_radius
    scales = {
        "e": 1.0,
        "e_energy": 1.0,
        "vx_out": vn,
        "vy_out": vn,
        "spin_out": vn / lever,
        "delta_max": r.delta_max,
        "delta_p": r.delta_max,
        "sliding_length": r.delta_max,
        "contact_travel": r.delta_max,
        "duration": r.duration,
        "max_force": r.max_force,
        "normal_impulse": r.normal_impulse,
        "tangential_impulse": r.normal_impulse,
        "energy_dissipated": e0,
        "stick_time": r.duration,
        "vn_out": vn,
        "vt_out": vn,
    }
    mine = r.to_dict()
    mine["vx_out"], mine["vy_out"] = r.velocity_out
    return {k: abs(mine[k] - ref[k]) / s for k, s in scales.items()}


@pytest.mark.parametrize("friction", tuple(FRICTION_IDS))  # partial_slip: own tests
@pytest.mark.parametrize("law", law_names())
@pytest.mark.parametrize("body", ["rod", "sphere"])
def test_engine_matches_solve_ivp(law: str, friction: str, body: str) -> None:
    b, case = (PAPER_ROD, ROD_CASE) if body == "rod" else (SPHERE, SPHERE_CASE)
    ref = simulate_reference(b, law=law, friction=friction, rtol=1e-10, **case)
    r = simulate(b, law=law, friction=friction, **case)
    errs = _scaled_errors(r, ref, b)
    assert errs.pop("stick_time") < 1e-4
    worst = max(errs, key=errs.__getitem__)
    assert errs[worst] < REL_LAW.get(law, REL), (worst, errs[worst])
    if law == "tabulated" and r.regime != ref["regime"]:
        # the sphere case ends on the border of stick and reversal for this law: a slip
        # reversal of ~1e-6 of the contact time at the default tolerance, none at 1e-10
        r = simulate(b, law=law, friction=friction, rtol=1e-10, **case)
    assert r.regime == ref["regime"]


@pytest.mark.parametrize("friction", tuple(FRICTION_IDS))  # partial_slip: own tests
def test_paper_rod_both_at_the_same_tolerance(friction: str) -> None:
    """The paper's case (20 deg, 1.41 m/s, mu 0.2, Ghaednia) with both integrators at the same
    tight tolerance: the two implementations agree far below 1e-6."""
    case = {"angle": math.radians(20.0), "velocity": (0.0, -1.41), "mu": 0.2}
    ref = simulate_reference(PAPER_ROD, law="ghaednia", friction=friction, rtol=1e-11, **case)
    r = simulate(PAPER_ROD, law="ghaednia", friction=friction, rtol=1e-11, **case)
    errs = _scaled_errors(r, ref, PAPER_ROD)
    assert max(errs.values()) < 1e-8, errs
