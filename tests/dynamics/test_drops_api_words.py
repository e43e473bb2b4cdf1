"""The words of the drop and impact APIs' refusals: an angle just past 90 deg is said to lean
past the flat's normal (its mirror image named), the degrees hint only where a number may be
degrees; a batch refuses mu in the words of one run; ``simulate_drops`` refuses a rate law with
its reason and the alternative."""

from __future__ import annotations

import math

import numpy as np
import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD, FlexibleRod
from impactlab.dynamics.drop import simulate_drop
from impactlab.dynamics.input_checks import PAST_NORMAL, check_angle, check_mu, mu_problem

MIRROR = "the rod leans past the flat's normal, the mirror of a drop at angle = "
NEGATED = "with vx (or incidence) and spin negated"


def _angle_error(angle: object) -> str:
    with pytest.raises(ValueError, match="angle must be") as info:
        check_angle(angle, PAPER_ROD)
    return str(info.value)


@pytest.mark.parametrize("run", ["simulate_drop", "simulate"])
def test_91_deg_in_radians_is_a_rod_past_the_normal_not_degrees(run) -> None:
    kw = {"angle": math.radians(91), "velocity": (0.0, -1.41)}
    call = simulate_drop if run == "simulate_drop" else il.simulate
    body = FlexibleRod.paper() if run == "simulate_drop" else PAPER_ROD
    with pytest.raises(ValueError, match="angle must be") as info:
        call(body, **kw)
    text = str(info.value)
    assert text == (
        f"angle must be in radians in (0, pi/2], got {math.radians(91)!r} rad (91 deg): "
        f"{MIRROR}1.55334 rad (89 deg) {NEGATED} (x runs from the tip towards the centre of mass)"
    )
    assert "meant in degrees" not in text


@pytest.mark.parametrize(
    ("angle", "mirror", "degrees"),
    [
        (1.6, "1.54159 rad (88.3268 deg)", False),  # within PAST_NORMAL of pi/2: radians
        (0.5 * math.pi + PAST_NORMAL, "1.39626 rad (80 deg)", False),
        (2.0, "1.14159 rad (65.4084 deg)", True),  # beyond it: degrees too (2 deg?)
        (3.0, "0.141593 rad (8.11266 deg)", True),
        (20.0, None, True),  # past pi: no rod's angle in radians, degrees alone
        (90.0, None, True),
        (120.0, None, False),  # beyond 90: neither
        (-0.2, None, False),
    ],
)
def test_which_hint_a_bare_angle_gets(angle, mirror, degrees) -> None:
    text = _angle_error(angle)
    assert text.startswith(f"angle must be in radians in (0, pi/2], got {angle!r} rad")
    assert (f"{MIRROR}{mirror} {NEGATED}" in text) if mirror else (MIRROR not in text)
    hint = f"if {angle!r} is meant in degrees, pass math.radians({angle!r}) = "
    assert (hint in text) is degrees
    if mirror or degrees:  # the angle in degrees leads the hints, as before
        assert f"got {angle!r} rad ({math.degrees(angle):.6g} deg)" in text


def test_an_angle_with_a_unit_past_90_deg_says_what_it_means() -> None:
    assert _angle_error("95 deg") == (
        f"angle must be in (0, 90] deg, got 95 deg: {MIRROR}85 deg {NEGATED} (x runs from the "
        "tip towards the centre of mass)"
    )
    assert _angle_error("200 deg") == "angle must be in (0, 90] deg, got 200 deg"


def test_the_mirrored_angle_is_the_mirror_image() -> None:
    """What the hint says: at pi - th the centre of mass lies where it lies at th with x
    negated (lever arms (-a, b), paper Eq. 1), so the drop is the mirror image (x -> -x: vx and
    the counter-clockwise spin change sign) of one at th."""
    th = math.radians(100)
    assert f"{MIRROR}{math.pi - th:.6g} rad (80 deg) {NEGATED}" in _angle_error(th)
    a, b = il.bodies.lever_arms(PAPER_ROD.half_length, PAPER_ROD.tip_radius, th)
    a0, b0 = il.bodies.lever_arms(PAPER_ROD.half_length, PAPER_ROD.tip_radius, math.pi - th)
    assert a == pytest.approx(-a0, rel=1e-12) and b == pytest.approx(b0, rel=1e-12)


