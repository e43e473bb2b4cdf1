"""Eq. 12 with an incoming tangential velocity of the tip (``vt_in``): the inversion against the
engine's own dents, the closed forms' round trip, the bounds where the sliding reverses, and
today's numbers where it is absent."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab import analytic as an
from impactlab.bodies import PAPER_ROD

#: Eq. 12 on the engine's dents: the bound of the reproduction's check (docs/paper/reproduction.md)
ENGINE_REL = 6e-4
FLAT = il.get_material("aisi-1010")


def _engine(deg: float, mu: float, vx: float, spin: float) -> il.dynamics.ImpactResult:
    return il.simulate(
        PAPER_ROD, FLAT, mu=mu, angle=math.radians(deg), velocity=(vx, -2.18), spin=spin
    )


def _invert(r, deg: float, **kw):
    mu = abs(r.tangential_impulse / r.normal_impulse)
    return an.invert(
        angle=math.radians(deg), v_i=r.vn_in, mu=mu, e=r.e, delta_p=r.delta_p, n_samples=100, **kw
    )


@pytest.mark.parametrize(
    ("deg", "mu", "vx", "spin"),
    [
        (45, 0.13, -0.3, 0.0),
        (45, 0.13, 0.0, -3.0),
        (45, 0.13, -0.2, -2.0),
        (70, 0.10, -0.3, 0.0),
        (70, 0.10, 0.0, -3.0),
    ],
)
def test_invert_with_vt_in_recovers_the_engines_duration(deg, mu, vx, spin):
    r = _engine(deg, mu, vx, spin)
    assert str(r.regime) == "slip" and r.vt_in < 0
    slip = _invert(r, deg, sliding_length=r.sliding_length, vt_in=r.vt_in)
    assert slip.duration == pytest.approx(r.duration, rel=ENGINE_REL)
    # the patch's travel with the tip sphere's centre's velocity, v_t0 - R omega
    travel = _invert(
        r,
        deg,
        sliding_length=r.contact_travel,
        vt_in=r.vt_in - PAPER_ROD.tip_radius * spin,
        measure="travel",
    )
    assert travel.duration == pytest.approx(r.duration, rel=ENGINE_REL)
    # without it (the paper's form) T is far off
    assert _invert(r, deg, sliding_length=r.sliding_length).duration > 1.2 * r.duration


def test_a_reversing_slip_is_bounded_and_warned():
    deg = 45
    r = _engine(deg, 0.13, 0.3, 0.0)
    assert str(r.regime) == "reversal" and r.vt_in > 0
    low = _invert(r, deg, sliding_length=r.sliding_length).duration
    with pytest.warns(il.ImplausibleInputWarning, match=r"vt_in = 0.3 \+- 0 m/s > 0") as rec:
        res = _invert(r, deg, sliding_length=r.sliding_length, vt_in=r.vt_in)
    assert low < r.duration < res.duration
    text = str(rec[0].message)
    assert f"T lies between {low:.4g} s" in text and f"and {res.duration:.4g} s" in text
    assert res.warnings == (text,)
    # within 3 sigma of 0: no bounds of the nominal T, but the Monte Carlo's samples above 0
    with pytest.warns(il.ImplausibleInputWarning, match=r"Monte Carlo samples have vt_in > 0"):
        within = _invert(r, deg, sliding_length=r.sliding_length, vt_in=(r.vt_in, 0.2))
    assert not any("T lies between" in w for w in within.warnings)


def test_vt_in_at_or_beyond_alpha_vi_is_refused():
    base = dict(angle="45 deg", v_i=-2.18, mu=0.13, e=0.49, delta_p=26e-6, sliding_length=1650e-6)
    al = abs(an.alpha(math.radians(45), 0.13))
    with pytest.raises(
        ValueError, match=r"vt_in = 1\.3 m/s is at least \|alpha\| \|v_i\| = 1\.204"
    ):
        an.invert(**base, vt_in=1.3)
    assert al * 2.18 == pytest.approx(1.204, abs=1e-3)


def test_without_vt_in_the_numbers_are_todays():
    base = dict(
        angle=math.radians(20),
        v_i=-1.41,
        mu=(0.2, 0.01),
        e=0.5,
        delta_p=22e-6,
        sliding_length=(1400e-6, 50e-6),
    )
    ref = an.invert(**base)
    for zero in (0.0, (0.0, 0.0), an.Measured(0.0)):
        assert an.invert(**base, vt_in=zero).to_dict() == ref.to_dict()
    assert "vt_in" not in ref.inputs
    assert ref.duration == pytest.approx(4.10595e-3, rel=1e-5)


def test_vt_in_is_propagated_with_its_sigma():
    base = dict(angle="45 deg", v_i=-2.18, mu=0.13, e=0.49, delta_p=26e-6, sliding_length=1650e-6)
    res = an.invert(**base, vt_in=("-0.3 m/s", 0.01))
    al = abs(res.alpha)
    T = (26e-6 + 1650e-6 / al) / (2.18 + 0.3 / al)
    assert res.duration == pytest.approx(T, rel=1e-12)
    assert res.inputs["vt_in"] == (-0.3, 0.01)
    # dT/dvt_in = T / (|alpha| |v_i| - vt_in)
    assert res.sensitivity_T["vt_in"] == pytest.approx(T / (al * 2.18 + 0.3), rel=1e-6)
    assert res.sigma_T_mc == pytest.approx(res.sigma_T_linear, rel=0.05)
    assert "vt_in = -0.3 ± 0.01 m/s" in str(res)


def test_closed_forms_round_trip_with_vt_in():
    th, mu = math.radians(20), 0.2
    al = an.alpha(th, mu)
    for gravity in (False, True):
        T = an.impact_duration(22e-6, 1400e-6, -1.41, al, vt_in=-0.1, gravity=gravity)
        assert T < an.impact_duration(22e-6, 1400e-6, -1.41, al, gravity=gravity)
    T = an.impact_duration(22e-6, 1400e-6, -1.41, al, vt_in=-0.1)
    assert an.sliding_length(22e-6, -1.41, T, th, mu, vt_in=-0.1) == pytest.approx(-1400e-6)
    assert an.sliding_length(22e-6, -1.41, T, th, mu, vt_in=0.0) == an.sliding_length(
        22e-6, -1.41, T, th, mu
    )


def test_closed_forms_refuse_a_reversing_slip_with_the_bounds():
    al = an.alpha(math.radians(20), 0.2)
    with pytest.raises(
        ValueError,
        match=r"vt_in must be <= 0 m/s .* got 0.1 m/s: .* T lies between 0.004106 s \(the value "
        r"for vt_in = 0\) and 0.005801 s$",
    ):
        an.impact_duration(22e-6, 1400e-6, -1.41, al, vt_in=0.1)
    with pytest.raises(ValueError, match=r"vt_in must be <= 0 m/s"):
        an.sliding_length(22e-6, -1.41, 4e-3, math.radians(20), 0.2, vt_in="0.1 m/s")
