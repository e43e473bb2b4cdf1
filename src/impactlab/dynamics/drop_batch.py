"""``simulate_drops``: many drops of one flexible (or rigid) rod on a flat, one law and friction
model, in one compiled call on every core (``impactlab.dynamics.flexcore.batch``).

The body's modal model and the contact model are built once; the cases (angle, velocity,
spin, mu) run in the compiled loop, each with its status (``kernels.status``), and the checks
of ``simulate_drop`` run on all of them at once: its input checks, the energy balance against
the tolerance (ST_INACCURATE) and the result flags. Each output of a case equals, bit for
bit, that of ``simulate_drop`` with the same inputs (tests/flexible/test_drop_batch.py). The
result class: ``dynamics.drop_batch_result``.
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numba
import numpy as np

from impactlab._interrupts import plain_interrupts
from impactlab._validation import refuse_unknown_keywords
from impactlab.bodies import Rod
from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.bodies.layout import BP_GSTAR
from impactlab.contact import ContactModel
from impactlab.contact.brittle import brittle_flags, brittle_pressure
from impactlab.contact.range_note import range_note
from impactlab.contact.ranges import delta_ratio, extrapolation_flags
from impactlab.dynamics.checks import checked_model
from impactlab.dynamics.drop_batch_data import ENGINE_NAME
from impactlab.dynamics.drop_batch_result import DropBatchResult, DropSetup
from impactlab.dynamics.drop_body import body_model
from impactlab.dynamics.drop_checks import (
    check_body,
    check_friction,
    check_stop,
    drop_rtol,
    inaccurate_cases,
    input_problems,
    input_status,
    refuse_rate,
    status_error,
)
from impactlab.dynamics.drop_gravity import e_lifted_by_gravity
from impactlab.dynamics.export import batch_setup
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.batch import (
    CK_E0,
    CK_FLAGS,
    N_CHECKS,
    drop_address,
    drop_batch,
)
from impactlab.dynamics.flexcore.indirect import batch_addresses
from impactlab.dynamics.flexcore.model import constants, model_tuple
from impactlab.dynamics.input_checks import batch_velocity, check_flat, gravity_value
from impactlab.dynamics.kernels import status as S
from impactlab.dynamics.kernels.layout import MU_NEGLIGIBLE
from impactlab.dynamics.models import body_params, kernel_params, references_used
from impactlab.dynamics.simulate_many import _batch_inputs, flattening_words
from impactlab.dynamics.time_limit import DEFAULT_TIME_LIMIT, takes_renamed
from impactlab.flags import FLAG_GRAVITY_DOMINATED
from impactlab.friction import COULOMB, DEFAULT_MU, PARTIAL_SLIP, PARTIAL_SLIP_CELLS
from impactlab.materials import AISI_1010, Material

__all__ = ["DropBatchResult", "input_status", "simulate_drops"]


#: What simulate_drops says of a keyword of ``simulate`` or ``simulate_batch`` it does not take.
DROPS_KEYWORD_NOTES = {
    "history": "a drop batch keeps no history, each case's totals only; one drop's time history:"
    " impactlab.simulate_drop(body, flat, angle=..., velocity=(vx, vy), mu=...) or "
    "impactlab.simulate(FlexibleRod(...), ...), history=True by default",
    "constant_angle": "a drop follows the rod's rotation; fixed lever arms: simulate_batch",
    "partial_slip_cells": f"a drop's partial slip has {PARTIAL_SLIP_CELLS} compiled cells per end",
    "theta": "the rod's angle to the flat is angle= [rad]",
}


@takes_renamed  # t_max=, time_limit's name before 0.3 (a DeprecationWarning)
@refuse_unknown_keywords(DROPS_KEYWORD_NOTES)
def simulate_drops(
    body: FlexibleRod | Rod,
    flat: Material = AISI_1010,
    *,
    angle: Any = None,
    vy: Any = None,
    vx: Any = None,
    spin: Any = 0.0,
    mu: Any = DEFAULT_MU,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    law_params: Mapping[str, float] | None = None,
    gravity: Any = True,
    rtol: float | None = None,
    stop: str = "sequence",
    time_limit: Any = DEFAULT_TIME_LIMIT,
    speed: Any = None,
    incidence: Any = None,
    velocity: Any = None,
    rate: Any = None,
) -> DropBatchResult:
    """Many drops of ``body`` (a FlexibleRod, or a rigid Rod: its rigid limit) on ``flat``, in
    parallel on all cores: each case as ``simulate_drop`` runs it, bit for bit.

    ``angle`` [rad, in (0, pi/2]], ``vx``, ``vy`` [m/s] of the centre of mass at first touch
    (or ``velocity=(vx, vy)``, or ``speed`` [m/s] and ``incidence`` [rad]: vx = speed
    sin(incidence), vy = -speed cos(incidence)), ``spin`` [rad/s] and ``mu`` are scalars or
    1-D arrays, broadcast against each other (the dimensional ones may carry units, as in
    ``simulate_batch``). law, friction (``"coulomb"``, ``"impulse_ratio"``, ``"mindlin"``,
    ``"partial_slip"``), law_params, gravity (True, False or [m/s^2]), rtol (default 1e-7),
    stop and time_limit [s] as ``simulate_drop`` (``t_max=``, its name before 0.3, read as
    it with a DeprecationWarning), the same for every case. ``rate`` (a
    rate-dependent flat) is refused with a ValueError: its self-consistent factor iterates drop
    by drop (``simulate_drop(..., rate=...)`` for each case).

    A case the drop refuses (a non-finite input, mu < 0, an angle outside (0, pi/2], a tip
    that does not approach the flat, or approaches it slower than ``MIN_APPROACH_SPEED``) or
    whose drop fails (its status, e.g. ST_TMAX, or ST_INACCURATE when the energy balance
    closed worse than rtol promises) gets its status in ``DropBatchResult.status`` (its reason
    in ``messages``) and NaN outputs; it never stops the batch. ValueError for a bad body,
    flat, law, friction, gravity, rtol (with partial slip: up to 1e-5), stop or time_limit (one
    message naming it), and for a bad ``speed`` or ``incidence`` (checked before any case
    runs, as ``simulate_batch`` does: each offending case named by its index). TypeError for a
    keyword it does not take, with the nearest name or what to use instead
    (``DROPS_KEYWORD_NOTES``: ``history=``, a drop batch keeps none). When the rod's material
    yields before the flat's (``materials.body_yields_first``, one pair per call),
    ``body_yields_first`` is True and ``warnings`` says once that dent_depth is the rod's
    flattening, not a dent in the flat (advisory: no value changes).
    """
    refuse_rate(rate, "simulate_drops")
    body = check_body(body)
    bm = body_model(body)
    flat = check_flat(flat)
    fric, _ = check_friction(friction, 0.0)
    if angle is None:
        raise ValueError(
            "angle is required: the rod axis to the flat at the first touch, in radians (or "
            "with a unit), in (0, pi/2]"
        )
    g = gravity_value(gravity)
    r = drop_rtol(rtol, fric)
    t_end, stop_mode = check_stop(stop, time_limit)
    model = checked_model(bm.rigid, flat, law, law_params)
    vx, vy = batch_velocity(vx, vy, speed, incidence, velocity)
    cols = _batch_inputs({"mu": mu, "angle": angle, "vx": vx, "vy": vy, "spin": spin}, bm.rigid)
    n = cols["angle"].shape[0]
    status, refusals = input_problems(bm.rigid, cols, g, r)
    run = status == 0
    mu_run = np.where(cols["mu"] < MU_NEGLIGIBLE, 0.0, cols["mu"])  # frictionless below
    fid = np.full(n, fric.friction_id, dtype=np.int64)
    fid[(fric.friction_id == PARTIAL_SLIP) & (mu_run == 0.0)] = COULOMB
    out = np.full((n, F.N_DROP_OUT), np.nan)
    checks = np.full((n, N_CHECKS), np.nan)
    if np.any(run):
        p = kernel_params(model)
        gstar = float(body_params(bm.rigid, flat)[BP_GSTAR])
        rod = bm.rigid
        c = constants(rod.half_length, rod.tip_radius, rod.mass, bm.inertia, g, 0.0, 0.0, p,
                      COULOMB, gstar)  # fmt: skip
        mdl = model_tuple(model.law_id, p, c, bm.omega, bm.zeta, bm.U, bm.W, bm.Psi,
                          bm.geometric)  # fmt: skip
        # partial slip's right-hand side, step and cell switches, compiled only where a case uses it
        mdl += batch_addresses(bool(np.any(fid[run] == PARTIAL_SLIP)))
        init = np.stack([cols[k][run] for k in ("angle", "vx", "vy", "spin")], axis=1)
        o, ck = (
            np.full((init.shape[0], F.N_DROP_OUT), np.nan),
            np.full((init.shape[0], N_CHECKS), np.nan),
        )
        st = np.zeros(init.shape[0], dtype=np.int32)
        with plain_interrupts():  # the drop is dispatched through its address
            drop_batch(numba.get_num_threads(), mdl, np.ascontiguousarray(init),
                       np.ascontiguousarray(mu_run[run]), np.ascontiguousarray(fid[run]), r,
                       t_end, stop_mode, o, ck, st, drop_address())  # fmt: skip
        status[run], out[run], checks[run] = st, o, ck
    failed = _failures(status, run, out, model)  # before the rows are blanked
    inaccurate = _refuse_inaccurate(out, checks, status, r)
    done = status == 0
    out[~done] = np.nan
    checks[~done] = np.nan
    dmax = out[:, F.O_DELTA_MAX]
    flags = np.where(done, np.nan_to_num(checks[:, CK_FLAGS]).astype(np.int64), 0)
    lifted = e_lifted_by_gravity(out[:, F.O_E], out[:, F.O_E_RAW], flags, r)  # drop_flags'
    flags[lifted] |= FLAG_GRAVITY_DOMINATED
    flags[done] |= np.asarray(extrapolation_flags(model.law_id, model.params, dmax[done]))
    limit = brittle_pressure(bm.rigid.material, flat)
    fmax = out[:, F.O_MAX_FORCE]
    flags[done] |= np.asarray(
        brittle_flags(model.law_id, model.params, dmax[done], fmax[done], limit)
    )
    refs = references_used(model, fric, bool(np.any(mu_run > 0.0))) + bm.references
    setup = batch_setup(body, flat, friction=fric.name, gravity=g, rtol=r, constant_angle=None,
                        law=law, law_params=law_params)  # fmt: skip
    depths = out[:, F.DROP_OUTPUT_FIELDS.index(ENGINE_NAME["dent_depth"])][status == 0]
    yields, said = flattening_words(bm.rigid.material, flat, depths, "dent_depth")
    drop_setup: dict[str, Any] = {"body": bm.description, "stop": stop, "time_limit": t_end}
    drop_setup["body_yields_first"] = int(yields)
    return DropBatchResult(
        out=out,
        status=status,
        flags=flags,
        initial_energy=checks[:, CK_E0],
        max_delta_ratio=np.asarray(delta_ratio(model.law_id, model.params, dmax)),
        inputs=cols,
        body=bm.description,
        law=model.name,
        friction=fric.name,
        gravity=g,
        rtol=r,
        references=tuple(dict.fromkeys(refs)),
        law_range=range_note(model.law_id, model.params),
        refusals={i: t for i, t in refusals.items() if status[i] == S.ST_BAD_INPUT}
        | failed
        | inaccurate,
        setup=DropSetup(setup | drop_setup),
        body_yields_first=yields,
        warnings=said,
    )


def _failures(
    status: np.ndarray, run: np.ndarray, out: np.ndarray, model: ContactModel
) -> dict[int, str]:
    """The message of each drop that ran and failed (``run`` and a status), by case index, as
    ``simulate_drop``'s error words it from its output row (``drop_checks.status_error``: its
    steps, its time, what to change)."""
    why: dict[int, str] = {}
    for i in np.flatnonzero(run & (status != 0)).tolist():
        row = out[i] if np.all(np.isfinite(out[i, [F.O_N_STEPS, F.O_T_FINAL]])) else None
        why[i] = str(status_error(int(status[i]), model, row)).removeprefix("drop: ")
    return why


def _refuse_inaccurate(
    out: np.ndarray, checks: np.ndarray, status: np.ndarray, rtol: float
) -> dict[int, str]:
    """ST_INACCURATE where a finished drop's energy balance closed worse than ``rtol`` promises
    over its steps (``drop_checks.check_energy_balance``, on every case at once); returns why,
    by case index: the whole message, its numbers as ``simulate_drop``'s error words them."""
    ok = np.flatnonzero(status == 0)
    if ok.size == 0:
        return {}
    columns = {name: out[ok, i] for i, name in enumerate(F.DROP_OUTPUT_FIELDS)}
    found = inaccurate_cases(columns, checks[ok, CK_E0], rtol)
    head = S.STATUS_MESSAGES[S.ST_INACCURATE]
    why = {int(ok[j]): f"{head}: {text}" for j, text in found.items()}
    status[list(why)] = S.ST_INACCURATE
    return why
