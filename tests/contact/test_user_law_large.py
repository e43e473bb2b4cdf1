"""A table of thousands of rows (an indenter's raw export) registers in a few fits: its
sampling error is cross-validated over ``FOLDS`` held-out sets past ``LOO_MAX_POINTS`` interior
points instead of one fit per row, agrees with leave-one-out within 10 %, and a table below the
threshold keeps its leave-one-out error bit for bit."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import IndentationCurves, register_law, unregister_law
from impactlab.contact import loading_fit as lf
from impactlab.contact.indentation_data import shipped_curves
from impactlab.contact.tabulated import interpolation_error, loading_points
from impactlab.materials import AISI_201, AISI_1010, ContactPair

PAIR = ContactPair(AISI_201, AISI_1010)
R = 8.8e-3


def _curves(rows: int, scatter: float = 0.0, seed: int = 3) -> IndentationCurves:
    """A softening loading curve of ``rows`` rows from 1 to 300 um (relative ``scatter`` in
    force, kept non-decreasing) and 12 residual depths."""
    d = np.geomspace(1e-6, 300e-6, rows)
    hertz = 4.0 / 3.0 * PAIR.E_star * math.sqrt(R) * d**1.5
    f = hertz / np.sqrt(1.0 + (d - 1e-6) / 3e-6)
    f = f * (1.0 + scatter * np.random.default_rng(seed).standard_normal(rows))
    f[0] = hertz[0]
    dm = np.geomspace(1e-6, 300e-6, 12)
    ratio = 0.85 * np.clip(np.log(dm / 1e-6) / np.log(300.0), 0.0, 1.0) ** 0.5
    return IndentationCurves.from_arrays(PAIR, R, d, np.maximum.accumulate(f), dm, ratio * dm)


@pytest.fixture
def fits(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """The number of spline fits made (``loading_fit.fit_with`` calls), as a one-item list."""
    count = [0]
    real = lf.fit_with

    def counted(*args, **kw):  # type: ignore[no-untyped-def]
        count[0] += 1
        return real(*args, **kw)

    monkeypatch.setattr(lf, "fit_with", counted)
    return count


def test_a_5000_row_table_registers_in_a_few_dozen_fits(fits: list[int]) -> None:
    """Formerly one fit per row (5000 rows: over 7 CPU-minutes; 1000 rows: 50 s)."""
    law = register_law("export-5000", _curves(5000))
    try:
        assert fits[0] <= 2 * (len(lf.INTERVALS) + 1) + lf.FOLDS  # two GCV choices, the folds
        assert "error by 10-fold cross-validation (residual depths: leave-one-out)" in law.validity
        assert law.sampling_error[0] < 1e-6  # a smooth curve: the fit follows it
    finally:
        unregister_law("export-5000")


def _both(c: IndentationCurves, monkeypatch: pytest.MonkeyPatch) -> tuple[tuple[float, ...], ...]:
    """(leave-one-out, ``FOLDS``-fold) ``interpolation_error`` of ``c``."""
    monkeypatch.setattr(lf, "LOO_MAX_POINTS", 10**9)
    loo = interpolation_error(c)
    monkeypatch.setattr(lf, "LOO_MAX_POINTS", 0)
    return loo, interpolation_error(c)


@pytest.mark.parametrize("which", ["shipped", "300 rows, 0.3 %", "300 rows, 1 %"])
def test_the_folds_agree_with_leave_one_out_within_10_percent(
    which: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    """Measured: 0.99-1.04 times leave-one-out's force error; the residual depths' the same
    (PCHIP is local, and every held-out point keeps its neighbours)."""
    sets = {
        "shipped": shipped_curves(),
        "300 rows, 0.3 %": (_curves(300, 0.003),),
        "300 rows, 1 %": (_curves(300, 0.01),),
    }[which]
    for c in sets:
        loo, folds = _both(c, monkeypatch)
        assert folds[0] == pytest.approx(loo[0], rel=0.1), c.name
        assert folds[1] == pytest.approx(loo[1], rel=0.1), c.name


def _old_leave_one_out(x: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The leave-one-out of ``loading_fit`` before the folds (one fit per interior point)."""
    k = lf.choose_intervals(x, w)
    out = []
    for i in range(1, x.size - 1):
        keep = np.arange(x.size) != i
        out.append(float(lf.fit_with(x[keep], w[keep], k, (x[0], x[-1]))(x[i])) - w[i])
    return np.asarray(out)


def test_a_table_below_the_threshold_keeps_its_leave_one_out_bit_for_bit() -> None:
    assert lf.LOO_MAX_POINTS == 100 and lf.FOLDS == 10
    for c in (*shipped_curves(), _curves(60, 0.003), _curves(101)):
        x, z = loading_points(c)
        assert x.size - 2 <= lf.LOO_MAX_POINTS
        w = 1.5 * x - z
        np.testing.assert_array_equal(lf.cross_validated(x, w), _old_leave_one_out(x, w))
    law = register_law("small-table", _curves(60, 0.003))
    try:
        assert "leave-one-out error" in law.validity and "fold" not in law.validity
    finally:
        unregister_law("small-table")
