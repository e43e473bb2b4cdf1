"""Inputs the flexible drop cannot take are refused with one-line ValueErrors that name the
parameter, its value and what is allowed (no ZeroDivisionError, OverflowError or LinAlgError),
and a creeping partial-slip drop fails in seconds."""

from __future__ import annotations

import math
import re
from collections.abc import Callable

import pytest

import impactlab as il
from impactlab.bodies import beam_modes
from impactlab.bodies.flexible_rod import MAX_MODES, FlexibleRod
from impactlab.dynamics.drop import MIN_APPROACH_SPEED, DropError, simulate_drop
from impactlab.dynamics.flexcore import layout as F


@pytest.mark.parametrize("vy", [-1e-300, -1e-200, -1e-12])
def test_vanishing_approach_speed_is_refused(vy: float) -> None:
    with pytest.raises(ValueError, match=r"approach speed .* is below 1e-09 m/s") as exc:
        simulate_drop(FlexibleRod.paper(), angle=math.radians(20), velocity=(0.0, vy))
    assert not isinstance(exc.value, DropError) and "\n" not in str(exc.value)
    assert MIN_APPROACH_SPEED == 1e-9


def test_cli_vanishing_speed_is_one_line(cli_main: Callable[..., tuple[int, str, str]]) -> None:
    code, _, err = cli_main("drop", "--angle", "20 deg", "--vy", "-1e-300 m/s")
    assert code == 2, err
    assert "Traceback" not in err and "approach speed" in err


@pytest.mark.parametrize(
    ("field", "value"), [("n_bending", 224), ("n_bending", 300), ("n_axial", 100000)]
)
def test_mode_counts_are_bounded(field: str, value: int) -> None:
    with pytest.raises(ValueError, match=rf"{field} must be an integer in \[0, 128\], got {value}"):
        FlexibleRod.paper(**{field: value})
    assert MAX_MODES == 128


def test_largest_mode_counts_build() -> None:
    rod = FlexibleRod.paper(n_axial=MAX_MODES, n_bending=MAX_MODES)
    assert rod.basis().n_modes == 2 * MAX_MODES + 2
    assert math.isfinite(float(beam_modes.eb_beta_l(230)[-1]))  # no cosh overflow


def test_creeping_partial_slip_fails_fast() -> None:
    """46 s and 2e6 steps before; now the step limit follows the Mindlin pre-pass (counted in
    steps, not timed: 100 times the pre-pass's, 81 700 here, 4 % of the former limit). The
    tip bounces, flies for 114 ms and lands again to creep: the sequence alone ends after its
    bounce (a new impact of the tip, ``next_end`` 0), ``stop="flight"`` follows the creep."""
    rod = FlexibleRod.paper(n_axial=2, n_bending=0, damping=0.03185021386008342)
    kw = {
        "law": "brake",
        "mu": 0.5172584083120987,
        "angle": "62.05981562187482 deg",
        "velocity": (0.9423713445466566, -0.4817121757074115),
        "spin": 3.412682469935538,
    }
    with pytest.raises(DropError, match=r"step limit reached after \d+ steps.*mindlin") as exc:
        il.simulate(rod, friction="partial_slip", stop="flight", **kw)
    assert exc.value.status == F.ST_MAX_STEPS
    steps = int(re.search(r"after (\d+) steps", str(exc.value)).group(1))  # type: ignore[union-attr]
    assert (
        F.PARTIAL_MIN_STEPS <= steps <= F.DROP_MAX_STEPS // 20
        and steps % F.PARTIAL_STEP_FACTOR == 0
    )
    bounce = il.simulate(rod, friction="partial_slip", **kw)
    assert bounce.ok and bounce.n_contacts == 1 and bounce.next_end == 0


@pytest.mark.parametrize("stop", ["sequence", "flight"])
def test_both_ends_sticking_flat_is_no_division_by_zero(stop: str) -> None:
    """A rigid-limit rod landing almost flat (0.0095 deg): both ends stick with redundant
    tangential constraints (a singular 2x2 mobility); ZeroDivisionError before."""
    rod = FlexibleRod.paper(n_axial=0, n_bending=0, axial_residual=False)
    r = simulate_drop(rod, friction="coulomb", mu=0.2, angle=math.radians(0.0095),
                      velocity=(0.0, -1.0), stop=stop)  # fmt: skip
    assert any(c.end == 1 for c in r.contacts)
    assert math.isfinite(r.e) and 0.0 <= r.dent_depth <= r.delta_max
    assert r.energy_error < 1e-4
