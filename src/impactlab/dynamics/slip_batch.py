"""Partial-slip impacts in compiled code: one case (``slip_case``, the pre-pass of the rigid core
then ``slipcore.impact_slip``) and many in parallel (``slip_batch``, numba prange with the rigid
batch's work queue).

``slip_case`` is what ``simulate(friction="partial_slip")`` runs, so a batch's results equal
``simulate``'s bit for bit. The cells span the largest contact radius estimated by a pre-pass
of the rigid core (frictionless for a sphere, whose normal motion friction does not change:
exact; with ``mindlin`` friction for a rod), times 1.0001; a contact that outgrows the estimate
takes up to ``slipcore.layout.EXTRA`` times as many cells. With mu < ``MU_NEGLIGIBLE`` the
core's frictionless impact is returned.
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
from numba import njit, prange, types
from numba.extending import register_jitable

from impactlab.bodies.layout import BP_KIND, KIND_ROD
from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.dynamics.core.atomic import fetch_add
from impactlab.dynamics.core.batch import BLOCK, _stride
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.kernels.address_call import address_intrinsic, compiled_addresses
from impactlab.dynamics.kernels.layout import FR_COULOMB, FR_MINDLIN, MU_NEGLIGIBLE, O_DMAX
from impactlab.dynamics.kernels.status import ST_BAD_INPUT, ST_OK
from impactlab.dynamics.slipcore import impact_slip

#: The cells' span over the pre-pass's largest contact radius (a margin for round-off).
RADIUS_MARGIN = 1.0001
_F1 = types.float64[::1]
#: The rigid core's ``impact`` as ``simulate`` calls it from Python (every argument a value):
#: law, p, fric, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, record, diag, out; (status,
#: history, rows). The pre-pass calls it through its address (``kernels.address_call``), so
#: that the batch's library does not generate the whole rigid core again.
IMPACT_SIGNATURE = types.Tuple((types.int64, types.float64[:, ::1], types.int64))(
    types.int64, _F1, types.int64, _F1, *(types.float64,) * 6, types.boolean, types.float64,
    types.boolean, types.boolean, _F1,
)  # fmt: skip
call_impact = address_intrinsic("call_impact", IMPACT_SIGNATURE)


@cache
def prepass_address() -> int:
    """The entry point of the rigid core's ``impact`` (``IMPACT_SIGNATURE``; compiled, or
    loaded from the cache, on first use, then kept for the process)."""
    return compiled_addresses(((impact, IMPACT_SIGNATURE),))[0]


@register_jitable
def prepass_friction(bp: np.ndarray, mu: float) -> tuple[int, float]:
    """(friction id, mu) of the rigid core's pre-pass: ``mindlin`` for a rod that rubs, else
    frictionless (a sphere's normal motion does not depend on friction). Plain Python when
    called from Python, inlined where compiled code calls it."""
    if bp[BP_KIND] == KIND_ROD and mu >= MU_NEGLIGIBLE:
        return FR_MINDLIN, mu
    return FR_COULOMB, 0.0


@njit(cache=True, error_model="numpy")
def slip_estimate(law, p, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, diag, out, impact_at):
    """(status, estimated largest contact radius [m]) from the pre-pass of the rigid core (its
    outputs are left in ``out``; with mu < ``MU_NEGLIGIBLE`` they are the impact's own, the
    core's frictionless impact).

    The core is called at its address ``impact_at`` (``prepass_address``) with the signature of
    ``simulate``'s calls from Python, every argument a value, none a constant
    (``IMPACT_SIGNATURE``): the compile ``simulate`` uses, from the cache."""
    fric, mu_pre = prepass_friction(bp, mu)
    no_history = out.shape[0] < 0  # False, as a value (see above)
    st, _h, _n = call_impact(
        impact_at, law, p, fric, bp, th0, vx0, vy0, w0, mu_pre, g, const_angle, rtol, no_history,
        diag, out,
    )  # fmt: skip
    if st != ST_OK:
        return st, math.nan
    return ST_OK, loading_contact_radius(law, p, out[O_DMAX]) * RADIUS_MARGIN


@njit(cache=True, error_model="numpy")
def slip_case(
    law, p, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, diag, n_cells, out, at, impact_at
):
    """One partial-slip impact without history into ``out`` (the outputs of
    ``impactlab.dynamics.core.impact``); ``n_cells`` cells over the estimated largest contact
    radius; ``at``: the engine's addresses (``slipcore.slip_addresses``), ``impact_at``: the
    rigid core's (``prepass_address``). Returns the status."""
    if not (mu >= 0.0):  # NaN or negative: refused, as by simulate's checks
        for i in range(out.shape[0]):
            out[i] = math.nan
        return ST_BAD_INPUT
    st, a_est = slip_estimate(
        law, p, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, diag, out, impact_at
    )
    if st != ST_OK or mu < MU_NEGLIGIBLE:  # frictionless: the core's impact, as in the core
        return st
    no_history = out.shape[0] < 0  # False, as a value: simulate's signature (slip_estimate)
    st, _h, _n, _jump = impact_slip(
        law, p, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, no_history, diag, n_cells,
        a_est, out, at,
    )  # fmt: skip
    return st


@njit(cache=True, parallel=True, error_model="numpy")
def slip_batch(
    threads,
    law,
    lp,
    bpa,
    init,
    mu,
    g,
    const_angle,
    rtol,
    diag,
    n_cells,
    out,
    status,
    at,
    impact_at,
):
    """``init.shape[0]`` partial-slip impacts in parallel on ``threads`` loops (the arguments of
    ``core.batch.impact_batch`` without the friction id, plus ``n_cells`` and the addresses of
    ``slip_case``): each thread takes
    the next block of ``BLOCK`` cases from a shared counter, in a scattered order."""
    n = init.shape[0]
    shared_p = lp.shape[0] == 1
    shared_b = bpa.shape[0] == 1
    nb = (n + BLOCK - 1) // BLOCK
    stride = _stride(nb)
    next_block = np.zeros(1, np.int64)
    for _t in prange(max(1, threads)):
        while True:
            kb = fetch_add(next_block, 1)
            if kb >= nb:
                break
            b = (kb * stride) % nb
            for i in range(b * BLOCK, min(b * BLOCK + BLOCK, n)):
                pi = lp[0] if shared_p else lp[i]
                bi = bpa[0] if shared_b else bpa[i]
                status[i] = slip_case(
                    law, pi, bi, init[i, 0], init[i, 1], init[i, 2], init[i, 3], mu[i], g,
                    const_angle, rtol, diag, n_cells, out[i], at, impact_at,
                )  # fmt: skip
