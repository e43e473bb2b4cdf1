"""Many drops of one body in one compiled call (numba ``prange``), and the per-case checks of a
finished drop that ``simulate_drop`` shares with it: the tip's sequence and the result flags.

``drop_batch`` runs ``drop`` (``driver``) for each case of an (N, 4) array of first-touch
states [angle [rad], vx, vy [m/s], spin [rad/s]] with its own mu and friction id, on the
model tuple of one body and law (``model.model_tuple``; its constants vector is copied per
case and given the case's angle, mu, friction, cell widths and step limit exactly as
``model.constants`` sets them). Partial slip runs the Mindlin pre-pass of ``simulate_drop``
first (its cells span the pre-pass's largest loading contact radius per end). Each case gets
a status (``kernels.status``); a failed case never stops the batch. The cases are dealt to
the threads in turn (case i to thread i mod T): the costs of neighbouring cases of a grid
differ little, so each thread gets its share of the costly ones.
"""

from __future__ import annotations

import math
from functools import cache

import numpy as np
from numba import njit, prange

from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.address_call import (
    AT_ACCEPT,
    AT_CELLS,
    AT_COAST,
    AT_EVENTS,
    AT_OUTPUTS,
    AT_PARTIAL_CELLS,
    AT_PARTIAL_RHS,
    AT_PARTIAL_STEP,
    AT_RECORD,
    AT_RHS,
    AT_STEP,
    DROP_SIGNATURE,
    call_drop,
)
from impactlab.dynamics.flexcore.driver import drop
from impactlab.dynamics.flexcore.setup import state_size
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.address_call import compiled_addresses
from impactlab.dynamics.kernels.cells import CP_DX, N_CELLS
from impactlab.dynamics.kernels.quality import (
    SLIP_VTOL,
    beyond_rim,
    energy_gained,
    gravity_dominated,
)
from impactlab.flags import (
    ENERGY_GAIN_RTOL_FACTOR,
    ENERGY_ROUNDOFF,
    FLAG_BEYOND_TIP,
    FLAG_ENERGY_GAIN,
    FLAG_GRAVITY_DOMINATED,
    FLAG_OTHER_END,
)

#: ``impactlab.friction`` ids the batch needs (coulomb, mindlin; partial slip is F.FR_PARTIAL).
FR_COULOMB = 1
FR_MINDLIN = 2
#: Columns of the per-case checks array ``checks`` (N, N_CHECKS) that ``drop_batch`` fills.
CK_E0, CK_FLAGS = 0, 1
N_CHECKS = 2


@njit(cache=True, error_model="numpy")
def initial_energy(m, inertia, vx, vy, w):
    """E0 = m (vx^2 + vy^2) / 2 + I_C w^2 / 2 [J] at first touch."""
    return 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * (w * w)


@njit_internal
def tip_sequence(contacts, n_contacts, duration, normal_impulse):
    """(duration [s], normal impulse [N s]) of the tip's sequence, and whether the other end
    touched in the run. The tip's sequence: its contacts until stop="sequence" would end,
    before the other end's first touch and before the first contact that began after the end
    test of stop="sequence" would have passed (``layout.CR_PAST``: the tip's return after a
    clear flight, which ``stop="flight"`` follows on); ``duration`` and ``normal_impulse``,
    the drop's totals, when neither came."""
    t1 = math.inf
    other = False
    for j in range(n_contacts):
        if contacts[j, F.CR_END] == 1.0:
            other = True
        if contacts[j, F.CR_END] == 1.0 or contacts[j, F.CR_PAST] == 1.0:
            t1 = min(t1, contacts[j, F.CR_T0])
    if t1 == math.inf:
        return duration, normal_impulse, other
    end = -math.inf
    impulse = 0.0
    for j in range(n_contacts):
        if contacts[j, F.CR_END] == 0.0 and contacts[j, F.CR_T0] < t1:
            end = max(end, contacts[j, F.CR_T0] + contacts[j, F.CR_DUR])
            impulse += contacts[j, F.CR_PN]
    return end, impulse, other


