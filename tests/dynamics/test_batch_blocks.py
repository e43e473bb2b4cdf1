"""The batch runs blocks of neighbouring cases (``core.batch.BLOCK``) in a scattered block
order (issue 13, session 8): every case exactly once, each with the numbers it has alone, for
batch sizes around and below the block size."""

from __future__ import annotations

import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law
from impactlab.dynamics import batch
from impactlab.dynamics.core.batch import BLOCK
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010


@pytest.mark.parametrize("n", [1, BLOCK - 1, BLOCK, BLOCK + 1, 3 * BLOCK + 5, 97])
def test_every_case_once_with_its_own_numbers(n) -> None:
    p = kernel_params(contact_model(PAPER_ROD, AISI_1010, "ghaednia"))
    bp = PAPER_ROD.to_params(AISI_1010)
    rng = np.random.default_rng(n)
    init = np.column_stack(
        [rng.uniform(0.1, 1.3, n), np.zeros(n), rng.uniform(-3.0, -0.5, n), np.zeros(n)]
    )
    mu = rng.uniform(0.0, 0.5, n)
    law, fric = get_law("ghaednia").law_id, batch.FRICTION_IDS["coulomb"]
    out, status = batch.run_arrays(law, fric, p, bp, init, mu)
    assert (status == 0).all()
    for i in range(n):
        alone, st = batch.run_arrays(law, fric, p, bp, init[i : i + 1], mu[i : i + 1])
        assert st[0] == 0
        np.testing.assert_array_equal(out[i], alone[0])
