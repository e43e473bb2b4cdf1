"""The Python API's input errors say what the user wrote (an angle with a unit
is answered in degrees, numbers print as plain floats)."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.dynamics import simulate
from impactlab.units import registry


@pytest.mark.parametrize(
    ("angle", "shown"),
    [("95 deg", "95 deg"), ("-20 deg", "-20 deg"), (registry().Quantity(95.0, "deg"), "95 deg")],
)
def test_angle_with_a_unit_is_answered_in_degrees(angle: object, shown: str) -> None:
    with pytest.raises(ValueError, match="angle must be") as info:
        simulate(PAPER_ROD, angle=angle, velocity=(0.0, -1.41))
    text = str(info.value)
    if shown == "95 deg":  # past the flat's normal: what it means follows
        assert text.startswith(f"angle must be in (0, 90] deg, got {shown}: the rod leans past")
        assert "the mirror of a drop at angle = 85 deg with vx (or incidence) and spin" in text
    else:
        assert text == f"angle must be in (0, 90] deg, got {shown}"


def test_bare_number_keeps_the_degrees_hint() -> None:
    with pytest.raises(ValueError, match=r"in \(0, pi/2\], got 20.0 rad \(1145.92 deg\); if"):
        simulate(PAPER_ROD, angle=20.0, velocity=(0.0, -1.41))


def test_receding_velocity_message_prints_a_plain_float() -> None:
    with pytest.raises(ValueError, match="must be < 0") as info:
        simulate(PAPER_ROD, angle=math.radians(20), velocity=(0.0, "1.41 m/s"))
    assert "np.float64" not in str(info.value) and "= 1.41 m/s must be < 0" in str(info.value)
