"""Thornton (1997) elastic-perfectly plastic law, normal sphere impact without gravity: the
engine's e equals Thornton's closed form across V/V_y = 1 ... 1000 within 1e-6 (absolute).

Thornton, J. Appl. Mech. 64 (1997) 383, doi:10.1115/1.2787319. The closed form and V_y come
from ``impactlab.contact.thornton``.
"""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.bodies import Sphere
from impactlab.contact import kernels as k
from impactlab.contact import thornton
from impactlab.dynamics import contact_model, simulate, simulate_batch
from impactlab.materials import AISI_1010, ContactPair

TOL = 1e-6
RATIOS = np.geomspace(1.0, 1000.0, 25)


def _yield_velocity(s: Sphere) -> float:
    model = contact_model(s, AISI_1010, "thornton")
    py = float(model.params[k.P_TH_PY])
    return float(
        thornton.thornton_yield_velocity(
            ContactPair(s.material, AISI_1010).E_star, s.radius, s.mass, py
        )
    )


def test_thornton_restitution_closed_form_batch() -> None:
    s = Sphere(0.01)
    vy = _yield_velocity(s)
    b = simulate_batch(
        s, law="thornton", friction="coulomb", mu=0.0, vy=-RATIOS * vy, gravity=False
    )
    assert np.all(b.ok), b.messages
    expected = np.asarray(thornton.thornton_restitution(RATIOS))
    dev = np.abs(b.e - expected)
    assert dev.max() < TOL, (dev.max(), RATIOS[np.argmax(dev)])
    # e* equals e for a normal sphere impact (v_n is the only velocity)
    assert np.abs(b.e_energy - b.e).max() < TOL


@pytest.mark.parametrize("ratio", [1.5, 30.0, 900.0])
def test_thornton_single(ratio: float) -> None:
    s = Sphere(0.004)
    vy = _yield_velocity(s)
    r = simulate(s, law="thornton", velocity=(0.0, -ratio * vy), gravity=False)
    assert abs(r.e - float(thornton.thornton_restitution(ratio))) < TOL
    assert r.delta_p > 0.0
