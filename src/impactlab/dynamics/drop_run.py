"""One compiled drop and its outcome (SI units): the call into ``flexcore`` (``run_drop``), what
its pre-passes read (partial slip's cell widths, the first contact's radius) and its output row
as a ``DropResult``, the engine's names mapped onto the schema's (``assemble_drop_result``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from impactlab import schema
from impactlab._compile_notice import one_line
from impactlab.contact import ContactModel
from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.contact.range_note import range_note
from impactlab.contact.ranges import extrapolation, range_status
from impactlab.contact.rate import RateFactor
from impactlab.dynamics.drop_body import BodyModel
from impactlab.dynamics.drop_checks import check_energy_balance, drop_flags, status_error
from impactlab.dynamics.drop_result import ContactRecord, DentRecord, DropHistory, DropResult
from impactlab.dynamics.flexcore import drop
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.batch import initial_energy
from impactlab.dynamics.flexcore.model import constants, model_tuple, state_length
from impactlab.dynamics.models import kernel_params
from impactlab.friction import PARTIAL_SLIP_CELLS
from impactlab.references import Reference

__all__ = [
    "DropRun",
    "assemble_drop_result",
    "first_contact_radius",
    "run_drop",
    "slip_cell_widths",
]


@dataclass(frozen=True)
class DropRun:
    """What one compiled drop returns: its status, output row, contacts, dents and history."""

    status: int
    out: np.ndarray
    contacts: np.ndarray
    dents: np.ndarray
    history: np.ndarray | None


def run_drop(
    bm: BodyModel,
    model: ContactModel,
    state: tuple[float, float, float, float],
    friction: tuple[int, float, float, tuple[float, float]],
    g: float,
    options: tuple[float, float, int, bool],
    max_steps: int = F.DROP_MAX_STEPS,
) -> DropRun:
    """One compiled drop. state = (angle, vx, vy, spin); friction = (id, mu, G* [Pa], the cell
    widths of the ends [m] (partial slip)); options = (rtol, time_limit [s], stop, history);
    the step limit."""
    angle, vx, vy, w = state
    fid, mu, gstar, widths = friction
    rtol, time_limit, stop, history = options
    rod = bm.rigid
    p = kernel_params(model)
    c = constants(
        rod.half_length, rod.tip_radius, rod.mass, bm.inertia, g, angle, mu, p, fid, gstar, widths,
        max_steps,
    )  # fmt: skip
    out = np.empty(F.N_DROP_OUT)
    contacts = np.zeros((F.MAX_CONTACTS, F.NCR))
    dents = np.zeros((F.MAX_DENTS, F.NDT))
    yfinal = np.zeros(state_length(bm.omega.size, fid))
    with one_line():  # a first drop compiles the addresses' functions
        mdl = model_tuple(model.law_id, p, c, bm.omega, bm.zeta, bm.U, bm.W, bm.Psi, bm.geometric)
        st, ncon, nd, hist, _nh = drop(
            mdl, vx, vy, w, rtol, time_limit, stop, history, out, contacts, dents, yfinal
        )
    return DropRun(
        int(st), out, contacts[:ncon].copy(), dents[:nd].copy(), hist if history else None
    )


def slip_cell_widths(run: DropRun, model: ContactModel) -> tuple[float, float]:
    """Partial slip: the cell width of each end [m], PARTIAL_SLIP_CELLS cells over the largest
    loading contact radius of its contacts in the pre-pass ``run`` (an end without contacts
    there: the tip's), as the rigid engine's estimate (``dynamics.partial_slip``)."""
    if run.status != F.ST_OK:
        raise status_error(run.status, model, run.out)
    p = kernel_params(model)
    a = [0.0] * F.NE
    for row in run.contacts:
        k = int(row[F.CR_END])
        a[k] = max(a[k], float(loading_contact_radius(model.law_id, p, float(row[F.CR_DMAX]))))
    a1 = a[1] if a[1] > 0.0 else a[0]
    return a[0] * 1.0001 / PARTIAL_SLIP_CELLS, a1 * 1.0001 / PARTIAL_SLIP_CELLS


def first_contact_radius(run: DropRun, model: ContactModel) -> float:
    """a_m: the contact radius at the largest interference of the first contact [m]."""
    if run.status != F.ST_OK:
        raise status_error(run.status, model, run.out)
    dm = float(run.contacts[0, F.CR_DMAX])
    return float(loading_contact_radius(model.law_id, kernel_params(model), dm))


def assemble_drop_result(
    r: DropRun,
    bm: BodyModel,
    model: ContactModel,
    inputs: dict[str, Any],
    rate: tuple[str | None, RateFactor | None],
    references: tuple[Reference, ...],
    brittle_limit: float,
) -> DropResult:
    o: dict[str, Any] = {
        name: float(v) for name, v in zip(F.DROP_OUTPUT_FIELDS, r.out, strict=True)
    }
    m = bm.rigid.mass
    vx, vy = inputs["velocity_in"]
    e0 = float(initial_energy(m, bm.inertia, vx, vy, inputs["spin_in"]))
    rtol = inputs.pop("rtol")
    check_energy_balance(o, e0, rtol)
    ratio, ratio_max = extrapolation(model.law_id, model.params, o["delta_max"])
    skip = {"vx_out", "vy_out", "n_contacts", "next_end", "n_steps", "n_jumps", "n_dents"}
    skip |= {"t_final"}
    flags, lifted = drop_flags(r.out, e0, m, inputs["gravity"], rtol, model, r.contacts,
                               bm.rigid.tip_radius, brittle_limit)  # fmt: skip
    return DropResult(
        contacts=tuple(ContactRecord.from_row(row) for row in r.contacts),
        dents=tuple(DentRecord.from_row(row) for row in r.dents),
        n_contacts=int(o["n_contacts"]),
        velocity_out=(o["vx_out"], o["vy_out"]),
        initial_energy=e0,
        next_end=int(o["next_end"]),
        n_steps=int(o["n_steps"]),
        body=bm.description,
        n_modes=int(bm.omega.size),
        law=model.name,
        rate=rate[0],
        rate_factor=rate[1].k if rate[1] is not None else 1.0,
        strain_rate=rate[1].strain_rate if rate[1] is not None else math.nan,
        history=DropHistory(r.history) if r.history is not None else None,
        flags=flags,
        max_delta_ratio=ratio,
        fitted_delta_ratio_max=ratio_max,
        fitted_range_status=range_status(model.law_id, model.params),
        law_range=range_note(model.law_id, model.params),
        references=references,
        _law=(model.law_id, np.asarray(model.params)),
        _e_lifted=lifted,
        _rate_doubt=rate_doubt(rate[1]),
        **inputs,
        **{_RENAMED_OUTPUTS.get(k, k): v for k, v in o.items() if k not in skip},
    )


def rate_doubt(factor: Any) -> str:
    """Why a rate factor is doubtful ("" where its fixed point converged, or there is none)."""
    if factor is None or factor.converged:
        return ""
    return (
        f"the self-consistent rate factor k = {factor.k:.6g} is the closest iterate of "
        f"{factor.iterations} drop(s), its relative change {factor.change:.2g}; the result "
        "rests on an unconverged yield strength"
    )


#: The drop's engine outputs (``flexcore.layout.DROP_FIELDS``) that ``DropResult`` names
#: otherwise: the sequence totals (``impactlab.schema.SEQUENCE_FIELDS``).
_RENAMED_OUTPUTS: dict[str, str] = {
    k: v for k, v in schema.RENAMED_DROP_FIELDS.items() if k in F.DROP_OUTPUT_FIELDS
}
