"""Shared data of the flexible-rod tests: the paper's rod and drops, and one warm-up of the
compiled drop integrator (loaded from numba's disk cache, or compiled once per session)."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.rod_section import RodSection

#: The paper's three drops: angle [deg], vy [m/s], measured mu (used as the Coulomb mu).
CASES = [(20, -1.41, 0.20), (45, -2.18, 0.13), (70, -3.45, 0.10)]
#: The paper's rod as a section (d from m, L and rho).
SEC = RodSection.paper()


@pytest.fixture(scope="session", autouse=True)
def _warm_drop() -> None:
    """Compile (or load) the drop integrator once, before the tests."""
    from impactlab.dynamics.drop import simulate_drop

    simulate_drop(
        FlexibleRod.paper(n_axial=1, n_bending=1),
        angle=math.radians(45),
        velocity=(0.0, -1.0),
        mu=0.1,
    )
