"""The batch runs blocks of neighbouring cases (``core.batch.BLOCK``) in a scattered block
order, taken by its threads from an atomic counter: every
case exactly once, each with the numbers it has alone, for batch sizes around and below the
block size and for any number of threads."""

from __future__ import annotations

import numba
import numpy as np
import pytest

from impactlab.bodies import PAPER_ROD
from impactlab.contact import get_law
from impactlab.contact.kernels import NPARAM
from impactlab.dynamics import batch
from impactlab.dynamics.core.atomic import fetch_add
from impactlab.dynamics.core.batch import BLOCK, impact_batch
from impactlab.dynamics.kernels.layout import N_OUT
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


@pytest.mark.parametrize("threads", [1, 2, 3, 7])
def test_any_number_of_loops_runs_every_case_once(threads) -> None:
    """The work queue hands every block to exactly one loop, however many loops take from it
    (more loops than threads or than blocks included): the results equal one loop's."""
    n = 5 * BLOCK + 3
    p = kernel_params(contact_model(PAPER_ROD, AISI_1010, "ghaednia"))[None, :NPARAM]
    bp = PAPER_ROD.to_params(AISI_1010)[None, :]
    rng = np.random.default_rng(threads)
    init = np.column_stack(
        [rng.uniform(0.1, 1.3, n), np.zeros(n), rng.uniform(-3.0, -0.5, n), np.zeros(n)]
    )
    mu = rng.uniform(0.0, 0.5, n)
    law, fric = get_law("ghaednia").law_id, batch.FRICTION_IDS["coulomb"]

    def run(loops: int) -> tuple[np.ndarray, np.ndarray]:
        out = np.full((n, N_OUT), np.nan)
        status = np.full(n, -99, dtype=np.int32)
        impact_batch(loops, law, p, fric, bp, init, mu, 9.81, False, 1e-6, False, out, status)
        return out, status

    ref_out, ref_status = run(1)
    assert (ref_status == 0).all()
    out, status = run(threads)
    np.testing.assert_array_equal(status, ref_status)
    np.testing.assert_array_equal(out, ref_out)


@pytest.mark.parametrize("threads", [1, 2])
def test_run_arrays_equal_on_one_and_two_threads(threads) -> None:
    p = kernel_params(contact_model(PAPER_ROD, AISI_1010, "brake"))
    bp = PAPER_ROD.to_params(AISI_1010)
    n = 3 * BLOCK + 1
    init = np.column_stack(
        [np.linspace(0.2, 1.2, n), np.zeros(n), np.linspace(-3.0, -0.5, n), np.zeros(n)]
    )
    mu = np.linspace(0.05, 0.4, n)
    law, fric = get_law("brake").law_id, batch.FRICTION_IDS["coulomb"]
    before = numba.get_num_threads()
    try:
        numba.set_num_threads(1)
        ref, _ = batch.run_arrays(law, fric, p, bp, init, mu)
        numba.set_num_threads(min(threads, numba.config.NUMBA_NUM_THREADS))
        out, _ = batch.run_arrays(law, fric, p, bp, init, mu)
    finally:
        numba.set_num_threads(before)
    np.testing.assert_array_equal(out, ref)


@numba.njit(cache=False)
def _take_all(counter, n_takers, per_taker):
    taken = np.full(n_takers * per_taker, -1, np.int64)
    for t in numba.prange(n_takers):
        for j in range(per_taker):
            taken[t * per_taker + j] = fetch_add(counter, 1)
    return taken


_take_all_parallel = numba.njit(parallel=True, cache=False)(_take_all.py_func)


def test_fetch_add_returns_the_value_before_and_adds() -> None:
    counter = np.zeros(1, np.int64)
    np.testing.assert_array_equal(_take_all(counter, 1, 5), np.arange(5))
    assert counter[0] == 5


def test_fetch_add_hands_each_value_to_one_thread() -> None:
    """Two threads taking 200 000 values each: every value from 0 to 399 999 exactly once (a
    plain, non-atomic increment loses some of them)."""
    counter = np.zeros(1, np.int64)
    taken = _take_all_parallel(counter, 2, 200_000)
    assert counter[0] == 400_000
    np.testing.assert_array_equal(np.sort(taken), np.arange(400_000))


def test_fetch_add_refuses_other_counters() -> None:
    with pytest.raises(numba.core.errors.TypingError):
        _take_all(np.zeros(1, np.float64), 1, 1)
