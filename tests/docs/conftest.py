"""Shared fixture of the documentation tests: warm numba's on-disk cache once per session, so
that the verification functions and the example scripts (run in subprocesses with this
process's NUMBA_CACHE_DIR) load the compiled engine instead of compiling it each."""

from __future__ import annotations

import math

import pytest


@pytest.fixture(scope="session")
def warm_engine() -> None:
    """Compile (or load) the engine kernels the examples and the verification use."""
    from impactlab.bodies import PAPER_ROD, Sphere
    from impactlab.dynamics import simulate, simulate_batch

    for fr in ("impulse_ratio", "coulomb", "mindlin"):
        r = simulate(
            PAPER_ROD,
            law="ghaednia",
            friction=fr,
            mu=0.2,
            angle=math.radians(20),
            velocity=(0.0, -1.41),
        )
    r.dent(nx=21, ny=11)  # the dent map's kernels (the reproduction's Fig. 4)
    simulate_batch(Sphere(0.01), law="hertz", friction="coulomb", mu=0.1, vy=[-1.0, -2.0])
    simulate_batch(
        PAPER_ROD,
        law="ghaednia",
        friction="coulomb",
        mu=[0.1, 0.9],
        angle=math.radians(20),
        vy=-1.41,
    )
