"""A rate row whose self-consistent factor did not converge is not ok in the explanation, as
the drop itself is (it stayed "ok" and could rank first)."""

from __future__ import annotations

import functools
import warnings
from pathlib import Path

import pytest

import impactlab.dynamics.drop as D
from impactlab.calibrate.measurements import read_measurements
from impactlab.explain.configurations import LIBRARY_RATES
from impactlab.explain.runs import drop_alone, run_on_drop

DROPS = Path(__file__).resolve().parents[2] / "examples" / "data" / "paper_drops.csv"


def test_an_unconverged_rate_row_is_not_ok(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(D, "self_consistent_factor",
                        functools.partial(D.self_consistent_factor, max_iter=1))  # fmt: skip
    drop = drop_alone(read_measurements(DROPS), 0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        out = run_on_drop(LIBRARY_RATES[0], drop, "ghaednia")
    assert not out.ok
    assert out.status.startswith("not ok: rate factor not converged: the self-consistent rate")
    monkeypatch.undo()
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        assert run_on_drop(LIBRARY_RATES[0], drop, "ghaednia").ok
