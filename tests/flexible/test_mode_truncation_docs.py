"""docs/flexible.md ("Convergence and the default") states where the default modes' truncation
error in e passes the random drops' 1.8 %: the 60.65 deg drop of the paper's rod at
1.892 m/s, mu 0.3416 (e 0.1920 against 0.2024 with (24, 36) modes), and what a stiff flat
needs."""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.dynamics.drop import simulate_drop

DOC = " ".join((Path(__file__).resolve().parents[2] / "docs" / "flexible.md").read_text().split())


def test_the_60_deg_drop_is_5_percent_off_with_the_default_modes() -> None:
    kw: dict[str, Any] = {"angle": math.radians(60.65), "velocity": (0.0, -1.892), "mu": 0.3416}
    default = simulate_drop(FlexibleRod.paper(), history=False, **kw)
    more = simulate_drop(FlexibleRod.paper(n_axial=24, n_bending=36), history=False, **kw)
    assert default.e == pytest.approx(0.1920, abs=5e-5)
    assert more.e == pytest.approx(0.2024, abs=5e-5)
    assert abs(default.e / more.e - 1.0) > 0.05
    assert "the default gives e 0.1920, (24, 36) modes 0.2024 and (48, 64) 0.2032" in DOC
    assert "The 1.8 % is the largest of that sample, not a bound" in DOC


def test_docs_state_the_stiff_flat_mode_counts() -> None:
    assert "in the number of contacts in 20 of 100 random drops" in DOC
    assert "`FlexibleRod.paper(n_axial=24, n_bending=36)`" in DOC


def test_docs_state_where_the_default_is_not_enough_and_the_check() -> None:
    """The steep slow drops of slender rods, with the reviewed numbers, and a check that reads
    twice against four times the counts (``mode_convergence``)."""
    assert "**Where the default is not enough.**" in DOC
    assert "gives 3 contacts and e 0.2502, `ok`; (32, 56) 4 contacts and e 0.2980" in DOC
    assert "the default (8, 22) has 9 contacts and e 1.27 (GRAVITY_DOMINATED" in DOC
    assert "`impactlab.dynamics.flex_simulate.mode_convergence(body, flat," in DOC
    assert "Read the change from twice to four times the counts" in DOC
    assert "modes (twice the default counts), not only with a tighter" not in DOC


def test_docs_say_sweeps_run_partial_slip_for_flexible_rods() -> None:
    """tests/sweep/test_sweep_partial_slip.py runs it; the page said that sweeps refuse it."""
    assert "rods refuse `partial_slip`" not in DOC
    assert "Sweeps run it for flexible rods too" in DOC


def test_docs_do_not_present_a_loose_rtol_as_safe() -> None:
    """The page said that the 20 deg drop at rtol 1e-4 'passes'; a drop's rtol is capped."""
    assert "at 1e-4 to 1e-3 E0 with its 4 contacts, and passes" not in DOC
    assert "**A loose rtol is refused, not trusted.**" in DOC
    assert "So rtol is at most 1e-5 for every drop (`input_checks.DROP_RTOL_MAX`" in DOC
