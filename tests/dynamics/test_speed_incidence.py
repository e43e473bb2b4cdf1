"""Speed and incidence as the alternative to (vx, vy): the same impact in Python, on the command
line and in study files; both or neither refused with one line."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab import simulate
from impactlab.bodies import PAPER_ROD, Sphere
from impactlab.cli._common import UserError, velocity_input
from impactlab.dynamics.input_checks import velocity_from
from impactlab.materials import AISI_52100, AL_6061_T6
from impactlab.sweep import Study


@settings(deadline=None, max_examples=15)
@given(
    speed=st.floats(0.2, 5.0),
    incidence=st.floats(-60.0, 60.0),
    angle=st.floats(15.0, 90.0),
    mu=st.floats(0.0, 0.5),
)
def test_speed_and_incidence_give_the_same_impact_as_vx_vy(speed, incidence, angle, mu) -> None:
    """The property: simulate(speed=, incidence=) is simulate(velocity=(s sin i, -s cos i))."""
    th = math.radians(incidence)
    vel = (speed * math.sin(th), -speed * math.cos(th))
    kw = {"law": "hertz", "mu": mu, "angle": math.radians(angle)}
    try:
        ref = simulate(PAPER_ROD, velocity=vel, **kw)
    except ValueError:  # the contact point does not approach: refused the same way
        with pytest.raises(ValueError, match="does not approach"):
            simulate(PAPER_ROD, speed=speed, incidence=f"{incidence!r} deg", **kw)
        return
    r = simulate(PAPER_ROD, speed=f"{speed!r} m/s", incidence=f"{incidence!r} deg", **kw)
    assert r.velocity_in == pytest.approx(ref.velocity_in, rel=1e-15, abs=1e-15)
    for key in ("e", "delta_p", "sliding_length", "duration", "mean_force"):
        assert getattr(r, key) == pytest.approx(getattr(ref, key), rel=1e-12, abs=1e-15), key


def test_sign_convention_and_the_sphere() -> None:
    assert velocity_from(None, 2.0, math.radians(30)) == pytest.approx((1.0, -math.sqrt(3)))
    vx, vy = velocity_from(None, "2 m/s", "-30 deg")
    assert vx == pytest.approx(-1.0) and vy == pytest.approx(-math.sqrt(3))
    ball = Sphere(radius=0.003, material=AISI_52100)
    r = simulate(ball, AL_6061_T6, speed="2.5 m/s", incidence="0 deg")
    assert r.velocity_in == pytest.approx((0.0, -2.5))


@pytest.mark.parametrize(
    ("velocity", "speed", "incidence", "message"),
    [
        (None, None, None, "give the velocity of the centre of mass"),
        ((0.0, -1.0), 1.0, 0.1, "not both"),
        (None, 1.0, None, "incidence is missing"),
        (None, None, "10 deg", "speed is missing"),
        (None, -1.0, 0.1, "speed must be"),
        (None, 1.0, "95 deg", r"incidence must lie in \(-90, 90\) deg"),
        (None, 1.0, 20.0, "a bare incidence is radians"),
    ],
)
def test_both_or_neither_refused(velocity, speed, incidence, message) -> None:
    with pytest.raises(ValueError, match=message):
        simulate(PAPER_ROD, angle=0.3, velocity=velocity, speed=speed, incidence=incidence)


def test_command_line_pair() -> None:
    assert velocity_input(None, None, "2 m/s", "30 deg") == pytest.approx((1.0, -math.sqrt(3)))
    assert velocity_input(None, "-1.41 m/s", None, None) == (0.0, -1.41)
    with pytest.raises(UserError, match="both given"):
        velocity_input(None, "-1 m/s", "2 m/s", "30 deg")
    with pytest.raises(UserError, match="--incidence 30 has no unit"):
        velocity_input(None, None, "2 m/s", "30")
    with pytest.raises(UserError, match="--vy is required"):
        velocity_input(None, None, None, None)
    with pytest.raises(UserError, match="go together: --speed is missing"):
        velocity_input(None, None, None, "30 deg")


def test_study_speed_and_incidence() -> None:
    st_ = Study.from_dict(
        {
            "fixed": {"mu": 0.1, "angle": "30 deg", "speed": "2 m/s"},
            "grid": {"incidence": ["0 deg", "30 deg"]},
        }
    )
    num, _, _ = st_.chunk_cases(0)
    assert num["vx"] == pytest.approx([0.0, 1.0])
    assert num["vy"] == pytest.approx([-2.0, -math.sqrt(3)])
    with pytest.raises(ValueError, match="go together: incidence has no value"):
        Study.from_dict({"fixed": {"mu": 0.1, "angle": "30 deg"}, "grid": {"speed": [1, 2]}})
    with pytest.raises(ValueError, match="vy and speed/incidence both set"):
        Study.from_dict(
            {
                "fixed": {"mu": 0.1, "angle": "30 deg", "vy": -1, "speed": 1},
                "grid": {"incidence": ["1 deg"]},
            }
        )
    with pytest.raises(ValueError, match=r"incidence.*has no unit"):
        Study.from_dict(
            {"fixed": {"mu": 0.1, "angle": "3 deg", "speed": 1}, "grid": {"incidence": [10]}}
        )


def test_batch_speed_and_incidence() -> None:
    from impactlab import simulate_batch

    inc = [0.0, 0.2, 0.4]
    by_speed = simulate_batch(PAPER_ROD, law="hertz", angle=0.6, speed=1.5, incidence=inc)
    vx = [1.5 * math.sin(i) for i in inc]
    vy = [-1.5 * math.cos(i) for i in inc]
    ref = simulate_batch(PAPER_ROD, law="hertz", angle=0.6, vx=vx, vy=vy)
    assert list(by_speed.e) == list(ref.e) and list(by_speed.status) == list(ref.status)
    with pytest.raises(ValueError, match="not both"):
        simulate_batch(PAPER_ROD, law="hertz", angle=0.6, vy=-1.0, speed=1.0, incidence=0.1)
    with pytest.raises(ValueError, match="vy is required"):
        simulate_batch(PAPER_ROD, law="hertz", angle=0.6)
