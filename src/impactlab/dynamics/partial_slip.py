"""``simulate`` with ``friction="partial_slip"``: one impact of a rigid rod or sphere with
Mindlin-Deresiewicz partial-slip friction, run by the compiled ``impactlab.dynamics.slipcore``.

The cells of the tangential model span the largest contact radius, estimated by a pre-pass of
the rigid core (frictionless for a sphere, whose normal motion friction does not change: exact;
with ``mindlin`` friction for a rod); a contact that outgrows the estimate takes up to
``EXTRA`` times as many cells. With mu = 0 the core's frictionless impact is returned.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from impactlab.bodies import Rod
from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.dynamics.checks import ImpactInputs
from impactlab.dynamics.core.driver import impact
from impactlab.dynamics.kernels import layout as L
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.models import body_params, kernel_params
from impactlab.dynamics.outcome import impact_result, status_error
from impactlab.dynamics.results import ImpactResult
from impactlab.dynamics.slipcore import impact_slip
from impactlab.friction import COULOMB, MINDLIN, PARTIAL_SLIP_CELLS

__all__ = ["run_partial_slip"]


def _core(x: ImpactInputs, fric: int, mu: float, history: bool, out: np.ndarray) -> Any:
    vx, vy = x.velocity
    p = kernel_params(x.model)
    bp = body_params(x.body, x.flat)
    return impact(
        x.model.law_id, p, fric, bp, x.angle, vx, vy, x.spin, mu, x.gravity,
        x.constant_angle, x.rtol, history, False, out,
    )  # fmt: skip


def largest_radius(x: ImpactInputs) -> tuple[int, float]:
    """(status, estimated largest contact radius [m]) from a pre-pass of the rigid core."""
    out = np.empty(L.N_OUT)
    rod = isinstance(x.body, Rod)
    status, _h, _n = _core(x, MINDLIN if rod else COULOMB, x.mu if rod else 0.0, False, out)
    if status != S.ST_OK:
        return int(status), math.nan
    a = loading_contact_radius(x.model.law_id, kernel_params(x.model), out[L.O_DMAX])
    return S.ST_OK, float(a) * 1.0001


def run_partial_slip(
    x: ImpactInputs, history: bool, n_cells: int = PARTIAL_SLIP_CELLS
) -> tuple[int, np.ndarray, np.ndarray | None]:
    """(status, outputs, history rows or None) of one partial-slip impact (checked inputs)."""
    out = np.empty(L.N_OUT)
    if x.mu < L.MU_NEGLIGIBLE:  # frictionless, as in the core (``layout.MU_NEGLIGIBLE``)
        status, hist, nh = _core(x, COULOMB, 0.0, history, out)
        return int(status), out, (hist[:nh] if history else None)
    status, a_est = largest_radius(x)
    if status != S.ST_OK:
        return status, out, None
    vx, vy = x.velocity
    status, hist, nh, _jump = impact_slip(
        x.model.law_id, kernel_params(x.model), body_params(x.body, x.flat), x.angle, vx, vy,
        x.spin, x.mu, x.gravity, x.constant_angle, x.rtol, history, False, n_cells, a_est, out,
    )  # fmt: skip
    return int(status), out, (hist[:nh] if history else None)


def simulate_partial_slip(
    x: ImpactInputs, history: bool, n_cells: int = PARTIAL_SLIP_CELLS
) -> ImpactResult:
    """The ``ImpactResult`` of one partial-slip impact; ValueError on an engine failure."""
    status, out, hist = run_partial_slip(x, history, n_cells)
    if status != S.ST_OK:
        raise status_error(status, x.model, prefix="partial_slip impact: ")
    return impact_result(x, out, hist)
