"""Rigid limits: the compliant engine against the rigid-body impulse solution (Stronge).

With the lever arms frozen (``constant_angle=True``) and no gravity, the velocities are exact
linear functions of the impulses, and an elastic (Hertz) contact ends when the normal work
int v_n dP returns to zero (energetic COR e* = 1): the engine must reproduce the rigid solution
to integration accuracy, for any stiffness. With the body's full rotation a stiff contact
approaches it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest
from engine_rigid import rigid_impact

from impactlab.bodies import PAPER_ROD, Rod, Sphere
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.dynamics import contact_model, simulate
from impactlab.materials import AISI_1010

TH = math.radians(20.0)


def _arms(body: Rod | Sphere, th: float) -> tuple[float, float]:
    return body.half_length * math.cos(th), body.half_length * math.sin(th) + body.tip_radius


def mu_critical(body: Rod | Sphere, th: float) -> float:
    a, b = _arms(body, th)
    k2 = body.inertia / body.mass
    return a * b / (k2 + b * b)


def _compare(
    body: Rod | Sphere,
    th: float,
    vx: float,
    vy: float,
    w: float,
    mu: float,
    *,
    law: str | ContactModel = "hertz",
    constant_angle: bool = True,
    rel: float = 1e-6,
) -> str:
    a, b = _arms(body, th)
    vt0 = vx + w * b
    vn0 = vy - w * a
    rig = rigid_impact(body.mass, body.inertia, a, b, vt0, vn0, mu)
    r = simulate(
        body,
        law=law,
        friction="coulomb",
        mu=mu,
        angle=th if isinstance(body, Rod) else None,
        velocity=(vx, vy),
        spin=w,
        gravity=False,
        constant_angle=constant_angle,
    )
    scale = abs(vn0)
    assert abs(r.vn_out - rig.vn) < rel * scale, (r.vn_out, rig.vn)
    assert abs(r.vt_out - rig.vt) < rel * scale, (r.vt_out, rig.vt)
    assert r.normal_impulse == pytest.approx(rig.P, rel=rel)
    assert abs(r.tangential_impulse - rig.Pt) < rel * rig.P
    assert r.e == pytest.approx(rig.vn / -vn0, rel=rel)
    assert r.regime == rig.regime
    return r.regime


def test_rod_paper_slip_throughout() -> None:
    mu = 0.5 * mu_critical(PAPER_ROD, TH)
    assert _compare(PAPER_ROD, TH, 0.0, -1.41, 0.0, mu) == "slip"


def test_rod_paper_stick() -> None:
    mu = 1.2 * mu_critical(PAPER_ROD, TH)
    assert _compare(PAPER_ROD, TH, 0.0, -1.41, 0.0, mu) == "stick"


def test_rod_slip_reversal() -> None:
    mu = 0.4 * mu_critical(PAPER_ROD, TH)
    assert _compare(PAPER_ROD, TH, 0.15, -1.41, 0.0, mu) == "reversal"


def test_rod_slip_then_stick() -> None:
    mu = 1.5 * mu_critical(PAPER_ROD, TH)
    assert _compare(PAPER_ROD, TH, 0.3, -1.41, 0.0, mu) == "stick"


def test_rod_negative_slip_then_stick_gives_e_above_one() -> None:
    """Kinematic e may exceed 1 (Stronge): the normal work, not v_n, is what restitution
    conserves; energy is still dissipated."""
    mu = 1.5 * mu_critical(PAPER_ROD, TH)
    _compare(PAPER_ROD, TH, -0.4, -1.41, 0.0, mu)
    r = simulate(
        PAPER_ROD,
        law="hertz",
        mu=mu,
        angle=TH,
        velocity=(-0.4, -1.41),
        gravity=False,
        constant_angle=True,
    )
    assert r.e > 1.0
    assert abs(r.e_energy - 1.0) < 1e-6
    assert r.energy_dissipated > 0.0


@pytest.mark.parametrize("th_deg", [10.0, 20.0, 45.0, 70.0])
def test_critical_friction_coefficient(th_deg: float) -> None:
    """mu_c = a b / (k^2 + b^2) separates slip from stick (rod, v_t0 = 0)."""
    th = math.radians(th_deg)
    mu_c = mu_critical(PAPER_ROD, th)
    below = simulate(
        PAPER_ROD,
        law="hertz",
        mu=mu_c * (1 - 1e-3),
        angle=th,
        velocity=(0.0, -1.0),
        gravity=False,
        constant_angle=True,
    )
    above = simulate(
        PAPER_ROD,
        law="hertz",
        mu=mu_c * (1 + 1e-3),
        angle=th,
        velocity=(0.0, -1.0),
        gravity=False,
        constant_angle=True,
    )
    assert below.regime == "slip" and below.stick_time == 0.0
    assert above.regime == "stick"
    assert above.stick_time == pytest.approx(above.duration, rel=1e-9)
    assert abs(above.vt_out) < 1e-9
    assert below.vt_out < 0.0  # the tip slides towards -x (sliding length < 0)
    assert below.sliding_length < 0.0


@pytest.mark.parametrize(
    ("vx", "w", "mu", "regime"),
    [
        (2.0, 0.0, 0.1, "slip"),
        (0.3, 0.0, 0.2, "stick"),
        (0.5, -100.0, 0.3, "stick"),
        (0.0, 0.0, 0.3, "stick"),
    ],
)
def test_sphere(vx: float, w: float, mu: float, regime: str) -> None:
    s = Sphere(0.01)  # no angle to freeze: constant_angle=True is refused for a sphere
    assert _compare(s, 0.5 * math.pi, vx, -1.0, w, mu, constant_angle=False) == regime


def test_sphere_full_rotation_equals_rigid() -> None:
    """A sphere's lever arms never change: full rotation is exact too."""
    _compare(Sphere(0.01), 0.5 * math.pi, 0.3, -1.0, 0.0, 0.2, constant_angle=False)


def _stiff_hertz(scale: float) -> ContactModel:
    base = contact_model(PAPER_ROD, AISI_1010, "hertz")
    p = np.array(base.params)
    p[k.P_ESTAR] *= scale
    return ContactModel("hertz", base.law_id, p)


@pytest.mark.parametrize(("vx", "mu_factor"), [(0.0, 0.5), (0.0, 1.3), (0.15, 0.4), (0.3, 1.5)])
def test_stiff_contact_full_rotation_tends_to_rigid(vx: float, mu_factor: float) -> None:
    mu = mu_factor * mu_critical(PAPER_ROD, TH)
    _compare(
        PAPER_ROD, TH, vx, -1.41, 0.0, mu, law=_stiff_hertz(1e6), constant_angle=False, rel=1e-4
    )
