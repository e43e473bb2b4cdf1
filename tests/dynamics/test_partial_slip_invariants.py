"""Invariants of the ``partial_slip`` friction model: no energy gain, the Coulomb
bound, continuity of F_t at every switch, the rigid (Coulomb) limit as G* grows, the rods, the
result object and the batch engine's ids, no cascade of switches at a receding edge cell.
Convergence in the cell count against the exact solution: test_partial_slip_accuracy.py."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il
from impactlab.bodies.layout import BP_GSTAR
from impactlab.contact import law_names
from impactlab.dynamics.batch import run_arrays
from impactlab.dynamics.checks import check_impact
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.models import body_params, kernel_params
from impactlab.dynamics.partial_slip import largest_radius
from impactlab.dynamics.slipcore import impact_slip, slip_addresses
from impactlab.flags import ResultFlag
from impactlab.friction import (
    BATCH_FRICTION_IDS,
    FRICTION_IDS,
    PARTIAL_SLIP,
    friction_names,
    get_friction,
)
from impactlab.sweep.engine import EngineEvaluator
from impactlab.verification.partial_slip import kharaz_case, rigid_coulomb

SPHERE = il.Sphere(radius=5e-3, material=il.AISI_201)


def _raw(body, law, vel, mu=0.3, gstar=1.0, n_cells=16, angle=None, gravity=0.0):
    """(status, outputs, history, F_t jump / mu F_max) straight from the compiled engine, with
    the energy diagnostics on and G* scaled by ``gstar``."""
    x = check_impact(
        body, il.AISI_1010, law=law, friction="partial_slip", mu=mu, angle=angle,
        velocity=vel, spin=0.0, law_params=None, gravity=gravity, constant_angle=False,
        rtol=None,
    )  # fmt: skip
    st, a_est = largest_radius(x)
    assert st == 0
    bp = body_params(body, il.AISI_1010).copy()
    bp[BP_GSTAR] *= gstar
    out = np.empty(L.N_OUT)
    st, hist, nh, jump = impact_slip(
        x.model.law_id, kernel_params(x.model), bp, x.angle, vel[0], vel[1], 0.0, mu,
        x.gravity, False, x.rtol, True, True, n_cells, a_est, out, slip_addresses(),
    )  # fmt: skip
    return int(st), out, hist[:nh], jump


def _sample():
    rng = np.random.default_rng(12)
    for law in law_names():
        for _ in range(2):
            theta = rng.uniform(1.0, 70.0)
            v = rng.uniform(0.2, 2.0)
            yield law, v * math.sin(math.radians(theta)), -v * math.cos(math.radians(theta))


@pytest.mark.parametrize("case", list(_sample()), ids=lambda c: f"{c[0]}-{c[1]:.2f}")
def test_energy_coulomb_bound_and_continuity(case: tuple[str, float, float]) -> None:
    law, vx, vy = case
    st, out, hist, jump = _raw(SPHERE, law, (vx, vy))
    assert st == 0
    assert out[L.O["energy_rise"]] < 1e-9  # total energy incl. the cells never rises
    assert out[L.O["energy_dissipated"]] > -1e-9 * 0.5 * SPHERE.mass * (vx * vx + vy * vy)
    assert out[L.O["friction_excess"]] < 1e-8  # |F_t| <= mu F_n (up to the 1e-9 hysteresis)
    assert jump < 1e-7  # F_t continuous at every birth, release and stick/slip switch
    e = hist[:, L.H_ENERGY]  # dense-output rows too: 4th-order interpolation, hence 1e-7
    assert np.all(np.diff(e) <= 1e-7 * e[0])
    ft, fn = hist[:, L.H_FT], hist[:, L.H_FN]
    assert np.all(np.abs(ft) <= 0.3 * fn * (1.0 + 1e-8) + 1e-12 * fn.max())


def test_rigid_limit_as_the_tangential_stiffness_grows() -> None:
    """G* -> infinity: the result tends to rigid-body Coulomb (slide, then roll) at 10 deg
    (prototype, Kharaz case, exact model: 0.078 at 1 x G*, 9.7e-3 at 10 x, 1.8e-3 at 100 x;
    here steel, mu = 0.3, Psi = 0.59)."""
    vel = (math.sin(math.radians(10.0)), -math.cos(math.radians(10.0)))
    errs = []
    for k in (1.0, 10.0, 100.0):
        st, out, _h, _j = _raw(SPHERE, "hertz", vel, gstar=k)
        assert st == 0
        ref = rigid_coulomb(_case_of(SPHERE), vel[0], out[L.O_E])
        errs.append(abs(out[L.O_VX] / vel[0] - ref["et"]))
    assert errs[0] > 0.02 and errs[2] < 4e-3  # (not monotonic in between: 0.03, 0.07, 2e-3)


def _case_of(body):
    case = kharaz_case()
    return type(case)(body, il.AISI_1010, "hertz", 0.3, 1.0)


def test_mu_zero_is_frictionless() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match="with mu = 0 is frictionless"):
        r = il.simulate(SPHERE, law="hertz", friction="partial_slip", mu=0.0, velocity=(0.3, -1.0))
    assert r.velocity_out[0] == pytest.approx(0.3, abs=1e-12)
    assert r.spin_out == 0.0 and r.regime == "frictionless"


@pytest.mark.parametrize("law", law_names())
def test_rod_every_law(law: str) -> None:
    """The paper's rod (20 deg, 1.41 m/s, mu 0.2, gravity on): finite, no energy gain, close to
    the Mindlin-type model (the normal impulse dominates)."""
    kw = {"law": law, "mu": 0.2, "angle": math.radians(20.0), "velocity": (0.0, -1.41)}
    r = il.simulate(il.Rod.paper(), friction="partial_slip", **kw)
    ref = il.simulate(il.Rod.paper(), friction="mindlin", **kw)
    assert r.ok and r.friction == "partial_slip"
    assert abs(r.e - ref.e) < 0.02
    assert r.energy_dissipated > 0.0
    h = r.history
    assert h is not None and len(h) > 50
    assert np.all(np.abs(h.tangential_force) <= 0.2 * h.normal_force * (1 + 1e-8) + 1e-9)
    assert set(np.unique(h.stick)) <= {0.0, 1.0}


def test_result_and_references() -> None:
    r = il.simulate(SPHERE, law="hertz", friction="partial_slip", mu=0.3, velocity=(0.1, -1.0))
    assert r.ok and r.regime in ("stick", "reversal")
    assert "10.1115/1.4009973" in r.dois() and "10.1115/1.4010702" in r.dois()
    assert r.stick_time > 0.0 and r.history is not None
    assert r.history.stick[1] == 1.0  # no gross slip at first touch at this small angle
    assert "partial_slip" in friction_names() and get_friction("partial_slip").friction_id == 3
    assert get_friction("partial_slip").references


def test_batch_engine_runs_partial_slip() -> None:
    """The batch engine and the sweeps take partial slip (tests/dynamics/test_partial_slip_batch.py
    checks its results against simulate); the core's ids are unchanged."""
    EngineEvaluator().validate({"friction": ["coulomb", "partial_slip"]})
    b = il.simulate_batch(SPHERE, friction="partial_slip", mu=0.2, vy=-1.0)
    assert b.friction == "partial_slip" and list(b.status) == [0]
    with pytest.raises(ValueError, match="friction_id must be one of"):
        run_arrays(0, 4, np.zeros(9), np.zeros(9), np.zeros((1, 4)), np.zeros(1))
    assert FRICTION_IDS == {"impulse_ratio": 0, "coulomb": 1, "mindlin": 2}  # unchanged
    assert BATCH_FRICTION_IDS == {**FRICTION_IDS, "partial_slip": PARTIAL_SLIP}
    assert PARTIAL_SLIP == 3


