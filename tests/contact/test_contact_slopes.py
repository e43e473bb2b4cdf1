"""The normal contact in one pass (``kernels.normal.normal_contact``, ``contact.slopes``): the
force and radius equal to the engine's own kernels bit for bit, the slopes equal to the
derivatives of the same curves."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.contact import kernels as k
from impactlab.contact import law_names
from impactlab.contact.base import ContactModel
from impactlab.contact.history_kernels import turning_point
from impactlab.contact.tabulate import with_table
from impactlab.dynamics.kernels.normal import (
    dforce_ddelta,
    dradius_ddelta,
    normal_contact,
    normal_force,
    radius,
)

LOADING = (0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0)


def _deltas(p: np.ndarray) -> np.ndarray:
    top = min(p[k.P_DLIM], 0.02 * p[k.P_R])
    return np.geomspace(1e-7 * top, 0.95 * top, 301)


def _smooth_slope(f, d: float) -> float | None:  # type: ignore[no-untyped-def]
    """The central difference of ``f`` at ``d`` where two step sizes agree (else None: a kink
    or a switch of the curve lies within the stencil)."""
    h = 1e-5 * d
    s1 = (f(d + h) - f(d - h)) / (2 * h)
    s2 = (f(d + 2 * h) - f(d - 2 * h)) / (4 * h)
    return s1 if abs(s1 - s2) <= 1e-8 * abs(s1) else None


@pytest.mark.parametrize("name", law_names())
@pytest.mark.parametrize("table", [False, True])
def test_loading_values_bitwise_and_slopes(
    paper_models: dict[str, ContactModel], name: str, table: bool
) -> None:
    model = paper_models[name]
    p = np.asarray(model.params, dtype=np.float64)
    law = model.law_id
    if table:
        p = with_table(law, p)
    checked = 0
    for d in _deltas(p):
        Fn, Fs, a, As = normal_contact(law, p, LOADING, d)
        assert Fn == normal_force(law, p, LOADING, d)
        assert a == radius(law, p, LOADING, d)
        fs = _smooth_slope(lambda x: normal_force(law, p, LOADING, x), d)
        rs = _smooth_slope(lambda x: radius(law, p, LOADING, x), d)
        if fs is not None:
            assert Fs == pytest.approx(fs, rel=1e-7)
            assert Fs == pytest.approx(dforce_ddelta(law, p, LOADING, d, Fn), rel=1e-7)
            checked += 1
        if rs is not None:
            assert As == pytest.approx(rs, rel=1e-7)
            assert As == pytest.approx(dradius_ddelta(law, p, LOADING, d), rel=1e-7)
    assert checked > 250
    assert normal_contact(law, p, LOADING, 0.0) == (0.0, 0.0, 0.0, 0.0)
    assert normal_contact(law, p, LOADING, -1e-9) == (0.0, 0.0, 0.0, 0.0)


@pytest.mark.parametrize("name", law_names())
def test_unloading_values_bitwise_and_slopes(
    paper_models: dict[str, ContactModel], name: str
) -> None:
    model = paper_models[name]
    law = model.law_id
    p = with_table(law, np.asarray(model.params, dtype=np.float64))
    dm = 0.5 * _deltas(p)[-1]
    _Fm, dr, Rr = turning_point(law, p, dm)
    md = (1.0, dm, dr, Rr, 0.0, 0.0, 0.0, 0.97)
    for d in np.linspace(dr, dm, 101)[1:]:
        Fn, Fs, a, As = normal_contact(law, p, md, d)
        assert Fn == normal_force(law, p, md, d)
        assert a == radius(law, p, md, d)
        e = d - dr
        assert Fs == pytest.approx(1.5 * Fn / e, rel=1e-15)
        assert As == pytest.approx(0.5 * a / e, rel=1e-15)
        assert As == pytest.approx(dradius_ddelta(law, p, md, d), rel=1e-7)
    assert normal_contact(law, p, md, dr) == (0.0, 0.0, 0.0, 0.0)
    assert normal_contact(law, p, md, 0.5 * dr) == (0.0, 0.0, 0.0, 0.0)
