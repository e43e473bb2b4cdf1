"""Fast checks of the prototype (pytest, ~1 min single-threaded):
    source env.sh && $PY -m pytest -q test_prototype.py
"""

import numpy as np
import pytest

import mdr
from cases import kharaz_case, velocities
from kharaz_data import KGS_ET
from model import cells_quasistatic
from runners import run_exact, run_existing, run_new

Gs, MU, R, ES = 1.0e10, 0.3, 1e-3, 1e11
A0 = 1e-4
N0 = 4.0 / 3.0 * ES * A0**3 / R
USTAR = 3 * MU * N0 / (16 * Gs * A0)


def _cm(u):
    return MU * N0 * (1 - (1 - np.minimum(u, USTAR) / USTAR) ** 1.5)


def test_reference_reproduces_cattaneo_mindlin_masing():
    n = 2001
    u1 = np.linspace(0, 0.8 * USTAR, n)
    u2 = np.linspace(0.8 * USTAR, -0.8 * USTAR, 2 * n)
    u = np.concatenate([u1, u2])
    F, _ = mdr.quasistatic(np.full(u.size, N0), u, np.full(u.size, A0), Gs, MU, 4000, 1.0001 * A0)
    Ts = _cm(0.8 * USTAR)
    exact = np.concatenate([_cm(u1), Ts - 2 * MU * N0 * (1 - (1 - (0.8 * USTAR - u2) / (2 * USTAR)) ** 1.5)])
    assert np.abs(-F - exact).max() < 1e-6 * MU * N0


def test_discrete_model_converges_to_cattaneo_mindlin():
    m0, n = 400, 2001
    grow = np.linspace(0, 1, m0)
    u1 = np.linspace(0, 0.8 * USTAR, n)
    T, _ = cells_quasistatic(np.concatenate([N0 * grow, np.full(n, N0)]),
                             np.concatenate([np.zeros(m0), u1]),
                             np.concatenate([A0 * grow ** (1 / 3), np.full(n, A0)]), Gs, MU, 16, A0)
    assert np.abs(-T[m0:] - _cm(u1)).max() < 0.005 * MU * N0


@pytest.mark.parametrize("theta", [3.0, 10.0, 20.0, 45.0])
def test_new_model_matches_exact_md_and_invariants(theta):
    c = kharaz_case()
    vt, vn = velocities(3.9, theta)
    r = run_new(c, vt, vn)
    x = run_exact(c, vt, vn)
    assert abs(r["et"] - x["et"]) < 2e-3
    assert abs(r["w"] - x["w"]) < 2e-3 * abs(x["w"]) + 0.5
    assert r["erise"] < 1e-12          # no energy gain
    assert r["jump"] < 1e-9            # F_t continuous at every switch
    assert r["coulomb"] < 1e-8         # |F_t| <= mu F_n


def test_kharaz_small_angle_regime():
    c = kharaz_case()
    th, et = KGS_ET[1]  # 3.703 deg, e_t = 0.745 (digitised)
    vt, vn = velocities(3.9, th)
    assert abs(run_new(c, vt, vn)["et"] - et) < 0.02
    assert run_existing(c, vt, vn)["et"] - et > 0.08  # the defect of issue 12


def test_mbf_scale_invariance():
    c = kharaz_case()
    vals = []
    for mu in (0.1, 0.4):
        c.mu = mu
        for vn in (0.5, 3.0):
            vt = 2.5 * mu * vn / c.eta
            vals.append(c.eta * run_exact(c, vt, -vn)["vslip_out"] / (mu * vn))
    assert max(vals) - min(vals) < 1e-9