def test_creeping_rod_settles() -> None:
    """A creeping, gravity-dominated drop (1e-9 m/s): an edge cell's limit that round-off made
    slightly negative once made a cell switch stick <-> slip forever (status 'too many
    switches'); the limit is now >= 0 and the impact separates, flagged gravity-dominated."""
    r = il.simulate(
        il.Rod.paper(), law="hertz", friction="partial_slip", mu=0.2,
        angle=math.radians(20.0), velocity=(0.0, -1e-9), history=False,
    )  # fmt: skip
    assert r.flags & ResultFlag.GRAVITY_DOMINATED and not r.ok


def test_receding_edge_cell_on_its_limit_does_not_cascade() -> None:
    """A sticking edge cell that sits on its limit while the contact recedes (its stick rate
    f a'/l stiff as l -> 0) alternated between slip and stick when the steps before a release
    were cut close to the boundary: 827 located switches, 1914 steps (340 with the 1.05
    margin). The close cut is for births only; the result is that of the reference run."""
    r = il.simulate(
        il.Sphere(radius=0.01), law="thornton", friction="partial_slip", mu=0.41362784635731786,
        velocity=(0.16197666659322096, -1.2403148948686848), history=False,
    )  # fmt: skip
    assert r.ok
    assert r.n_steps < 400
    # the same impact at rtol = 1e-10: e = 0.33423648352, vt_out = -0.11932142909
    assert r.e == pytest.approx(0.33423648352, rel=1e-7)
    assert r.vt_out == pytest.approx(-0.11932142909, rel=2e-6)
