"""One warm-up of the compiled drop integrator for the flexible-rod tests (loaded from numba's
disk cache, or compiled once per session); the paper's drops are in ``paper_drops``."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies.flexible_rod import FlexibleRod


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
