"""``simulate`` with ``friction="partial_slip"``: one impact of a rigid rod or sphere with
Mindlin-Deresiewicz partial-slip friction, run by the compiled ``impactlab.dynamics.slipcore``:
the steps of the batch engine's per-case function (``impactlab.dynamics.slip_batch.slip_case``)
called one by one from Python, so that a first impact compiles neither the rigid core again
nor the batch's function (a batch's results equal ``simulate``'s bit for bit).

The cells of the tangential model span the largest contact radius, estimated by a pre-pass of
the rigid core (frictionless for a sphere, whose normal motion friction does not change: exact;
with ``mindlin`` friction for a rod); a contact that outgrows the estimate takes up to
``EXTRA`` times as many cells. With mu = 0 the core's frictionless impact is returned.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab._compile_notice import one_line
from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.dynamics.checks import ImpactInputs
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.input_checks import check_partial_slip_cells
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.models import body_params, kernel_params
from impactlab.dynamics.outcome import impact_result, status_error
from impactlab.dynamics.results import ImpactResult
from impactlab.dynamics.slip_batch import RADIUS_MARGIN, prepass_friction
from impactlab.dynamics.slipcore import impact_slip, slip_addresses
from impactlab.friction import COULOMB, PARTIAL_SLIP_CELLS, get_friction

__all__ = ["checked_cells", "run_partial_slip"]


def checked_cells(cells: Any, friction: Any, drop: bool) -> int:
    """``simulate``'s ``partial_slip_cells`` checked (``input_checks.check_partial_slip_cells``)
    for ``friction`` (an unknown name is left to the friction's own check) and, ``drop``, a
    drop (a FlexibleRod, or drop options), whose compiled cells are fixed: ValueError."""
    try:
        name: str | None = get_friction(friction).name
    except ValueError:
        name = None
    n = check_partial_slip_cells(cells, name)
    if drop and n != PARTIAL_SLIP_CELLS:
        raise ValueError(
            f"partial_slip_cells = {n}: a drop (a FlexibleRod, or the drop options) has its "
            f"compiled {PARTIAL_SLIP_CELLS} cells per end, which cannot be changed; leave it out"
        )
    return n


def largest_radius(x: ImpactInputs) -> tuple[int, float]:
    """(status, estimated largest contact radius [m]) from a pre-pass of the rigid core: the
    computation of ``slip_batch.slip_estimate``, run from Python on the rigid core's own compile
    (the signature of ``simulate``'s rigid calls), so that a first partial-slip impact does not
    compile the rigid core again into another library. The same bits as ``slip_estimate``."""
    out = np.empty(L.N_OUT)
    vx, vy = x.velocity
    law, p, bp = x.model.law_id, kernel_params(x.model), body_params(x.body, x.flat)
    fric, mu = prepass_friction(bp, x.mu)
    status, _h, _n = impact(
        law, p, fric, bp, x.angle, vx, vy, x.spin, mu, x.gravity, x.constant_angle, x.rtol,
        False, False, out,
    )  # fmt: skip
    if status != S.ST_OK:
        return int(status), math.nan
    return S.ST_OK, float(loading_contact_radius(law, p, out[L.O_DMAX])) * RADIUS_MARGIN


def run_partial_slip(
    x: ImpactInputs, history: bool, n_cells: int = PARTIAL_SLIP_CELLS
) -> tuple[int, np.ndarray, np.ndarray | None]:
    """(status, outputs, history rows or None) of one partial-slip impact (checked inputs): the
    computation of ``slip_batch.slip_case``, the batch's per-case function, step by step (its
    results equal a batch's bit for bit)."""
    out = np.empty(L.N_OUT)
    vx, vy = x.velocity
    law, p, bp = x.model.law_id, kernel_params(x.model), body_params(x.body, x.flat)
    if x.mu < L.MU_NEGLIGIBLE:  # frictionless, as in the core (``layout.MU_NEGLIGIBLE``)
        status, hist, nh = impact(
            law, p, COULOMB, bp, x.angle, vx, vy, x.spin, 0.0, x.gravity, x.constant_angle,
            x.rtol, history, False, out,
        )  # fmt: skip
        return int(status), out, (hist[:nh] if history else None)
    status, a_est = largest_radius(x)
    if status != S.ST_OK:
        return status, out, None
    with one_line():  # a first impact compiles the addresses' functions, then the impact
        status, hist, nh, _jump = impact_slip(
            law, p, bp, x.angle, vx, vy, x.spin, x.mu, x.gravity, x.constant_angle, x.rtol,
            history, False, n_cells, a_est, out, slip_addresses(),
        )  # fmt: skip
    return int(status), out, (hist[:nh] if history else None)


def simulate_partial_slip(
    x: ImpactInputs, history: bool, n_cells: int = PARTIAL_SLIP_CELLS
) -> ImpactResult:
    """The ``ImpactResult`` of one partial-slip impact; ValueError on an engine failure."""
    status, out, hist = run_partial_slip(x, history, n_cells)
    if status != S.ST_OK:
        raise status_error(
            status, x.model, prefix="partial_slip impact: ", vn=x.vn, gravity=x.gravity
        )
    return impact_result(x, out, hist)
