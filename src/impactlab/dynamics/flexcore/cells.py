"""Mindlin-Deresiewicz partial slip (``friction="partial_slip"``) at the ends of the flexible
rod (compiled): the cells of the method of dimensionality reduction, body-independent (they
take F_n, its rate, a, da/dt and v_slip, and the cell forces at an offset ``o`` of the state).

The model is the one of the rigid engine's ``impactlab.dynamics.slipcore`` (Mindlin 1949,
doi:10.1115/1.4009973; Mindlin & Deresiewicz 1953, doi:10.1115/1.4010702; exact in its
one-dimensional MDR form, Popov & Hess, doi:10.1007/978-3-642-53876-6; derivation, validity
and limits in docs/verification/index.md, "Partial slip"): a line of elastic-perfectly-plastic
elements of stiffness G_1 = 4 G* per unit length on |x| < a, cut into cells of width dx; cell i
(both halves) carries f_i, F_t = -sum f_i; limit L_i = mu F_n g_i(a) (sum L_i = mu F_n);
STICK: df_i/dt = 2 G_1 l_i v_slip (plus the share of a receding edge cell), SLIP: f_i = s_i L_i.
The cell kernels are the shared ones of ``impactlab.dynamics.kernels.cells`` (also those of
the rigid body's ``slipcore``); here they are applied per end (see docs/flexible.md).

Per end k the cell modes and slip signs are columns of the mode table (``MD_CM``, ``MD_SG``),
the limits, their rates and the forces columns of ``ek`` (``EK_L``, ``EK_LD``, ``EK_F``), the
cell parameters (``CP_*``) a slice of the constants vector at ``FC_CP + k NFCP``.
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.friction import rigid_mode
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.cells import (
    CP_DX,
    OUT,
    SLIP,
    STEP_PAST,
    STICK,
    boundary_time,
    cell_switch,
    limits,
    n_in,
    stick_rate,
)
from impactlab.dynamics.kernels.normal import dforce_ddelta, dradius_ddelta, radius


@njit(cache=True, inline="always", error_model="numpy")
def views(c, md, ek, k):
    """End k's cell modes, signs, parameters, limits, limit rates and forces (array views)."""
    cp = c[F.FC_CP + k * F.NFCP : F.FC_CP + (k + 1) * F.NFCP]
    cm = md[k, F.MD_CM : F.MD_CM + F.NCS]
    sg = md[k, F.MD_SG : F.MD_SG + F.NCS]
    L = ek[k, F.EK_L : F.EK_L + F.NCS]
    Ld = ek[k, F.EK_LD : F.EK_LD + F.NCS]
    f = ek[k, F.EK_F : F.EK_F + F.NCS]
    return cm, sg, cp, L, Ld, f


@njit_internal
def cell_forces(law, p, c, md, k, y, o, ek):
    """F_t [N] of end k in contact from its cells (forces at y[o:]); fills ``EK_A``, ``EK_AD``
    and the end's limits, rates and forces in ``ek`` (``ek`` holds delta, v_n and F_n)."""
    rm = rigid_mode(md, k)
    delta = ek[k, F.EK_DELTA]
    Fn = ek[k, F.EK_FN]
    ddel = -ek[k, F.EK_VN]
    ar = radius(law, p, rm, delta)
    Fd = dforce_ddelta(law, p, rm, delta, Fn) * ddel
    ad = dradius_ddelta(law, p, rm, delta) * ddel
    ek[k, F.EK_A] = ar
    ek[k, F.EK_AD] = ad
    cm, sg, cp, L, Ld, f = views(c, md, ek, k)
    dx = cp[CP_DX]
    mu = c[F.FC_MU]
    Ft = 0.0
    for i in range(n_in(cm)):
        L[i], Ld[i] = limits(i, dx, mu, Fn, Fd, ar, ad)
        f[i] = sg[i] * L[i] if cm[i] == SLIP else y[o + i]
        Ft -= f[i]
    return Ft


@njit_internal
def cell_rates(c, md, k, o, ek, der):
    """The derivatives of end k's cell forces into der[o:o + NCS] (0 out of contact)."""
    cm, sg, cp, _L, Ld, f = views(c, md, ek, k)
    nin = n_in(cm) if md[k, F.MD_IN] != 0.0 else 0
    ar = ek[k, F.EK_A]
    ad = ek[k, F.EK_AD]
    vs = ek[k, F.EK_VT]
    for i in range(F.NCS):
        if i >= nin:
            der[o + i] = 0.0
        elif cm[i] == STICK:
            der[o + i] = stick_rate(i, f[i], ar, ad, vs, cp)
        else:
            der[o + i] = sg[i] * Ld[i]


@njit_internal
def cell_events(c, md, k, ek, ev):
    """End k's cell events into ev[NEV + k NEVC:] (-1 where none can fire)."""
    e0 = F.NFEV + k * F.NFEVC
    for i in range(F.NFEVC):
        ev[e0 + i] = -1.0
    if md[k, F.MD_IN] == 0.0:
        return
    cm, sg, cp, L, Ld, f = views(c, md, ek, k)
    nin = n_in(cm)
    ar = ek[k, F.EK_A]
    ad = ek[k, F.EK_AD]
    dx = cp[CP_DX]
    if nin < F.NCS:
        ev[e0 + F.FG_BIRTH] = ar - nin * dx
    if nin > 1:
        ev[e0 + F.FG_REL] = (nin - 1) * dx - ar
    vs = ek[k, F.EK_VT]
    for i in range(nin):
        ev[e0 + F.FG_CELL + i] = cell_switch(i, cm, sg, cp, L[i], Ld[i], f[i], ar, ad, vs)


@njit(cache=True, error_model="numpy")
def reset(md, k, y, o):
    """End k's cells out of contact, unstressed (touch and separation)."""
    for i in range(F.NCS):
        md[k, F.MD_CM + i] = OUT
        md[k, F.MD_SG + i] = 0.0
        y[o + i] = 0.0


@njit(cache=True, inline="always", error_model="numpy")
def horizon(c, md, ek):
    """Time until the contact radius of an end in contact reaches its next cell boundary
    (inf when none lies ahead): a step ends just past it (a kink of the cell lengths)."""
    hz = math.inf
    for k in range(F.NE):
        if md[k, F.MD_IN] == 0.0:
            continue
        cm = md[k, F.MD_CM : F.MD_CM + F.NCS]
        dx = c[F.FC_CP + k * F.NFCP + CP_DX]
        hz = min(hz, boundary_time(cm, dx, ek[k, F.EK_A], ek[k, F.EK_AD]))
    return hz


@njit(cache=True, inline="always", error_model="numpy")
def step_cap(h, c, md, ek, hmin):
    """Partial slip: the step ``h`` ended just past (x STEP_PAST) the next cell boundary."""
    if c[F.FC_FRIC] != F.FR_PARTIAL:
        return h
    hz = horizon(c, md, ek)
    return min(h, STEP_PAST * hz + hmin) if hz > 0.0 else h


@njit(cache=True, inline="always", error_model="numpy")
def n_active(md, n, M):
    """Components of the state in the error norm: all but the cells out of contact."""
    ny0 = 6 + 2 * M + F.NQUAD
    if n == ny0:
        return n
    na = ny0
    for k in range(F.NE):
        na += n_in(md[k, F.MD_CM : F.MD_CM + F.NCS])
    return na