@njit(cache=True, error_model="numpy")
def sequence_flags(out, e0, m, g, rtol, contacts, n_contacts, radius):
    """The ``ResultFlag`` bits of a finished sequence but LAW_EXTRAPOLATED (docs/flexible.md,
    "Flags"): ENERGY_GAIN (the vibration energy counted with the kinetic; or friction that did
    positive work in a contact, ``friction_gained``), GRAVITY_DOMINATED on the tip's
    sequence (``tip_sequence``), OTHER_END when the other end touched in the run, or, unless
    gravity dominates, when e < 0 (or NaN); BEYOND_TIP when the flat reached the rim of an
    end's hemisphere (``radius`` [m]) in one of the contacts, at the angle of the end's section
    (the rod's plus its elastic rotation: ``layout.CR_TH0``)."""
    flags = 0
    for j in range(n_contacts):
        c = contacts[j]
        if beyond_rim(radius, c[F.CR_TH0], c[F.CR_TH1], c[F.CR_DMAX]):
            flags |= FLAG_BEYOND_TIP
    e_end = out[F.O_RIGID_KINETIC_ENERGY] + out[F.O_VIBRATION_ENERGY]
    e_pot = out[F.O_POTENTIAL_ENERGY]
    scale = e0 + e_end + abs(e_pot)  # the balance's, as energy_gained's
    if energy_gained(e0, e_end, e_pot, rtol) or friction_gained(contacts, n_contacts, scale, rtol):
        flags |= FLAG_ENERGY_GAIN
    duration, impulse, other = tip_sequence(
        contacts, n_contacts, out[F.O_DURATION], out[F.O_NORMAL_IMPULSE]
    )
    gravity = gravity_dominated(m * g * duration, impulse)
    if gravity:
        flags |= FLAG_GRAVITY_DOMINATED
    if other or not (gravity or out[F.O_E] >= 0.0):
        flags |= FLAG_OTHER_END
    return flags


@njit(cache=True, error_model="numpy")
def friction_gained(contacts, n_contacts, scale, rtol):
    """True when friction created energy in one of the ``n_contacts`` contacts: its net work
    [J] is positive beyond the energy criterion's tolerance, (ENERGY_GAIN_RTOL_FACTOR rtol +
    ENERGY_ROUNDOFF) times the balance's ``scale`` [J] (E0 + the final kinetic, vibration and
    |potential| energy), or (impulse_ratio) the contact point slid along the contact's fixed
    friction force faster than SLIP_VTOL times its normal speed at touch, the rigid engine's
    ``kernels.quality.slid_along_friction`` (positive work in part of the contact, whatever
    the net). The losses of the other contacts, or of the same contact, would hide that
    energy from the sequence's total (a contact's works are its end's own, also while the
    other end touches)."""
    limit = (ENERGY_GAIN_RTOL_FACTOR * rtol + ENERGY_ROUNDOFF) * scale
    gained = False
    for j in range(n_contacts):
        if contacts[j, F.CR_WT] > limit:
            gained = True
        if contacts[j, F.CR_VALONG] > SLIP_VTOL * contacts[j, F.CR_VNIN]:
            gained = True
    return gained


@njit_internal
def case_model(mdl, angle, mu, fid, w0, w1, max_steps):
    """The model tuple of one case: a copy of the constants vector with the case's angle, its
    sine and cosine, mu, friction id, cell widths [m] and step limit (as ``model.constants``),
    and the addresses of its friction model's right-hand side, step and cell switches, and the
    others (the batch model ends with partial slip's right-hand side, step and cell switches:
    ``indirect.batch_addresses``)."""
    c = mdl[2].copy()
    cells = fid == F.FR_PARTIAL
    c[F.FC_TH0] = angle
    c[F.FC_S0] = math.sin(angle)
    c[F.FC_C0] = math.cos(angle)
    c[F.FC_MU] = mu
    c[F.FC_FRIC] = float(fid)
    c[F.FC_CP + CP_DX] = w0
    c[F.FC_CP + F.NFCP + CP_DX] = w1
    c[F.FC_MAX_STEPS] = float(min(max_steps, F.DROP_MAX_STEPS))
    rhs = mdl[AT_PARTIAL_RHS] if cells else mdl[AT_RHS]
    step = mdl[AT_PARTIAL_STEP] if cells else mdl[AT_STEP]
    switches = mdl[AT_PARTIAL_CELLS] if cells else mdl[AT_CELLS]
    return (mdl[0], mdl[1], c, mdl[3], mdl[4], mdl[5], mdl[6], mdl[7], mdl[8], mdl[9],
            mdl[10], mdl[11], mdl[12], rhs, step, mdl[AT_EVENTS], mdl[AT_ACCEPT], mdl[AT_COAST],
            mdl[AT_OUTPUTS], mdl[AT_RECORD], switches)  # fmt: skip


@njit(cache=True, error_model="numpy")
def _run(drop_at, mdl, vx, vy, w, rtol, t_max, stop_mode, no_history, out, contacts, dents):
    """One drop (``driver.drop`` at its address ``drop_at``) on zeroed tables: (status,
    n_contacts)."""
    contacts[:] = 0.0
    dents[:] = 0.0
    yfinal = np.zeros(state_size(mdl[3].shape[0], mdl[2][F.FC_FRIC]))
    st, ncon, _nd, _h, _nh = call_drop(
        drop_at, mdl, vx, vy, w, rtol, t_max, stop_mode, no_history, out, contacts, dents, yfinal
    )
    return st, ncon