@pytest.mark.parametrize("mu", [-0.1, -1.0, 2000.0, 1e300])
def test_a_batch_refuses_mu_in_the_words_of_one_run(mu) -> None:
    with pytest.raises(ValueError, match=r"^mu must") as one:
        il.simulate(PAPER_ROD, angle=0.35, velocity=(0.0, -1.41), mu=mu)
    with pytest.raises(ValueError, match=r"^mu must") as drop:
        simulate_drop(PAPER_ROD, angle=0.35, velocity=(0.0, -1.41), mu=mu)
    assert str(one.value) == str(drop.value) == mu_problem(mu)
    kw = {"angle": 0.35, "vy": -1.41, "mu": [0.2, mu]}
    for batch in (il.simulate_batch(PAPER_ROD, **kw), il.simulate_drops(PAPER_ROD, **kw)):
        assert batch.messages[1] == f"invalid input: {one.value}"


def test_mu_words_name_the_rule_and_why() -> None:
    assert mu_problem(-0.1) == "mu must be >= 0, got -0.1"
    assert mu_problem(2000.0) == (
        "mu must lie in [0, 1000] (dry friction stays below about 2; a larger mu only sticks), "
        "got 2000.0"
    )
    assert mu_problem(0.0) == mu_problem(1000.0) == ""
    assert check_mu(0.2) == 0.2 and check_mu(-0.0) == 0.0
    with pytest.raises(ValueError, match="mu must be finite, got nan"):
        check_mu(math.nan)


def test_simulate_drops_refuses_a_rate_law_with_its_reason() -> None:
    with pytest.raises(ValueError, match="rate") as info:
        il.simulate_drops(FlexibleRod.paper(), angle=[0.3], vy=-1, rate="cowper-symonds")
    text = str(info.value)
    assert text.startswith("rate='cowper-symonds': simulate_drops takes no rate-dependent flat")
    assert "iterated drop by drop" in text
    assert "simulate_drop(body, flat, rate='cowper-symonds', ...) for each case" in text
    b = il.simulate_drops(FlexibleRod.paper(), angle=[0.3], vy=-1.0, rate=None, mu=0.1)
    assert b.status.tolist() == [0] and np.isfinite(b.e).all()
    none = il.simulate_drops(FlexibleRod.paper(), angle=[0.3], vy=-1.0, rate="none", mu=0.1)
    assert np.array_equal(none.e, b.e)  # "none", as simulate_drop takes it: no law
    with pytest.raises(ValueError, match="rate must be one of"):
        il.simulate_drops(FlexibleRod.paper(), angle=[0.3], vy=-1.0, rate=False)


@pytest.mark.parametrize("command", [("simulate", "rod"), ("drop", "--rigid")])
def test_the_command_line_says_the_same_of_an_angle_past_the_normal(cli_main, command) -> None:
    code, out, err = cli_main(*command, "--angle", "95 deg", "--vy", "-1 m/s")
    assert (code, out) == (2, "")
    assert err.startswith("error: --angle must be in (0, 90] deg, got 95 deg: ")
    assert f"{MIRROR}85 deg {NEGATED}" in err


def test_batches_and_sweeps_say_the_same_of_an_angle_past_the_normal() -> None:
    b = il.simulate_batch(il.Rod.paper(), angle=[1.7, 0.3], vy=-1.0)
    d = il.simulate_drops(il.Rod.paper(), angle=[1.7, 0.3], vy=-1.0)
    for messages in (b.messages, d.messages):
        assert messages[0].startswith("angle outside (0, pi/2] radians: angle = 1.7 rad")
        assert f"{MIRROR}1.44159 rad (82.5972 deg) {NEGATED}" in messages[0]
    from impactlab.sweep import Study

    with pytest.raises(ValueError, match="past the flat's normal") as info:
        Study(name="s", grid={"angle": ["20 deg", "95 deg"]}, fixed={"vy": -1.0, "mu": 0.2})
    assert str(info.value).startswith(
        "grid dimension 'angle': angle must lie in (0, 90] deg, got 95 deg (1 of 2 values): "
    )
