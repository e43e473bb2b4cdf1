"""One rule per input: the API, a batch, a batch of drops, a sweep's study check and the
command line refuse exactly what ``dynamics.kernels.inputs.input_problem`` refuses."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from impactlab import simulate, simulate_batch, simulate_drop, simulate_drops
from impactlab.bodies import PAPER_ROD
from impactlab.cli._common import angle_quantity
from impactlab.dynamics.kernels import inputs as I
from impactlab.dynamics.kernels.status import ST_BAD_ANGLE, ST_BAD_INPUT
from impactlab.sweep.dimensions import check_value

REACH = PAPER_ROD.half_length + PAPER_ROD.tip_radius
#: One valid impact: (angle, vx, vy, spin, mu, gravity, rtol).
VALID = (math.radians(20), 0.0, -1.41, 0.0, 0.2, 9.80665, 1e-7)
#: For each rule: the input's position in VALID, a value just inside and one just outside.
EDGES = {
    I.IN_ANGLE: (0, I.MAX_ANGLE, math.nextafter(I.MAX_ANGLE, 2.0)),
    I.IN_VX: (1, -I.MAX_SPEED, math.nextafter(-I.MAX_SPEED, -math.inf)),
    I.IN_VY: (2, -I.MAX_SPEED, math.nextafter(-I.MAX_SPEED, -math.inf)),
    I.IN_SPIN: (3, I.MAX_SPEED / REACH, 1.000001 * I.MAX_SPEED / REACH),
    I.IN_MU: (4, I.MAX_MU, math.nextafter(I.MAX_MU, math.inf)),
    I.IN_GRAVITY: (5, I.MAX_GRAVITY, math.nextafter(I.MAX_GRAVITY, math.inf)),
    I.IN_RTOL: (6, I.RTOL_MAX, math.nextafter(I.RTOL_MAX, 1.0)),
}


def problem(case: tuple[float, ...]) -> int:
    th, vx, vy, w, mu, g, r = case
    return I.input_problem(True, th, vx, vy, w, REACH, mu, g, r)


def with_value(position: int, value: float) -> tuple[float, ...]:
    case = list(VALID)
    case[position] = value
    return tuple(case)


@pytest.mark.parametrize("code", sorted(EDGES))
def test_each_rule_holds_at_its_bound_and_breaks_just_past_it(code: int) -> None:
    position, inside, outside = EDGES[code]
    assert problem(with_value(position, inside)) == I.IN_OK
    assert problem(with_value(position, outside)) == code
    assert problem(with_value(position, math.nan)) == code
    assert code in I.INPUT_RULES and I.problem_text(code, outside).startswith(
        I.INPUT_RULES[code][0]
    )


def test_the_angle_is_the_last_rule_a_sphere_has_none() -> None:
    case = with_value(4, -1.0)  # mu < 0 with the angle out of range: mu is named
    assert problem(with_value(0, 2.0)) == I.IN_ANGLE
    assert problem((2.0, *case[1:])) == I.IN_MU
    assert I.input_problem(False, math.nan, 0.0, -1.0, 0.0, 0.01, 0.2, 9.8, 1e-7) == I.IN_OK


def _simulate(case: tuple[float, ...]) -> None:
    th, vx, vy, w, mu, g, r = case
    simulate(PAPER_ROD, angle=th, velocity=(vx, vy), spin=w, mu=mu, gravity=g, rtol=r)


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
@pytest.mark.parametrize("code", sorted(EDGES))
def test_simulate_names_the_input_past_its_bound(code: int) -> None:
    position, _, outside = EDGES[code]
    name = I.INPUT_RULES[code][0]
    with pytest.raises(ValueError, match=name):
        _simulate(with_value(position, outside))


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
def test_batches_and_drops_refuse_the_case_past_a_bound() -> None:
    # the per-case inputs; gravity and rtol are one value per batch (their own ValueError)
    per_case = [c for c in sorted(EDGES) if EDGES[c][0] <= 4]
    cases = [with_value(EDGES[c][0], EDGES[c][2]) for c in per_case] + [VALID]
    th, vx, vy, w, mu = (np.array([c[k] for c in cases]) for k in range(5))
    expected = [ST_BAD_ANGLE if c == I.IN_ANGLE else ST_BAD_INPUT for c in per_case] + [0]
    batch = simulate_batch(PAPER_ROD, angle=th, vx=vx, vy=vy, spin=w, mu=mu)
    assert list(batch.status) == expected
    drops = simulate_drops(PAPER_ROD, angle=th, vx=vx, vy=vy, spin=w, mu=mu)
    assert list(drops.status) == expected
    for position, value in ((5, EDGES[I.IN_GRAVITY][2]), (6, EDGES[I.IN_RTOL][2])):
        name = I.INPUT_RULES[I.IN_GRAVITY if position == 5 else I.IN_RTOL][0]
        options = {"gravity": value} if position == 5 else {"rtol": value}
        with pytest.raises(ValueError, match=name):
            simulate_batch(PAPER_ROD, angle=0.35, vy=-1.0, **options)
        with pytest.raises(ValueError, match=name):
            simulate_drops(PAPER_ROD, angle=0.35, vy=-1.0, **options)


@pytest.mark.parametrize(
    ("name", "code"), [("angle", I.IN_ANGLE), ("vx", I.IN_VX), ("vy", I.IN_VY), ("mu", I.IN_MU)]
)
def test_a_study_takes_what_an_impact_takes(name: str, code: int) -> None:
    _, inside, outside = EDGES[code]
    if name != "angle":  # a rod's angle is a study-level rule (check_kinematics)
        assert check_value(name, inside) == inside
        with pytest.raises(ValueError, match=name):
            check_value(name, outside)
    else:
        assert math.isclose(angle_quantity("90 deg", "--angle"), 0.5 * math.pi)
        with pytest.raises(ValueError, match="must be in"):
            angle_quantity("90.0001 deg", "--angle")


_VALUE = st.floats(allow_nan=True, allow_infinity=True, width=64)


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")
@settings(max_examples=60, deadline=None)
@given(
    vx=st.one_of(st.floats(-2.0, 2.0), _VALUE),
    mu=st.one_of(st.floats(0.0, 1.0), _VALUE),
    spin=st.one_of(st.just(0.0), _VALUE),
    angle=st.one_of(st.floats(0.05, 1.5), _VALUE),
)
def test_the_compiled_core_and_python_apply_one_rule(
    vx: float, mu: float, spin: float, angle: float
) -> None:
    case = (angle, vx, -1.2, spin, mu, 9.80665, 1e-7)
    code = problem(case)
    # an array of angles: the compiled core's status per case (one angle alone is checked by
    # Python first, as simulate checks it)
    batch = simulate_batch(PAPER_ROD, angle=[angle], vx=vx, vy=-1.2, spin=spin, mu=mu)
    status = int(batch.status[0])
    if code == I.IN_OK:
        assert status not in (ST_BAD_INPUT, ST_BAD_ANGLE)
    else:
        assert status == (ST_BAD_ANGLE if code == I.IN_ANGLE else ST_BAD_INPUT)


def test_a_drop_names_the_spin_past_its_bound() -> None:
    spin = EDGES[I.IN_SPIN][2]
    with pytest.raises(ValueError, match=r"spin = .* rad/s moves the contact point"):
        simulate_drop(PAPER_ROD, angle=0.35, velocity=(0.0, -1.0), spin=spin)
