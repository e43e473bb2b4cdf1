"""Shared fixtures of the sweep tests: the fake evaluator, store comparison helpers."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

from sweep_fakes import FakeEvaluator  # noqa: E402


def store_files(path: Path) -> dict[str, bytes]:
    """Every file of a store (relative path -> bytes): two stores are identical iff equal."""
    return {str(p.relative_to(path)): p.read_bytes() for p in sorted(path.rglob("*"))
            if p.is_file()}


@pytest.fixture
def fake() -> FakeEvaluator:
    return FakeEvaluator()


@pytest.fixture(scope="session")
def engine():
    """The compiled engine, loaded (or compiled into NUMBA_CACHE_DIR) once per session; skips
    the test when impactlab.dynamics.batch is not available."""
    from impactlab.sweep import ENGINE, engine_available
    from impactlab.sweep.engine import Statics, evaluate

    if not engine_available():
        pytest.skip("impactlab.dynamics.batch not available")
    import numpy as np

    from impactlab.sweep.inputs import INPUTS

    cases = {n: np.full(1, np.nan if s.default is None else float(s.default))
             for n, s in INPUTS.items() if s.kind == "float"}
    cases.update(angle=np.array([0.5]), vy=np.array([-1.0]), mu=np.array([0.1]))
    cats = {n: str(s.default) for n, s in INPUTS.items() if s.kind == "category"}
    evaluate(cases, Statics(cats), ("e",))
    return ENGINE
