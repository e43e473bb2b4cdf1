"""Shared fixtures of the sweep tests: the fake evaluator and the compiled engine (the store
comparison helper ``store_files`` lives in ``sweep_fakes``)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

import numpy as np  # noqa: E402
from sweep_fakes import FakeEvaluator  # noqa: E402

from impactlab.sweep import ENGINE  # noqa: E402
from impactlab.sweep.engine import Statics, evaluate  # noqa: E402
from impactlab.sweep.inputs import INPUTS  # noqa: E402


@pytest.fixture
def fake() -> FakeEvaluator:
    return FakeEvaluator()


@pytest.fixture(scope="session")
def engine():
    """The compiled engine, loaded (or compiled into NUMBA_CACHE_DIR) once per session."""
    cases = {
        n: np.full(1, np.nan if s.default is None else float(s.default))
        for n, s in INPUTS.items()
        if s.kind == "float"
    }
    cases.update(angle=np.array([0.5]), vy=np.array([-1.0]), mu=np.array([0.1]))
    cats = {n: str(s.default) for n, s in INPUTS.items() if s.kind == "category"}
    evaluate(cases, Statics(cats), ("e",))
    return ENGINE
