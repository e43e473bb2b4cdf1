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
The same rules as the slipcore (``slipcore.model`` / ``slipcore.switches``; the import
contracts keep the two compiled packages apart, so the kernels are written here once for any
offset and per end; see docs/flexible.md).

Per end k the cell modes and slip signs are columns of the mode table (``MD_CM``, ``MD_SG``),
the limits, their rates and the forces columns of ``ek`` (``EK_L``, ``EK_LD``, ``EK_F``), the
cell parameters (``CP_*``) a slice of the constants vector at ``FC_CP + k NFCP``.
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.core.normal import dforce_ddelta, dradius_ddelta, radius
from impactlab.dynamics.flexcore import layout as F
from impactlab.dynamics.flexcore.friction import rigid_mode

OUT = 0.0  #: not (or no longer) in contact: f = 0
STICK = 1.0  #: df/dt = 2 G_1 l v_slip
SLIP = 2.0  #: f = s L
CP_G1 = 0  #: G_1 = 4 G* [Pa]
CP_DX = 1  #: cell width [m]
CP_VTOL = 2  #: slip-rate hysteresis of the slip -> stick test [m/s]
CP_FTOL = 3  #: force hysteresis of the stick -> slip test [N]
SLIP_HYST = 1e-9  #: relative hysteresis of the stick -> slip test
STEP_PAST = 1.05  #: a step ends this far past the predicted next cell boundary
N_CELLS = 16  #: cells over the estimated largest contact radius (``friction.PARTIAL_SLIP_CELLS``)


@njit(cache=True, inline="always", error_model="numpy")
def n_in(cm):
    """Number of cells in contact (born inwards-out, released outside-in)."""
    n = 0
    while n < cm.shape[0] and cm[n] != OUT:
        n += 1
    return n


@njit(cache=True, inline="always", error_model="numpy")
def cell_length(i, a, dx):
    """Length of cell ``i`` inside the contact radius ``a``."""
    ln = a - i * dx
    return 0.0 if ln < 0.0 else (dx if ln > dx else ln)


@njit(cache=True, inline="always", error_model="numpy")
def stick_rate(i, f, a, ad, vs, cp):
    """df_i/dt of cell ``i`` (force ``f``) in STICK: new material enters unstressed, material
    leaving a receding edge cell takes its share of the force."""
    ln = cell_length(i, a, cp[CP_DX])
    r = 2.0 * cp[CP_G1] * ln * vs
    if ad < 0.0 and 0.0 < ln < cp[CP_DX]:
        r += f * ad / ln
    return r


@njit(cache=True, inline="always", error_model="numpy")
def limits(i, dx, mu, Fn, Fd, ar, ad):
    """(L_i, dL_i/dt) of cell ``i``: mu F_n g_i(a) and its rate (F_n' = Fd, a' = ad)."""
    lo = i * dx
    if not (lo < ar and Fn > 0.0):
        return 0.0, 0.0
    edge = lo + dx > ar
    r = ar if edge else lo + dx
    r3 = r * r * r - lo * lo * lo
    a2 = ar * ar
    g = max(0.0, 1.5 / ar * (r - lo) - 0.5 * r3 / (a2 * ar))  # >= 0 despite round-off
    if edge:
        dg = 1.5 * lo / a2 - 1.5 * lo * lo * lo / (a2 * a2)
    else:
        dg = -1.5 * (r - lo) / a2 + 1.5 * r3 / (a2 * a2)
    return mu * Fn * g, mu * (Fd * g + Fn * dg * ad)


@njit(cache=True, inline="always", error_model="numpy")
def cell_switch(i, cm, sg, cp, L, Ld, f, ar, ad, vs):
    """Event function of cell ``i``: STICK -> SLIP when |f| passes its limit, SLIP -> STICK
    when the limit outruns the stick trial (fires when it goes from <= 0 to > 0)."""
    if cm[i] == STICK:
        return abs(f[i]) - L[i] * (1.0 + SLIP_HYST) - cp[CP_FTOL]
    if cm[i] == SLIP and ar > i * cp[CP_DX]:
        ln = cell_length(i, ar, cp[CP_DX])
        trial = stick_rate(i, f[i], ar, ad, vs, cp)
        return Ld[i] - sg[i] * trial - 2.0 * cp[CP_G1] * ln * cp[CP_VTOL]
    return -1.0


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


