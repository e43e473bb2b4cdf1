"""Batches through the Python API: a refused case's message names its input and value, the
velocity as one pair, and the notebook summary of a batch of drops."""

from __future__ import annotations

import numpy as np
import pytest

import impactlab as il
from impactlab.dynamics.kernels.status import ST_BAD_INPUT, ST_OK

ROD = il.Rod.paper()


def test_batch_messages_name_the_refused_input_and_value() -> None:
    mu = [0.2, np.nan, 2000.0, 0.2, 0.2]
    angle = [0.35, 0.35, 0.35, np.nan, 0.35]
    vy = [-1.41, -1.41, -1.41, -1.41, -2.0e4]
    b = il.simulate_batch(ROD, il.AISI_1010, mu=mu, angle=angle, vy=vy)  # 2e4 m/s: refused
    assert b.status.tolist() == [ST_OK] + [ST_BAD_INPUT] * 4
    assert b.messages == [
        "ok",
        "invalid input: mu = nan is not finite",
        "invalid input: mu must lie in [0, 1000] (dry friction stays below about 2; a larger "
        "mu only sticks), got 2000.0",
        "invalid input: angle = nan is not finite",
        "invalid input: vy = -20000.0: a velocity component must be finite and at most 10000 m/s",
    ]
    assert sorted(b.refusals) == [1, 2, 3, 4]


def test_batch_and_drop_batch_word_a_refusal_alike() -> None:
    kw = {"mu": [0.2, np.nan, 2000.0], "angle": 0.35, "vy": -1.41}
    b = il.simulate_batch(ROD, il.AISI_1010, **kw)
    d = il.simulate_drops(ROD, il.AISI_1010, **kw)
    assert b.messages[1:] == d.messages[1:]


def test_a_sphere_batch_names_its_refused_input() -> None:
    b = il.simulate_batch(il.Sphere(radius=0.005), law="hertz", vy=[-1.0, np.nan], mu=[0.1, -1])
    assert b.messages == ["ok", "invalid input: vy = nan is not finite"]
    b = il.simulate_batch(il.Sphere(radius=0.005), law="hertz", vy=-1.0, mu=[0.1, -1.0])
    assert b.messages == ["ok", "invalid input: mu must be >= 0, got -1.0"]


def test_good_cases_have_no_refusals() -> None:
    b = il.simulate_batch(ROD, il.AISI_1010, angle=[0.3, 0.35], vy=-1.41, mu=0.2)
    assert b.refusals == {}
    assert b.messages == ["ok", "ok"]


def test_batch_takes_the_velocity_as_one_pair() -> None:
    pair = il.simulate_batch(ROD, angle=0.35, mu=0.2, velocity=(0.1, [-1.41, -2.0]))
    split = il.simulate_batch(ROD, angle=0.35, mu=0.2, vx=0.1, vy=[-1.41, -2.0])
    np.testing.assert_array_equal(pair.out, split.out)
    assert pair.inputs["vx"].tolist() == [0.1, 0.1]
    one = il.simulate_batch(ROD, angle=0.35, mu=0.2, velocity=("0.1 m/s", "-141 cm/s"))
    np.testing.assert_array_equal(one.out[0], split.out[0])
    drops = il.simulate_drops(ROD, angle=0.35, mu=0.2, velocity=(0.1, [-1.41, -2.0]))
    np.testing.assert_array_equal(
        drops.out, il.simulate_drops(ROD, angle=0.35, mu=0.2, vx=0.1, vy=[-1.41, -2.0]).out
    )


