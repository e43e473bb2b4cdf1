"""An impact's scratch is one allocation: the state, the accumulators, the
error scales and every step loop's arrays are views of one buffer (``driver.impact``), so a
batch of N impacts allocates N buffers, counted by numba's runtime statistics."""

from __future__ import annotations

import math

import numpy as np
import pytest
from numba.core.runtime import _nrt_python as nrt
from numba.core.runtime import rtsys

from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law
from impactlab.dynamics import batch
from impactlab.dynamics.models import body_params, contact_model, kernel_params
from impactlab.materials import AISI_1010

pytestmark = pytest.mark.perf  # resource use of the compiled engine, not its speed


@pytest.mark.parametrize("friction", ["coulomb", "mindlin"])
def test_one_allocation_per_impact(friction) -> None:
    model = contact_model(PAPER_ROD, AISI_1010, "ghaednia")
    p = kernel_params(model)
    bp = body_params(PAPER_ROD, AISI_1010)
    n = 400
    angles = np.radians(np.linspace(5.0, 80.0, n))
    init = np.column_stack([angles, np.zeros(n), np.full(n, -1.41), np.zeros(n)])
    mu = np.full(n, 0.2)
    args = (get_law("ghaednia").law_id, batch.FRICTION_IDS[friction], p, bp, init, mu)
    batch.run_arrays(*args)  # compiled (or loaded) before counting
    was_on = nrt.memsys_stats_enabled()
    nrt.memsys_enable_stats()
    try:
        before = rtsys.get_allocation_stats()
        out, status = batch.run_arrays(*args)
        after = rtsys.get_allocation_stats()
    finally:
        if not was_on:
            nrt.memsys_disable_stats()
    assert (status == 0).all()
    assert math.isfinite(out[:, batch.OUTPUT_FIELDS.index("e")].sum())
    allocations = after.alloc - before.alloc
    assert after.free - before.free == allocations  # nothing kept
    # one buffer per impact, plus a few per batch (the parallel loop's set-up); 8 per impact
    # when the step loops allocated their own arrays
    assert n <= allocations <= n + 32