@njit(cache=True, error_model="numpy")
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


@njit(cache=True, error_model="numpy")
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


@njit(cache=True, error_model="numpy")
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
    for i in range(nin):
        ev[e0 + F.FG_CELL + i] = cell_switch(i, cm, sg, cp, L, Ld, f, ar, ad, ek[k, F.EK_VT])


@njit(cache=True, error_model="numpy")
def birth(i, y, o, cm, sg, cp, mu, estar, Fn, vn, vs, ar, ad):
    """Cell ``i`` enters the contact unstressed, slipping (towards v_slip) iff
    G_1 |v_slip| a^2 > 1.5 mu F_n a' (at a = 0: G_1 |v_slip| > mu E* |v_n|), else sticking."""
    y[o + i] = 0.0
    g1 = cp[CP_G1]
    if ar <= 0.0:
        slip = g1 * abs(vs) > mu * estar * abs(vn)
    else:
        slip = g1 * abs(vs) * ar * ar > 1.5 * mu * Fn * ad
    if vs != 0.0 and slip:
        cm[i] = SLIP
        sg[i] = 1.0 if vs > 0.0 else -1.0
    else:
        cm[i] = STICK
        sg[i] = 0.0


@njit(cache=True, error_model="numpy")
def to_slip(i, y, o, cm, sg, L):
    """Cell ``i`` slips in the direction of its force, clamped to its limit."""
    cm[i] = SLIP
    sg[i] = 1.0 if y[o + i] > 0.0 else -1.0
    y[o + i] = sg[i] * L[i]


@njit(cache=True, error_model="numpy")
def to_stick(i, y, o, cm, sg, L):
    """Cell ``i`` sticks with the force it had on its limit."""
    y[o + i] = sg[i] * L[i]
    cm[i] = STICK


@njit(cache=True, error_model="numpy")
def reset(md, k, y, o):
    """End k's cells out of contact, unstressed (touch and separation)."""
    for i in range(F.NCS):
        md[k, F.MD_CM + i] = OUT
        md[k, F.MD_SG + i] = 0.0
        y[o + i] = 0.0


@njit(cache=True, error_model="numpy")
def horizon(c, md, ek):
    """Time until the contact radius of an end in contact reaches its next cell boundary
    (inf when none lies ahead): a step ends just past it (a kink of the cell lengths)."""
    hz = math.inf
    for k in range(F.NE):
        if md[k, F.MD_IN] == 0.0:
            continue
        cm = md[k, F.MD_CM : F.MD_CM + F.NCS]
        nin = n_in(cm)
        dx = c[F.FC_CP + k * F.NFCP + CP_DX]
        ar = ek[k, F.EK_A]
        ad = ek[k, F.EK_AD]
        if ad > 0.0 and nin < F.NCS:
            hz = min(hz, (nin * dx - ar) / ad)
        elif ad < 0.0 and nin > 1:
            hz = min(hz, ((nin - 1) * dx - ar) / ad)
    return hz


@njit(cache=True, error_model="numpy")
def step_cap(h, c, md, ek, hmin):
    """Partial slip: the step ``h`` ended just past (x STEP_PAST) the next cell boundary."""
    if c[F.FC_FRIC] != F.FR_PARTIAL:
        return h
    hz = horizon(c, md, ek)
    return min(h, STEP_PAST * hz + hmin) if hz > 0.0 else h


@njit(cache=True, error_model="numpy")
def n_active(md, n, M):
    """Components of the state in the error norm: all but the cells out of contact."""
    ny0 = 6 + 2 * M + F.NQUAD
    if n == ny0:
        return n
    na = ny0
    for k in range(F.NE):
        na += n_in(md[k, F.MD_CM : F.MD_CM + F.NCS])
    return na


@njit(cache=True, error_model="numpy")
def any_stuck(md, k):
    """Whether a cell of end k sticks."""
    found = False
    for i in range(F.NCS):
        found = found or md[k, F.MD_CM + i] == STICK
    return found