@njit_internal
def cell_widths(law, p, contacts, n_contacts):
    """Partial slip: the cell width of each end [m] (``N_CELLS`` cells over the largest loading
    contact radius of its contacts; an end without contacts: the tip's), as ``simulate_drop``."""
    a0 = 0.0
    a1 = 0.0
    for j in range(n_contacts):
        a = loading_contact_radius(law, p, contacts[j, F.CR_DMAX])
        if contacts[j, F.CR_END] == 0.0:
            a0 = max(a0, a)
        else:
            a1 = max(a1, a)
    if not a1 > 0.0:
        a1 = a0
    return a0 * 1.0001 / N_CELLS, a1 * 1.0001 / N_CELLS


@njit_internal
def one_drop(drop_at, mdl, init, mu, fid, rtol, t_max, stop_mode, out, checks):
    """One case of the batch: fills ``out`` (layout.N_DROP_OUT) and ``checks`` (N_CHECKS);
    returns its status."""
    contacts = np.zeros((F.MAX_CONTACTS, F.NCR))
    dents = np.zeros((F.MAX_DENTS, F.NDT))
    no_history = init.shape[0] < 0  # a run-time False: one specialisation of ``drop``
    angle, vx, vy, w = init[0], init[1], init[2], init[3]
    w0 = math.nan
    w1 = math.nan
    max_steps = F.DROP_MAX_STEPS
    if fid == F.FR_PARTIAL:  # the cells span the contact radius of a Mindlin pre-pass
        pre = case_model(mdl, angle, mu, np.int64(FR_MINDLIN), w0, w1, max_steps)
        st, ncon = _run(
            drop_at, pre, vx, vy, w, rtol, t_max, stop_mode, no_history, out, contacts, dents
        )
        if st != F.ST_OK:
            return st
        w0, w1 = cell_widths(mdl[0], mdl[1], contacts, ncon)
        max_steps = max(F.PARTIAL_MIN_STEPS, F.PARTIAL_STEP_FACTOR * int(out[F.O_N_STEPS]))
    m = case_model(mdl, angle, mu, fid, w0, w1, max_steps)
    st, ncon = _run(drop_at, m, vx, vy, w, rtol, t_max, stop_mode, no_history, out, contacts, dents)
    if st != F.ST_OK:
        return st
    c = mdl[2]
    e0 = initial_energy(c[F.FC_M], c[F.FC_I], vx, vy, w)
    checks[CK_E0] = e0
    checks[CK_FLAGS] = sequence_flags(
        out, e0, c[F.FC_M], c[F.FC_G], rtol, contacts, ncon, c[F.FC_R]
    )
    return st


@njit(cache=True, parallel=True, error_model="numpy")
def drop_batch(threads, mdl, init, mu, fid, rtol, t_max, stop_mode, out, checks, status, drop_at):
    """Run ``init.shape[0]`` drops on ``threads`` loops (pass ``numba.get_num_threads()``).

    ``mdl``: the model tuple of the body and law (its constants' angle, mu, friction and
    cells are set per case) and, last, the addresses of partial slip's right-hand side, step
    and cell switches (``indirect.batch_addresses``; where no case uses it, never called);
    ``init``: (N, 4) [angle,
    vx, vy, spin]; ``mu``: (N,) the friction coefficient each case runs with; ``fid``: (N,)
    int64 friction ids; rtol, t_max [s], stop_mode as ``drop``. Fills ``out`` (N,
    layout.N_DROP_OUT), ``checks`` (N, N_CHECKS: E0 [J] and the flags but LAW_EXTRAPOLATED)
    and ``status`` (N,) int32; ``drop_at``: the address of ``driver.drop``
    (``drop_address``)."""
    n = init.shape[0]
    nt = max(1, min(threads, n))
    for t in prange(nt):
        for i in range(t, n, nt):
            status[i] = one_drop(drop_at, mdl, init[i], mu[i], fid[i], rtol, t_max, stop_mode,
                                 out[i], checks[i])  # fmt: skip


@cache
def drop_address() -> int:
    """The entry point of ``driver.drop`` (``address_call.DROP_SIGNATURE``, the compile
    ``simulate_drop`` uses; compiled, or loaded from the cache, on first use, then kept for the
    process): the batch calls it through its address, so that its library does not generate
    the drop again."""
    return compiled_addresses(((drop, DROP_SIGNATURE),))[0]
