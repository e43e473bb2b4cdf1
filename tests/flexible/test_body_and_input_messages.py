"""FlexibleRod checks its geometry against its material and warns on implausible values as
``Rod`` does; the drop's messages name what is wrong (tip radius against L/2, a missing angle,
a spin in hertz)."""

from __future__ import annotations

import math
import warnings

import pytest

import impactlab as il
from impactlab._validation import ImplausibleInputWarning
from impactlab.bodies.flexible_rod import DENSITY_TOLERANCE, FlexibleRod
from impactlab.dynamics.drop import simulate_drop


def test_inconsistent_diameter_is_refused() -> None:
    with pytest.raises(ValueError, match=r"imply a density of 192.4 kg/m\^3.* 7800 kg/m\^3"):
        FlexibleRod.paper(diameter=0.1)
    assert DENSITY_TOLERANCE == 0.02
    rod = FlexibleRod.paper(diameter=0.01571)  # consistent with m, L and the steel: accepted
    assert rod.diameter == 0.01571


def test_rod_thicker_than_long_is_refused() -> None:
    with pytest.raises(ValueError, match=r"diameter of 0.4967 m, L/d = 0.614 < 2: not a rod"):
        FlexibleRod.paper(mass=460.7)


def test_implausible_length_warns_as_rod() -> None:
    with pytest.warns(ImplausibleInputWarning, match=r"length = 304.8 m"):
        FlexibleRod.paper(length=304.8, mass=900.0, tip_radius=0.011)  # d = 21.9 mm
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        FlexibleRod.paper()  # the paper's rod: no warning


def test_tip_radius_message_prints_half_the_length() -> None:
    with pytest.raises(ValueError, match=r"half the length \(L/2 = 0.1524 m\)"):
        FlexibleRod.paper(tip_radius=0.2)


def test_missing_angle_names_the_flexible_rod() -> None:
    with pytest.raises(ValueError, match=r"angle is required for the drop of a FlexibleRod"):
        simulate_drop(FlexibleRod.paper(), angle=None, velocity=(0.0, -1.41))  # type: ignore[arg-type]


def test_spin_in_hertz_is_refused_turns_convert() -> None:
    rod = FlexibleRod.paper(n_axial=1, n_bending=1)
    kw = {"angle": "20 deg", "velocity": (0.0, -1.41), "mu": 0.2}
    with pytest.raises(ValueError, match=r"spin: '-5 Hz' is a frequency in hertz"):
        il.simulate(rod, spin="-5 Hz", **kw)
    assert il.simulate(rod, spin="-1 turn/s", **kw).spin_in == pytest.approx(-2 * math.pi)
