"""The compiled kernels: callable from other numba code, history semantics, contact radius."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numba import njit

from impactlab.contact import history_kernels as hk
from impactlab.contact import kernels as k
from impactlab.contact import law_names
from impactlab.contact.base import ContactModel


@njit(cache=False)
def _engine_like(law: int, p: np.ndarray, deltas: np.ndarray) -> np.ndarray:
    """Load along ``deltas`` (any order) the way an engine would, calling every kernel."""
    out = np.empty((deltas.size, 4))
    dm = 0.0
    dr = 0.0
    Rr = p[k.P_R]
    for i in range(deltas.size):
        d = deltas[i]
        if d > dm:
            dm = d
            Fm, dr, Rr = hk.turning_point(law, p, dm)
            dr2 = k.residual_depth(law, p, dm, k.loading_force(law, p, dm))
            if dr2 != dr:
                out[i, 3] = -1.0
            else:
                out[i, 3] = k.unloading_radius(p[k.P_ESTAR], dm, Fm, dr)
        else:
            out[i, 3] = Rr
        out[i, 0] = hk.contact_force(law, p, d, dm, dr, Rr)
        out[i, 1] = hk.contact_radius(law, p, d, dm, dr, Rr)
        out[i, 2] = k.hertz_force(p[k.P_ESTAR], p[k.P_R], d)
    return out


@pytest.mark.parametrize("name", law_names())
def test_kernels_are_callable_from_njit(name: str, paper_models: dict[str, ContactModel]) -> None:
    model = paper_models[name]
    path = np.array([0.0, 1e-6, 5e-5, 3e-5, 1e-5, 4e-5, 5e-5, 8e-5])
    out = _engine_like(model.law_id, model.params, path)
    assert np.all(out[:, 3] > 0.0)  # residual_depth agrees with turning_point
    br = model.unload(5e-5)
    # loading points equal the Python API, unloading points the branch of delta_m = 50 um
    np.testing.assert_allclose(out[[1, 2], 0], model.force(path[[1, 2]]), rtol=1e-14)
    np.testing.assert_allclose(out[[3, 4, 5], 0], br.force(path[[3, 4, 5]]), rtol=1e-14)
    np.testing.assert_allclose(out[[3, 4, 5], 1], br.contact_radius(path[[3, 4, 5]]), rtol=1e-14)
    assert out[6, 0] == pytest.approx(float(model.force(5e-5)), rel=1e-14)  # back on the curve
    assert out[7, 0] == pytest.approx(float(model.force(8e-5)), rel=1e-14)
    np.testing.assert_allclose(out[:, 2], 4 / 3 * model.E_star * math.sqrt(8.8e-3) * path**1.5)


@pytest.mark.parametrize("name", law_names())
def test_contact_radius(name: str, paper_models: dict[str, ContactModel]) -> None:
    model = paper_models[name]
    p, law, R = model.params, model.law_id, model.radius
    assert hk.contact_radius(law, p, 0.0, 0.0, 0.0, R) == 0.0
    assert hk.contact_radius(law, p, -1e-6, 0.0, 0.0, R) == 0.0
    d = 1e-7  # below 1.9 delta_c for every law: the Hertz radius
    assert hk.contact_radius(law, p, d, 0.0, 0.0, R) == pytest.approx(math.sqrt(R * d), rel=1e-14)
    br = model.unload(1e-4)
    for x in (0.5 * br.delta_r, br.delta_r):
        assert hk.contact_radius(law, p, x, br.delta_m, br.delta_r, br.R_r) == 0.0
    x = 0.5 * (br.delta_r + br.delta_m)
    a = hk.contact_radius(law, p, x, br.delta_m, br.delta_r, br.R_r)
    assert a == pytest.approx(math.sqrt(br.R_r * (x - br.delta_r)), rel=1e-14)
    if name not in ("ghaednia", "jackson-green"):
        assert float(model.contact_radius(1e-4)) == pytest.approx(math.sqrt(R * 1e-4), rel=1e-14)


def test_unknown_law_id_gives_nan_not_a_crash(paper_models: dict[str, ContactModel]) -> None:
    p = paper_models["hertz"].params
    assert math.isnan(k.loading_force(99, p, 1e-6))
    assert math.isnan(k.residual_depth(99, p, 1e-6, 1.0))


def test_zero_and_negative_interference(paper_models: dict[str, ContactModel]) -> None:
    for model in paper_models.values():
        assert k.loading_force(model.law_id, model.params, 0.0) == 0.0
        assert k.loading_force(model.law_id, model.params, -1e-6) == 0.0
        assert k.residual_depth(model.law_id, model.params, 0.0, 0.0) == 0.0
        assert model.unload(0.0).delta_r == 0.0
