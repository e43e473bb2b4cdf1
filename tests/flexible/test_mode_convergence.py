"""``mode_convergence``: one drop at growing mode counts, and whether its e, dent and contacts
have converged (docs/flexible.md, "Convergence and the default"). The paper's 20 deg drop has;
a steep slow drop of the slender 0.6 m rod (``FlexibleRod.paper(length=0.6)``, d = 11.2 mm)
has not: the default's 3 contacts and e 0.2502 became 4 contacts and e 0.2980 at twice the
counts, 0.3190 at four times, where the default gave no sign of it."""

from __future__ import annotations

import math
from typing import Any

import pytest

from impactlab.bodies import FlexibleRod, Rod
from impactlab.dynamics.flex_simulate import ModeConvergence, mode_convergence

#: The reviewed steep slow drop of the 0.6 m rod.
STEEP_SLOW: dict[str, Any] = {
    "angle": math.radians(76.874),
    "velocity": (-0.0511, -0.3107),
    "spin": 5.106,
    "mu": 0.374,
}


def test_the_paper_drop_has_converged() -> None:
    c = mode_convergence(FlexibleRod.paper(), angle=math.radians(20), velocity=(0.0, -1.41), mu=0.2)
    assert isinstance(c, ModeConvergence)
    assert c.modes == ((8, 12), (16, 24), (32, 48))
    assert [r.n_contacts for r in c.results] == [4, 4, 4]
    assert c.results[0].history is None  # history off unless asked
    assert c.e_change < 0.005 and c.dent_change < 0.01 and c.same_contacts
    assert c.converged()


def test_a_steep_slow_drop_of_a_slender_rod_has_not() -> None:
    c = mode_convergence(FlexibleRod.paper(length=0.6), factors=(1, 2), **STEEP_SLOW)
    assert c.modes == ((16, 28), (32, 56))
    assert [r.n_contacts for r in c.results] == [3, 4]
    assert [round(r.e, 4) for r in c.results] == [0.2502, 0.2980]
    assert c.e_change == pytest.approx(0.16, abs=0.005)
    assert not c.same_contacts and not c.converged()
    assert c.dent_change < 0.002  # the first contact's dent converges; e does not


def test_the_counts_stop_at_the_limit() -> None:
    """Twice and three times (64, 100) are both (128, 128): no check; refused before a run."""
    with pytest.raises(ValueError, match=r"= \(128, 128\) twice \(the counts stop at 128\)"):
        mode_convergence(FlexibleRod.paper(n_axial=64, n_bending=100), factors=(1, 2, 3))
    with pytest.raises(ValueError, match=r"= \(8, 12\) twice; give factors"):  # rounding, no cap
        mode_convergence(FlexibleRod.paper(), factors=(1, 1.01))


@pytest.mark.parametrize(
    ("body", "factors", "match"),
    [
        (Rod.paper(), (1, 2), "body must be a FlexibleRod"),
        (FlexibleRod.paper(), (2,), "two or more growing numbers"),
        (FlexibleRod.paper(), (2, 1), "two or more growing numbers"),
        (FlexibleRod.paper(), (0, 1), "two or more growing numbers"),
    ],
)
def test_bad_arguments_are_refused(body: Any, factors: Any, match: str) -> None:
    with pytest.raises(ValueError, match=match):
        mode_convergence(body, factors=factors, **STEEP_SLOW)
