"""Many impacts in parallel (numba prange) and the residual caps of virgin loadings (dent map)."""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from impactlab.contact.kernels import P_ESTAR, loading_force, residual_depth, unloading_radius
from impactlab.dynamics.core.atomic import fetch_add
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.kernels._jit import njit_internal

#: Cases a thread takes at once from the work queue (a block of neighbouring rows of ``out``).
BLOCK = 16


@njit(cache=True, parallel=True, error_model="numpy")
def impact_batch(threads, law, lp, fric, bpa, init, mu, g, const_angle, rtol, diag, out, status):
    """Run ``init.shape[0]`` impacts in parallel on ``threads`` loops (numba prange; pass
    ``numba.get_num_threads()``). ``lp``: (1 or N, NPARAM); ``bpa``: (1 or N, NB); ``init``:
    (N, 4) [angle, vx, vy, spin]; ``mu``: (N,)."""
    n = init.shape[0]
    shared_p = lp.shape[0] == 1
    shared_b = bpa.shape[0] == 1
    nb = (n + BLOCK - 1) // BLOCK
    stride = _stride(nb)
    next_block = np.zeros(1, np.int64)
    for _t in prange(max(1, threads)):
        # one loop per thread, each taking the next block of BLOCK cases from the shared counter
        # when it is free (dynamic scheduling, ``atomic``): a core that also runs other work
        # (the sweep's writer) does fewer blocks instead of delaying the whole batch
        while True:
            kb = fetch_add(next_block, 1)
            if kb >= nb:
                break
            # the blocks in a scattered order (a stride coprime to their number): a grid is
            # ordered, and its costly corners would otherwise come last; inside a block the
            # cases are neighbours, so the rows of ``out`` are written in order (one case at a
            # time at a stride cost 5 % in cache misses: CHANGELOG.md, "Performance history")
            b = (kb * stride) % nb
            for i in range(b * BLOCK, min(b * BLOCK + BLOCK, n)):
                pi = lp[0] if shared_p else lp[i]
                bi = bpa[0] if shared_b else bpa[i]
                st, _h, _n = impact(
                    law,
                    pi,
                    fric,
                    bi,
                    init[i, 0],
                    init[i, 1],
                    init[i, 2],
                    init[i, 3],
                    mu[i],
                    g,
                    const_angle,
                    rtol,
                    False,  # a literal: the history code is folded away (a second compile)
                    diag,
                    out[i],
                )
                status[i] = st


@njit_internal
def _stride(n):
    """A stride coprime to ``n`` near n / golden ratio (1 for n < 3): k -> k stride mod n is a
    permutation that scatters neighbouring blocks of cases."""
    if n < 3:
        return 1
    s = int(0.6180339887498949 * n) | 1
    while math.gcd(s, n) != 1:
        s += 2
    return s


@njit(cache=True, error_model="numpy")
def residual_caps(law, p, delta):
    """(delta_r, R_r) of the unloading branch from virgin loading to each ``delta`` [m]."""
    n = delta.shape[0]
    dr = np.zeros(n)
    rr = np.full(n, np.inf)
    for i in range(n):
        dm = delta[i]
        if dm <= 0.0:
            continue
        Fm = loading_force(law, p, dm)
        dri = residual_depth(law, p, dm, Fm)
        dr[i] = dri
        rr[i] = unloading_radius(p[P_ESTAR], dm, Fm, dri)
    return dr, rr
