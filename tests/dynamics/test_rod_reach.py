"""A rigid rod's impact that leaves the model's geometry is marked, never plain success:
BEYOND_TIP where the flat reaches the rim of the hemispherical tip (delta_max > R (1 -
|cos theta|)), OTHER_END where the other end comes within the interference of the flat
(L sin theta <= delta_max); ``simulate``, batches (both friction paths) and the command line
alike. A sphere is never so marked."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from typer.testing import CliRunner

import impactlab as il
from impactlab.cli import app
from impactlab.dynamics.rod_reach import rod_reach_bits, rod_reach_flags
from impactlab.flags import FLAG_BEYOND_TIP, FLAG_OTHER_END, ResultFlag

ROD = il.Rod.paper()
R, HALF = ROD.tip_radius, ROD.half_length


@pytest.mark.parametrize("deg", [2.0, 5.0, 20.0, 60.0, 89.0])
def test_the_rim_depth_is_the_threshold(deg: float) -> None:
    """Just below R (1 - cos theta) nothing, just above BEYOND_TIP (the angle unchanged)."""
    th = math.radians(deg)
    rim = R * (1.0 - math.cos(th))
    assert rod_reach_bits(HALF, R, th, th, rim * (1 - 1e-9)) & FLAG_BEYOND_TIP == 0
    assert rod_reach_bits(HALF, R, th, th, rim * (1 + 1e-9)) & FLAG_BEYOND_TIP


def test_the_other_end_is_checked_at_the_lower_angle() -> None:
    """The other end's lowest point lies 2 (L/2) sin theta - delta above the flat; the smaller
    angle of first touch and separation counts (a rod that turned past the flat: always)."""
    th = math.radians(0.01)
    reach = 2.0 * HALF * math.sin(th)
    assert rod_reach_bits(HALF, R, 0.5, 0.5, 0.9 * reach) & FLAG_OTHER_END == 0
    assert rod_reach_bits(HALF, R, 0.5, th, 0.9 * reach) & FLAG_OTHER_END == 0
    assert rod_reach_bits(HALF, R, 0.5, th, 1.1 * reach) & FLAG_OTHER_END
    assert rod_reach_bits(HALF, R, th, -1e-6, 1e-9) & FLAG_OTHER_END


def test_nan_inputs_set_nothing() -> None:
    assert rod_reach_bits(HALF, R, math.nan, math.nan, 1e-5) == 0
    assert rod_reach_bits(HALF, R, 0.3, 0.3, math.nan) == 0


@settings(max_examples=200, deadline=None)
@given(
    angle=st.floats(-0.1, math.pi),
    angle_out=st.floats(-0.1, math.pi),
    delta=st.floats(0.0, 2e-3),
)
def test_the_array_form_is_the_scalar_form(angle: float, angle_out: float, delta: float) -> None:
    one = rod_reach_bits(HALF, R, angle, angle_out, delta)
    many = rod_reach_flags(np.array([HALF]), np.array([R]), np.array([angle]),
                           np.array([angle_out]), np.array([delta]))  # fmt: skip
    assert int(many[0]) == one


@pytest.mark.parametrize("friction", ["coulomb", "partial_slip"])
def test_simulate_and_the_batch_mark_the_same_impacts(friction: str) -> None:
    """The paper's rod at 1.41 m/s: at 20 deg (delta_max 78 um, rim 531 um) plain; at 5 deg
    (73 um against a rim of 33.5 um) BEYOND_TIP; at 0.01 deg (the rod turns past the flat)
    OTHER_END too. The batch carries the same bits as ``simulate``."""
    degs = [0.01, 5.0, 20.0]
    batch = il.simulate_batch(ROD, angle=np.radians(degs), vy=-1.41, mu=0.2, friction=friction)
    for deg, bits in zip(degs, batch.flags, strict=True):
        r = il.simulate(ROD, angle=math.radians(deg), velocity=(0.0, -1.41), mu=0.2,
                        friction=friction, history=False)  # fmt: skip
        assert int(bits) == int(r.flags)
        th_low = min(math.radians(deg), r.angle_out)
        beyond = r.delta_max > R * (1.0 - math.cos(th_low))
        assert (ResultFlag.BEYOND_TIP in r.flags) == beyond == (deg < 10)
        assert (ResultFlag.OTHER_END in r.flags) == (deg < 1) == (r.angle_out < 0)
        assert r.ok == (deg > 10)
        assert any(w.startswith("beyond the tip") for w in r.warnings) == beyond


def test_a_sphere_is_never_marked() -> None:
    r = il.simulate(il.Sphere(radius=5e-3), velocity=(0.3, -5.0), mu=0.2, history=False)
    assert not r.flags & (FLAG_BEYOND_TIP | FLAG_OTHER_END)


def test_the_command_line_warns() -> None:
    res = CliRunner().invoke(
        app, ["simulate", "rod", "--angle", "5 deg", "--vy", "-1.41 m/s", "--mu", "0.2"]
    )
    assert res.exit_code == 0, res.output
    assert "beyond the tip" in res.output and "beyond_tip" in res.output


@pytest.mark.parametrize("body", [ROD, il.FlexibleRod.paper(n_axial=1, n_bending=2)])
def test_a_drop_marks_a_contact_beyond_the_rim(body: il.Rod | il.FlexibleRod) -> None:
    """A drop checks every contact's interference against the rim of its end at its contacts'
    angles at touch and separation (a flexible rod's: its end section's, the rod's plus the
    elastic rotation): at 5 deg, mu = 0.2, the tip's first contact (73 um for the rigid rod,
    46 um for the 1+2-mode rod) passes the rim (33.5 um at 5 deg; 32.7 um at the 1+2-mode
    rod's section angles), at 20 deg (rim 531 um) none does; the batch of drops carries the
    same bits."""
    for deg, beyond in ((5.0, True), (20.0, False)):
        r = il.simulate_drop(body, angle=math.radians(deg), velocity=(0.0, -1.41), mu=0.2,
                             history=False)  # fmt: skip
        assert (ResultFlag.BEYOND_TIP in r.flags) == beyond
        assert not r.ok if beyond else r.ok
        if isinstance(body, il.FlexibleRod):
            b = il.simulate_drops(body, angle=math.radians(deg), vy=[-1.41], mu=0.2)
            assert int(b.flags[0]) == int(r.flags)
