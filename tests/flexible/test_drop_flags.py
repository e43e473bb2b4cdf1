"""Flags of the flexible drop: e < 0 and the other end's impacts are never plain success, the
gravity criterion reads the tip's sequence, and an energy balance worse than the tolerance
promises is refused (docs/flexible.md, "Results" and "Flags")."""

from __future__ import annotations

import math

import pytest

import impactlab as il
from impactlab.dynamics import drop_checks
from impactlab.dynamics.drop import DropError, simulate_drop
from impactlab.dynamics.flexcore import layout as F
from impactlab.flags import ResultFlag, messages


def test_negative_e_on_the_other_end_is_flagged() -> None:
    r = il.simulate(
        il.FlexibleRod.paper(n_axial=0, n_bending=0, axial_residual=False),
        law="brake",
        friction="partial_slip",
        mu=0.12044112615067763,
        angle="48.40121651019466 deg",
        velocity=(0.2385602034721499, -4.608752473990582),
        spin=9.588401140918073,
        rate="johnson-cook",
        stop="flight",
    )
    assert r.e < 0.0
    assert ResultFlag.OTHER_END in r.flags
    assert not r.ok
    assert any(w.startswith("other end") for w in r.warnings)


def test_negative_e_of_a_rigid_rod_is_flagged() -> None:
    r = simulate_drop(il.Rod.paper(), friction="impulse_ratio", mu=0.4993,
                      angle=math.radians(0.02153), velocity=(-0.15598, -0.97539),
                      spin=6.1892)  # fmt: skip
    assert r.e < 0.0
    assert ResultFlag.OTHER_END in r.flags and not r.ok


def test_flight_is_flagged_other_end_not_gravity_dominated() -> None:
    kw = {"angle": "20 deg", "velocity": (0, -1.41), "mu": 0.2}
    seq = il.simulate(il.FlexibleRod.paper(), **kw)
    flight = il.simulate(il.FlexibleRod.paper(), stop="flight", **kw)
    assert seq.ok and ResultFlag.OTHER_END not in seq.flags
    assert any(c.end == 1 for c in flight.contacts)
    assert ResultFlag.OTHER_END in flight.flags
    assert ResultFlag.GRAVITY_DOMINATED not in flight.flags  # judged on the tip's sequence
    assert not flight.ok


def test_energy_balance_beyond_the_tolerance_is_refused(monkeypatch: pytest.MonkeyPatch) -> None:
    """A test double: the ceiling of the bound (``drop_checks.ENERGY_BALANCE_MAX``) lowered
    below the drop's error (an rtol loose enough to break the bound is refused before it runs,
    ``input_checks.DROP_RTOL_MAX``)."""
    monkeypatch.setattr(drop_checks, "ENERGY_BALANCE_MAX", 1e-12)
    with pytest.raises(DropError, match=r"energy balance closed to .* lower rtol") as exc:
        il.simulate(il.FlexibleRod.paper(), angle="20 deg", velocity=(0, -1.41), mu=0.2,
                    rtol=1e-5)  # fmt: skip
    assert exc.value.status == F.ST_INACCURATE
    assert "\n" not in str(exc.value)
    monkeypatch.undo()
    r = il.simulate(il.FlexibleRod.paper(), angle="20 deg", velocity=(0, -1.41), mu=0.2,
                    rtol=1e-5)  # fmt: skip
    assert r.ok and r.energy_error <= 100 * 1e-5


def test_other_end_message_is_in_bit_order() -> None:
    texts = messages(ResultFlag.OTHER_END | ResultFlag.ENERGY_GAIN)
    assert texts[0].startswith("energy gain") and texts[1].startswith("other end")


def test_docs_state_law_extrapolated_on_drops() -> None:
    """docs/flexible.md said LAW_EXTRAPOLATED is never set on drops; a fast drop sets it."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "docs" / "flexible.md").read_text()
    assert "LAW_EXTRAPOLATED is not set on drops" not in text
    assert "not yet set on\ndrops" not in text and "is not yet set" not in text
    assert "LAW_EXTRAPOLATED is set on drops" in text
    fast = il.simulate(il.FlexibleRod.paper(n_axial=1, n_bending=2), angle="20 deg",
                       velocity=(0, -3.0), mu=0.2)  # fmt: skip
    assert ResultFlag.LAW_EXTRAPOLATED in fast.flags and fast.ok
