"""The tabulated law of one's own data (``IndentationCurves.from_arrays`` -> ``tabulated_model``,
the docs' "Use" example): no residual depth below first yield, delta_c, where the data's
loading starts in the elastic range (before, the residual depths were interpolated from 0 at
the first loading point: delta_r/delta_max 0.11 at 0.3 delta_c, an elastic impact losing 13 %
of its energy); and a law whose loading fit departs from its own data by more than the stated
2.5 % is refused, as ``register_law`` refuses it (before, a curve stiffer than Hertz gave a
law 95 % off its data as a success). The shipped curves keep their residual tables."""

from __future__ import annotations

import math

import numpy as np
import pytest

from impactlab.contact import get_law, register_law
from impactlab.contact.indentation_data import IndentationCurves, shipped_curves
from impactlab.contact.tabulated import Tabulated, loading_fit_error, tabulated_model
from impactlab.contact.tabulated_fit import FIRST_YIELD, TABLE_FIT_TOLERANCE, residual_points
from impactlab.fe.curves import load_cases
from impactlab.fe.tabulated import hardened_law
from impactlab.materials import AISI_201, AISI_1010, ContactPair

R = 8.8e-3
PAIR = ContactPair(AISI_201, AISI_1010)
#: The pair of each shipped curve set (its FE case's).
PAIRS = {case.name: case.pair for case in load_cases()}


def _docs_example() -> IndentationCurves:
    """docs/laws/tabulated.md, "Use": Ghaednia's law sampled from the elastic range."""
    ref = get_law("ghaednia").build(PAIR, R)
    delta = np.geomspace(1e-8, 300e-6, 64)
    force = np.array([ref.force(d) for d in delta])
    delta_max = delta[31::4]
    delta_r = np.array([ref.unload(d).delta_r for d in delta_max])
    return IndentationCurves.from_arrays(PAIR, R, delta, force, delta_max, delta_r)


def test_no_residual_depth_below_first_yield() -> None:
    curves = _docs_example()
    assert curves.elastic_limit < 0.03 and curves.delta_max[0] > 3.5  # first dent at 3.7 dc
    model = tabulated_model(curves, PAIR, R)
    dc = model.details["delta_c"]
    for k in (0.1, 0.3, 0.5, 0.9, 1.0):  # before: 0.11 at 0.3 delta_c, 0.23 at delta_c
        assert model.unload(k * dc).delta_r == 0.0, k
    assert model.unload(2.0 * dc).delta_r > 0.0
    for dm, ratio in zip(curves.delta_max, curves.residual_ratio, strict=True):
        assert model.unload(dm * dc).delta_r / (dm * dc) == pytest.approx(ratio, abs=1e-3)
    x, r = residual_points(curves)
    assert math.exp(x[0]) == FIRST_YIELD and r[0] == 0.0


def test_data_whose_first_dent_lies_below_delta_c_keep_it() -> None:
    """A residual depth measured at 0.8 delta_c: the data's first yield is earlier than
    Jackson-Green's, and the zero stays at the first loading point (as before)."""
    d = np.geomspace(0.1, 100.0, 30)
    f = d**1.5 * (1.0 + d / 20.0) ** -0.5
    c = IndentationCurves("early", "test", 360.0, 0.3, d, f / f[0] * 0.1**1.5,
                          np.array([0.8, 3.0, 30.0]), np.array([0.01, 0.1, 0.5]),
                          elastic_limit=0.1)  # fmt: skip
    x, r = residual_points(c)
    assert math.exp(x[0]) == pytest.approx(0.1) and r[0] == 0.0 and x.size == 4


@pytest.mark.parametrize("curves", shipped_curves(), ids=lambda c: c.name)
def test_the_shipped_residual_tables_start_at_their_last_zero(curves: IndentationCurves) -> None:
    x, r = residual_points(curves)
    first = int(np.flatnonzero(curves.residual_ratio > 0.0)[0])
    assert x[0] == np.log(curves.delta_max[first - 1]) and r[0] == 0.0
    assert np.array_equal(x[1:], np.log(curves.delta_max[first:]))


def _stiffer_than_hertz() -> IndentationCurves:
    """F ~ delta^1.8 from the elastic range on: the fit (never stiffer than Hertz) cannot
    follow it."""
    hertz = get_law("hertz").build(PAIR, R)
    delta = np.geomspace(1e-8, 300e-6, 64)
    force = np.array([hertz.force(d) for d in delta]) * (delta / delta[0]) ** 0.3
    delta_max = delta[31::4]
    return IndentationCurves.from_arrays(PAIR, R, delta, force, delta_max, 0.3 * delta_max)


def test_a_law_off_its_own_data_is_refused() -> None:
    curves = _stiffer_than_hertz()
    assert loading_fit_error(curves)[0] > 0.9  # 95 % off
    expected = (
        r"^law 'tabulated', curves 'measured': the law's loading fit departs from the data's "
        r"force by -0\.955 \(relative\) at loading point index 63 .*the fit must stay within "
        r"2\.5 % of every point: check that F/F_Hertz never rises"
    )
    with pytest.raises(ValueError, match=expected):
        tabulated_model(curves, PAIR, R)
    with pytest.raises(ValueError, match=expected):
        Tabulated(curves).build(PAIR, R)
    with pytest.raises(ValueError, match=r"^law 'stiff': the law's loading fit departs .* -0\.955"):
        register_law("stiff", curves)


def test_the_shipped_and_documented_laws_are_within_the_bound() -> None:
    for c in shipped_curves():
        assert loading_fit_error(c)[0] <= TABLE_FIT_TOLERANCE, c.name
        assert (
            Tabulated(c).build(PAIRS[c.name], R).details["loading_fit_max"] <= TABLE_FIT_TOLERANCE
        )
    assert tabulated_model(_docs_example(), PAIR, R).details["loading_fit_max"] < 0.01
    assert hardened_law(PAIR, R).details["loading_fit_max"] <= TABLE_FIT_TOLERANCE
