"""The closed forms read ``gravity`` as ``invert`` does (True or False; the acceleration is
``g``) and answer an angle that reads as degrees with ``simulate``'s hint."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab import analytic as A

CALLS = {
    "impact_duration": lambda **kw: A.impact_duration(22e-6, 1.4e-3, 1.41, -0.3, **kw),
    "mean_force_momentum": lambda **kw: A.mean_force_momentum(4e-3, 0.46, 0.6, **kw),
    "mean_force_rigid": lambda **kw: A.mean_force_rigid(4e-3, 0.4, 1.41, 6.0, **kw),
}


@pytest.mark.parametrize("name", sorted(CALLS))
def test_a_number_for_gravity_is_refused_with_g_named(name: str) -> None:
    with pytest.raises(ValueError, match=r"^gravity must be True or False, got 1\.62: the "):
        CALLS[name](gravity=1.62)
    with pytest.raises(ValueError, match=r"^gravity must be True or False, got 'no'$"):
        CALLS[name](gravity="no")
    on, moon = CALLS[name](gravity=True), CALLS[name](gravity=True, g=1.62)
    off = CALLS[name](gravity=False)
    assert on != moon != off and CALLS[name]() == off


def test_invert_refuses_a_number_for_gravity_alike() -> None:
    with pytest.raises(ValueError, match=r"got 1\.62: the acceleration is g, e\.g\. gravity=True"):
        il.invert(e=0.4, mu=0.2, v_i=-1.41, angle=0.35, delta_p=22e-6, sliding_length=1.4e-3,
                  gravity=1.62)  # fmt: skip


@pytest.mark.parametrize("call", [lambda a: A.alpha(a, 0.2), A.critical_friction])
def test_an_angle_in_degrees_gets_the_hint(call) -> None:  # type: ignore[no-untyped-def]
    hint = r"; if 20\.0 is meant in degrees, pass math\.radians\(20\.0\) = 0\.349066 rad"
    with pytest.raises(ValueError, match=r"^angle must be <= 1\.5708 rad, got 20\.0 rad" + hint):
        call(20.0)
    with pytest.raises(ValueError, match=r"^angle must be <= 1\.5708 rad, got 1\.7 rad$"):
        call(1.7)  # past the normal, not degrees: no hint
    assert call(math.radians(20.0)) == call("20 deg")
