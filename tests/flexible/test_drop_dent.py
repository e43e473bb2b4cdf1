"""A drop's predicted dent (``DropResult.dent``): the single impact's dent model over every
contact of the tip, with the drop's own law (its rate factor included)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.bodies import FlexibleRod, Rod
from impactlab.dynamics import simulate
from impactlab.dynamics.drop import simulate_drop

KW = {"angle": math.radians(20), "velocity": (0.0, -1.41), "mu": 0.2}


def test_the_rigid_limit_is_the_impact_s_dent() -> None:
    """A rigid Rod's drop is one contact: its dent map is the impact's, to the integration's
    precision (the two cores sample the contact at other instants)."""
    drop = simulate_drop(Rod.paper(), **KW).dent()
    impact = simulate(Rod.paper(), **KW).dent()
    assert drop.max_depth == pytest.approx(impact.max_depth, rel=1e-6)
    assert drop.length == pytest.approx(impact.length, rel=1e-3)
    assert drop.width == pytest.approx(impact.width, rel=1e-3)


@pytest.mark.parametrize("rate", [None, "cowper-symonds"])
def test_a_ringing_rod_s_dent_holds_every_contact(rate: str | None) -> None:
    """The flexible rod touches four times: the map's deepest point is the drop's dent depth
    (the deepest dent, with the rate-raised yield strength when the flat is rate-dependent),
    the dent is at least as long as the contact point's path, and it never rises above the
    undeformed flat."""
    r = simulate_drop(FlexibleRod.paper(), rate=rate, **KW)
    assert r.n_contacts > 1
    d = r.dent(nx=161, ny=81)
    assert d.max_depth == pytest.approx(r.dent_depth, rel=1e-9)
    assert d.length >= r.scar_length and np.all(d.height <= 0.0)
    assert d.height.shape == (81, 161)


def test_without_the_history_it_says_what_it_needs() -> None:
    r = simulate_drop(FlexibleRod.paper(), history=False, **KW)
    with pytest.raises(
        ValueError, match=r"needs the history: run simulate_drop\(\.\.\., history=True\)"
    ):
        r.dent()
