"""The output vector of the flexible drop (``layout.DROP_FIELDS``) from the run state, the state
after the last separation, the contact records and the dents (compiled)."""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.kinematics import geometric_energy, vibration_energy
from impactlab.dynamics.kernels._jit import njit_internal


@njit(cache=True, inline="always", error_model="numpy")
def _tip_path(contacts, ncon, dents, nd):
    """(scar length, signed slip, slip path) [m] over the contacts and dents of end 0."""
    xlo = math.inf
    xhi = -math.inf
    slip = 0.0
    aslip = 0.0
    for i in range(ncon):
        if contacts[i, F.CR_END] != 0.0:
            continue
        xlo = min(xlo, contacts[i, F.CR_X0], contacts[i, F.CR_X1])
        xhi = max(xhi, contacts[i, F.CR_X0], contacts[i, F.CR_X1])
        slip += contacts[i, F.CR_SLIP]
        aslip += contacts[i, F.CR_ASLIP]
    for i in range(nd):
        if dents[i, F.DT_END] == 0.0:
            xlo = min(xlo, dents[i, F.DT_XLO])
            xhi = max(xhi, dents[i, F.DT_XHI])
    return xhi - xlo, slip, aslip


@njit(cache=True, inline="always", error_model="numpy")
def _energies(mdl, ye, out):
    """Works, vibration and rigid kinetic energy after the last contact."""
    c, om, om2, Tg, ia, ib = mdl[2], mdl[3], mdl[4], mdl[10], mdl[11], mdl[12]
    M = om.shape[0]
    iv = 3 + M
    iq = 6 + 2 * M
    vx = ye[iv]
    vy = ye[iv + 1]
    w = ye[iv + 2]
    out[F.O_VIBRATION_ENERGY] = vibration_energy(om2, M, ye)
    if Tg.shape[0] > 0:
        out[F.O_VIBRATION_ENERGY] += geometric_energy(Tg, ia, ib, ye)
    out[F.O_POTENTIAL_ENERGY] = c[F.FC_M] * c[F.FC_G] * ye[1]
    out[F.O_RIGID_KINETIC_ENERGY] = 0.5 * c[F.FC_M] * (vx * vx + vy * vy) + 0.5 * c[F.FC_I] * w * w
    out[F.O_WORK_NORMAL] = ye[iq]
    out[F.O_WORK_FRICTION] = ye[iq + 1]
    out[F.O_WORK_DAMPING] = ye[iq + 2]
    pn = 0.0
    pt = 0.0
    for k in range(F.NE):
        pn += ye[iq + 3 + 4 * k]
        pt += ye[iq + 4 + 4 * k]
    out[F.O_NORMAL_IMPULSE] = pn
    out[F.O_TANGENTIAL_IMPULSE] = pt


@njit_internal
def fill_outputs(mdl, sv, t, ye, vx0, vy0, out, contacts, dents):
    """Fill ``out``: the run's counters always, the impact measures only when the sequence
    finished (NaN otherwise). ``ye``: the state at the last separation; t: the final time."""
    c, om = mdl[2], mdl[3]
    M = om.shape[0]
    iv = 3 + M
    for i in range(out.shape[0]):
        out[i] = math.nan
    ncon = int(sv[F.SV_NCON])
    nd = int(sv[F.SV_ND])
    out[F.O_N_STEPS] = sv[F.SV_NSTEPS]
    out[F.O_N_JUMPS] = sv[F.SV_NJUMPS]
    out[F.O_N_CONTACTS] = ncon
    out[F.O_N_DENTS] = nd
    out[F.O_DELTA_MAX] = sv[F.SV_DMAX]
    out[F.O_MAX_FORCE] = sv[F.SV_FMAX]
    out[F.O_T_FINAL] = t
    out[F.O_ENERGY_ERROR] = sv[F.SV_EERR] / sv[F.SV_E0]
    out[F.O_STICK_TIME] = sv[F.SV_STICK]
    if sv[F.SV_FINISHED] == 0.0:
        return
    T = sv[F.SV_T_LAST_SEP]
    vx = ye[iv]
    vy = ye[iv + 1]
    w = ye[iv + 2]
    th = c[F.FC_TH0] + ye[2]
    a = c[F.FC_D] * math.cos(th)
    vn0 = sv[F.SV_VN0]
    out[F.O_DURATION] = T
    out[F.O_VX_OUT] = vx
    out[F.O_VY_OUT] = vy
    out[F.O_SPIN_OUT] = w
    out[F.O_ANGLE_OUT] = th
    out[F.O_E_RAW] = -(vy - w * a) / vn0
    out[F.O_E] = -(vy + c[F.FC_G] * T - w * a) / vn0
    dp = 0.0
    for i in range(nd):
        if dents[i, F.DT_END] == 0.0:  # the tip's dents (the other end's: ``dents``)
            dp = max(dp, dents[i, F.DT_DR])
    out[F.O_DELTA_P] = dp
    scar, slip, aslip = _tip_path(contacts, ncon, dents, nd)
    out[F.O_SCAR_LENGTH] = scar
    out[F.O_SLIDING_LENGTH] = slip
    out[F.O_SLIP_PATH] = aslip
    _energies(mdl, ye, out)
    dvy = vy - vy0 + c[F.FC_G] * T
    out[F.O_MU_APPARENT] = abs((vx - vx0) / dvy) if dvy != 0.0 else math.nan
    nxt = sv[F.SV_NEXT_END]
    out[F.O_NEXT_END] = nxt
    out[F.O_NEXT_TIME] = sv[F.SV_NEXT_TIME] + (t - T) if nxt >= 0 else math.inf
