"""Shared fixtures of the engine tests: warm the numba cache once per session."""

from __future__ import annotations

import pytest


@pytest.fixture(scope="session", autouse=True)
def _warm_engine() -> None:
    """Compile (or load from the disk cache) the engine once (the one warm-up:
    ``impactlab.dynamics.warm``, which ``python3 tasks.py test`` runs before the suite)."""
    from impactlab.dynamics.warm import warm

    warm(("rigid impact", "batch"))