@pytest.mark.parametrize(
    ("extra", "message"),
    [
        ({"vy": -1.0}, r"not velocity= with vy="),
        ({"vx": 0.0, "vy": -1.0}, r"not velocity= with vx= and vy="),
        ({"speed": 1.0, "incidence": 0.1}, r"not velocity= with speed= and incidence="),
    ],
)
def test_velocity_pair_with_its_components_is_refused(extra: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        il.simulate_batch(ROD, angle=0.35, velocity=(0.0, -1.41), **extra)


@pytest.mark.parametrize("velocity", [-1.41, "0, -1.41", (0.0, -1.0, 2.0), {"vx": 0.0}])
def test_velocity_that_is_no_pair_is_refused(velocity: object) -> None:
    with pytest.raises(ValueError, match=r"^velocity must be a pair \(vx, vy\) in m/s") as err:
        il.simulate_batch(ROD, angle=0.35, velocity=velocity)
    assert "\n" not in str(err.value)


def test_drop_batch_shows_a_notebook_summary() -> None:
    d = il.simulate_drops(ROD, il.AISI_1010, mu=[0.2, np.nan], angle=0.35, vy=-1.41)
    b = il.simulate_batch(ROD, il.AISI_1010, mu=[0.2, np.nan], angle=0.35, vy=-1.41)
    html = d._repr_html_()
    assert html.startswith("<div><strong>DropBatchResult</strong><p>2 cases, 1 computed, 1 ok")
    for name in ("dent_depth", "sequence_duration", "sequence_sliding_length", "max_force"):
        assert f"<tr><td>{name}</td>" in html
    assert "<tr><td>delta_p</td>" not in html
    # the same table as BatchResult's (the rigid rod's drop is its impact, to the same digits)
    assert b._repr_html_().count("<tr>") == html.count("<tr>")
    assert "law ghaednia, friction coulomb" in html


@pytest.mark.parametrize(
    "velocity",
    [
        [(-0.5, -1.41), (-0.3, -2.0)],  # two cases' pairs: read as vx=[-0.5, -1.41] before
        ((0.0, -1.41), (0.0, -2.0)),
        np.array([[0.0, 0.0], [-1.41, -2.0]]),
    ],
)
def test_two_by_two_velocity_is_refused_as_ambiguous(velocity: object) -> None:
    with pytest.raises(
        ValueError, match=r"^velocity: .* could be two cases' \(vx, vy\) pairs"
    ) as err:
        il.simulate_batch(ROD, angle=[0.35, 0.35], mu=0.2, velocity=velocity)
    message = str(err.value)
    assert "\n" not in message and "pass vx= and vy=" in message


def test_velocity_components_are_numbers_or_1d_arrays() -> None:
    pair = (np.array([-0.5, -0.3]), np.array([-1.41, -2.0]))  # stated as the arrays (vx, vy)
    arrays = il.simulate_batch(ROD, angle=0.35, mu=0.2, velocity=pair)
    split = il.simulate_batch(ROD, angle=0.35, mu=0.2, vx=[-0.5, -0.3], vy=[-1.41, -2.0])
    np.testing.assert_array_equal(arrays.out, split.out)
    assert arrays.inputs["vy"].tolist() == [-1.41, -2.0]
    with pytest.raises(ValueError, match=r"^velocity must be a pair .* each a number or a 1-D"):
        il.simulate_batch(ROD, angle=0.35, velocity=([[0.0, 0.1, 0.2]], [-1.0, -1.2, -1.4]))


def test_angle_and_approach_refusals_name_the_value() -> None:
    with pytest.warns(il.ImplausibleInputWarning, match="every refused angle .* degrees"):
        b = il.simulate_batch(ROD, angle=[0.35, 2.0, 0.35], vy=[-1.41, -1.41, 1.0], mu=0.2)
    assert b.messages[0] == "ok"
    assert b.messages[1].startswith(
        "angle outside (0, pi/2] radians: angle = 2.0 rad = 114.6 deg: the rod leans past the "
        "flat's normal, the mirror of a drop at angle = 1.14159 rad (65.4084 deg)"
    )
    assert b.messages[2] == (
        "the contact point does not approach the flat (normal velocity >= 0): vn = +1.0 m/s"
    )
    with pytest.warns(il.ImplausibleInputWarning, match="every refused angle .* degrees"):
        d = il.simulate_drops(ROD, angle=[0.35, 2.0, 0.35], vy=[-1.41, -1.41, 1.0], mu=0.2)
    assert d.messages[1] == b.messages[1]
    assert d.messages[2].endswith("(normal velocity >= 0): vy = 1.0 m/s, spin = 0.0 rad/s, "
                                  "angle = 0.35 rad")  # fmt: skip
