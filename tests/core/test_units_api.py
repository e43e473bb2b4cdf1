"""The Python API takes pint quantities of any registry and unit strings wherever it takes a
dimensional float: the same numbers as SI floats."""

from __future__ import annotations

import math

import numpy as np
import pint
import pytest

import impactlab as il
from impactlab.bodies import PAPER_ROD, FlexibleRod, Rod, Sphere

OTHER = pint.UnitRegistry()  # not impactlab's registry


def test_bodies_take_quantities_and_strings() -> None:
    a = Rod(length=0.3048 * OTHER.m, tip_radius="8.8 mm", mass=460.7 * OTHER.g)
    assert (a.length, a.tip_radius, a.mass) == pytest.approx((0.3048, 0.0088, 0.4607))
    s = Sphere(radius=5 * OTHER.mm, density="7800 kg/m^3")
    assert s.radius == pytest.approx(0.005) and s.density == pytest.approx(7800.0)
    f = FlexibleRod(length="304.8 mm", tip_radius=8.8 * OTHER.mm, mass=0.4607 * OTHER.kg)
    assert f.mass == pytest.approx(0.4607)


def test_simulate_takes_quantities_of_another_registry_and_strings() -> None:
    ref = il.simulate(PAPER_ROD, angle=math.radians(20), velocity=(0.0, -1.41), mu=0.2)
    q = il.simulate(
        PAPER_ROD,
        angle=20 * OTHER.deg,
        velocity=(0 * OTHER("m/s"), -1.41 * OTHER("m/s")),
        spin=0 * OTHER("rad/s"),
        mu=0.2 * OTHER.dimensionless,
    )
    s = il.simulate(PAPER_ROD, angle="20 deg", velocity=("0 m/s", "-141 cm/s"), mu=0.2)
    assert q.e == pytest.approx(ref.e, rel=1e-12) and s.e == pytest.approx(ref.e, rel=1e-12)
    with pytest.raises(ValueError, match="angle"):
        il.simulate(PAPER_ROD, angle=20 * OTHER.kg, velocity=(0.0, -1.41))


def test_batch_and_invert_take_quantities() -> None:
    b = il.simulate_batch(
        PAPER_ROD, vy=np.array([-1.0, -1.41]) * OTHER("m/s"), angle="20 deg", mu=0.2
    )
    ref = il.simulate(PAPER_ROD, angle="20 deg", velocity=(0.0, -1.41), mu=0.2)
    assert b["e"][1] == pytest.approx(ref.e, rel=1e-9)
    r = il.invert(
        angle=20 * OTHER.deg,
        v_i="-1.41 m/s",
        e=0.5,
        mu=0.2,
        delta_p=22 * OTHER.um,
        sliding_length=("1.4 mm", 50 * OTHER.um),
        n_samples=200,
    )
    plain = il.invert(
        angle=math.radians(20), v_i=-1.41, e=0.5, mu=0.2, delta_p=22e-6, sliding_length=1.4e-3
    )
    assert r.duration == pytest.approx(plain.duration, rel=1e-12)
    assert r.inputs["sliding_length"][1] == pytest.approx(50e-6)


def test_a_spin_in_hertz_is_refused_everywhere() -> None:
    """pint converts 1 Hz to 1 rad/s; a spin of 5 Hz usually means 5 turns per second: the
    rigid engine, the command line's parser and the drop refuse hertz, and take turns."""
    import math

    import impactlab as il
    from impactlab.units import magnitude, to_si

    kw = {"angle": "20 deg", "velocity": (0.0, -1.41), "mu": 0.2, "history": False}
    for spin in ("-5 Hz", "5 kHz"):
        with pytest.raises(ValueError, match=r"spin: '.*' is a frequency in hertz, ambiguous"):
            il.simulate(il.Rod.paper(), spin=spin, **kw)
    with pytest.raises(ValueError, match="is a frequency in hertz"):
        to_si("3 Hz", "rad/s", name="spin")
    assert magnitude("spin", "1 turn/s", "rad/s") == pytest.approx(2 * math.pi)
    assert magnitude("spin", "60 rpm", "rad/s") == pytest.approx(2 * math.pi)
    assert magnitude("spin", "5 rad/s", "rad/s") == pytest.approx(5.0)


def test_a_temperature_is_named_as_such() -> None:
    """'20 degC' is degrees Celsius, not an angle: one line that says so (not pint's text)."""
    import impactlab as il

    with pytest.raises(ValueError, match=r"angle: '20 degC' is a temperature .* e\.g\. '20 deg'"):
        il.simulate(il.Rod.paper(), angle="20 degC", velocity=(0.0, -1.41), history=False)
