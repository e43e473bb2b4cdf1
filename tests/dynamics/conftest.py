"""Shared fixtures of the engine tests: warm the numba cache once per session."""

from __future__ import annotations

import math

import pytest

from impactlab.bodies import PAPER_ROD, Sphere


@pytest.fixture(scope="session", autouse=True)
def _warm_engine() -> None:
    """Compile (or load from the disk cache) the engine once, before any timed test."""
    from impactlab.dynamics import simulate, simulate_batch

    for fr in ("impulse_ratio", "coulomb", "mindlin"):
        simulate(
            PAPER_ROD,
            law="hertz",
            friction=fr,
            mu=0.2,
            angle=math.radians(20),
            velocity=(0.0, -1.0),
        )
    simulate_batch(Sphere(0.01), law="hertz", friction="coulomb", mu=0.1, vy=[-1.0, -2.0])
