"""The partial-slip contact of a rigid body: the right-hand side and the event functions on the
state array ``y`` (rigid-body state, then the cell forces), with the cell kernels (limits,
lengths, stick rates, switch functions) of ``impactlab.dynamics.kernels.cells``.

Mindlin-Deresiewicz partial slip with arbitrary normal and tangential history (Mindlin 1949,
doi:10.1115/1.4009973; Mindlin & Deresiewicz 1953, doi:10.1115/1.4010702) in its exact
one-dimensional representation by the method of dimensionality reduction (Popov & Hess,
doi:10.1007/978-3-642-53876-6): a line of independent elastic-perfectly-plastic tangential
elements of stiffness G_1 = 4 G* per unit length on |x| < a(t), each limited by mu times the
Hertzian line load q(x) = (3 F_n / 4a)(1 - x^2/a^2). The line is cut into cells of width dx
(mirrored to -x): cell i = [i dx, (i + 1) dx] carries the force f_i of both halves; F_t = -sum f_i.

- length in contact l_i = clamp(a - i dx, 0, dx); full-stick stiffness sum 2 G_1 l_i = 8 G* a;
- limit L_i = mu F_n g_i(a), g_i = (3/2a)(r - l) - (r^3 - l^3)/(2a^3), l = i dx,
  r = min((i + 1) dx, a): sum L_i = mu F_n exactly, L_i -> 0 as the edge crosses i dx;
- STICK: df_i/dt = 2 G_1 l_i v_slip, plus f_i l_i'/l_i for a receding edge cell; SLIP:
  f_i = s_i L_i; OUT: f_i = 0.

docs/verification/index.md ("Partial slip") has the derivation, validity and limits.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal, njit_llvm_inline, njit_no_refcount
from impactlab.dynamics.kernels.cells import (
    CP_DX,
    CP_G1,
    SLIP,
    STICK,
    boundary_time,
    cell_length,
    cell_switch,
    limits_inv,
    n_in,
)
from impactlab.dynamics.kernels.layout import (
    C_DLIM,
    C_DSW,
    C_G,
    C_I,
    C_M,
    C_MU,
    EV_LIMIT,
    EV_RELOAD,
    EV_SEP,
    EV_SWITCH,
    EV_VN,
    M_COMP,
    M_DM,
    M_DR,
    M_PHASE,
    S_PHI,
    S_Q,
    S_SPIN,
    S_VX,
    S_VY,
    S_WORK,
    S_X,
    S_Y,
)
from impactlab.dynamics.kernels.normal import normal_contact, radius
from impactlab.dynamics.kernels.rhs import geometry_llvm
from impactlab.dynamics.slipcore.layout import G_BIRTH, G_CELL, G_REL, Y_CELL


@njit_llvm_inline
def radius_llvm(law, p, md, delta):
    """``normal.radius`` compiled once and inlined by LLVM (``kernels._jit``): ``evaluate`` and
    ``event_value`` share it, as they share ``kernels.rhs.geometry_llvm`` with the rigid
    engine."""
    return radius(law, p, md, delta)


@njit_llvm_inline
def normal_contact_llvm(law, p, md, delta):
    """``normal.normal_contact`` (F_n, dF_n/d delta, a, da/d delta in one pass) compiled once
    and inlined by LLVM into ``evaluate`` and ``event_value``."""
    return normal_contact(law, p, md, delta)


@njit_llvm_inline
def normal_state(law, p, c, md, y):
    """(delta, a, b, F_n, v_n, v_slip, radius, dF_n/dt, d radius/dt) at state ``y``: the
    normal contact from one pass over the law (``kernels.normal.normal_contact``)."""
    delta, a, b, _xs, _sl = geometry_llvm(c, y)
    w = y[S_SPIN]
    vn = y[S_VY] - w * a
    vs = y[S_VX] + w * b
    Fn, Fs, ar, As = normal_contact_llvm(law, p, md, delta)
    return delta, a, b, Fn, vn, vs, ar, Fs * -vn, As * -vn


@njit_llvm_inline
def cells_tangential_force(W, nin):
    """F_t = -sum f_i [N] over the ``nin`` cells in contact (in cell order, from 0.0). A loop of
    its own: the cells' loop before it, free of this chain of additions, can be vectorised."""
    Ft = 0.0
    for i in range(nin):
        Ft -= W[2, i]
    return Ft


@njit(cache=True, inline="always", error_model="numpy")
def cell_stick_rate(i, f, ar, ad, vs, g2, dx):
    """``kernels.cells.stick_rate`` of cell ``i`` (force ``f`` [N]) with the cell parameters
    read once by the caller (``g2`` = 2 G_1 [Pa], ``dx`` [m]; the same bits) [N/s]."""
    ln = cell_length(i, ar, dx)
    r = g2 * ln * vs
    if ad < 0.0 and 0.0 < ln < dx:
        r += f * ad / ln
    return r


@njit_llvm_inline
def cell_quantities(y, cm, sg, cp, W, mu, Fn, Fd, ar, ad, vs, nin, dy, o):
    """The ``nin`` cells in contact: W[0] = limits L_i, W[1] = dL_i/dt, W[2] = forces f_i (SLIP:
    s_i L_i) and their rates df_i/dt into dy[o + i] (STICK: ``kernels.cells.stick_rate``, SLIP:
    s_i dL_i/dt). One loop without branches, which LLVM vectorises from about 40 cells in
    contact (below, its cost model keeps the scalar loop: the run-time checks that the arrays
    do not overlap would not pay)."""
    dx = cp[CP_DX]
    g2 = 2.0 * cp[CP_G1]
    u = 1.0 / ar if ar > 0.0 else 0.0
    for i in range(nin):
        L, Ld = limits_inv(i, dx, mu, Fn, Fd, ar, ad, u)
        yi = y[Y_CELL + i]  # read unconditionally: no masked loads
        s = sg[i]
        mode = cm[i]
        f = s * L if mode == SLIP else yi
        W[0, i] = L
        W[1, i] = Ld
        W[2, i] = f
        r = cell_stick_rate(i, f, ar, ad, vs, g2, dx)
        dy[o + i] = r if mode == STICK else s * Ld


@njit_llvm_inline
def cell_forces(y, cm, sg, cp, W, mu, Fn, Fd, ar, ad, vs, nin, dy, o):
    """``cell_quantities`` for a stage inside a step: W[2] = the forces f_i and their rates into
    dy[o + i], the same values (the same bits), without W[0] and W[1] (the limits and their
    rates, which only the event functions read) and without the limits of the sticking cells
    (a slipping cell's force is s_i L_i)."""
    dx = cp[CP_DX]
    g2 = 2.0 * cp[CP_G1]
    u = 1.0 / ar if ar > 0.0 else 0.0
    for i in range(nin):
        if cm[i] == SLIP:
            L, Ld = limits_inv(i, dx, mu, Fn, Fd, ar, ad, u)
            W[2, i] = sg[i] * L
            dy[o + i] = sg[i] * Ld
        else:  # STICK
            f = y[Y_CELL + i]
            W[2, i] = f
            dy[o + i] = cell_stick_rate(i, f, ar, ad, vs, g2, dx)


@njit_no_refcount
def evaluate(law, p, c, md, y, cm, sg, cp, W):
    """Contact quantities at state ``y``: fills W[0] = limits L_i, W[1] = dL_i/dt, W[2] = the
    cell forces f_i (OUT: 0, SLIP: s_i L_i) and W[3] = their rates, and returns
    (delta, a, b, F_n, F_t, v_n, v_slip, radius, d radius/dt, n in contact)."""
    delta, a, b, Fn, vn, vs, ar, Fd, ad = normal_state(law, p, c, md, y)
    nin = n_in(cm)
    cell_quantities(y, cm, sg, cp, W, c[C_MU], Fn, Fd, ar, ad, vs, nin, W[3], np.int64(0))
    return delta, a, b, Fn, cells_tangential_force(W, nin), vn, vs, ar, ad, nin


@njit_llvm_inline
def rigid_rates(c, y, ev, dy):
    """The time derivative of the rigid-body state into ``dy`` from the quantities ``ev``."""
    _delta, a, b, Fn, Ft, vn, _vs, _ar, _ad, _nin = ev
    m = c[C_M]
    dy[S_X] = y[S_VX]
    dy[S_Y] = y[S_VY]
    dy[S_PHI] = y[S_SPIN]
    dy[S_VX] = Ft / m
    dy[S_VY] = Fn / m - c[C_G]
    dy[S_SPIN] = (b * Ft - a * Fn) / c[C_I]
    dy[S_WORK] = Fn * vn
    dy[S_Q] = 0.0


@njit_no_refcount
def derivative(c, y, W, ev, dy):
    """The time derivative of ``y`` into ``dy`` from the quantities ``ev`` and ``W`` of
    ``evaluate``."""
    rigid_rates(c, y, ev, dy)
    for i in range(ev[9]):
        dy[Y_CELL + i] = W[3, i]


@njit_llvm_inline
def evaluate_rates(law, p, c, md, y, cm, sg, cp, W, dy, nin, limits):
    """``evaluate`` and ``derivative`` together for the ``nin`` cells in contact (the same
    bits): fills ``W[:3]`` (with ``limits`` False only ``W[2]``: ``cell_forces``) and ``dy``,
    returns the quantities of ``evaluate``. The stages of a step call it, inlined by LLVM: a
    call passes about 90 values (the arrays' fields, the constant and mode tuples), about
    35 ns."""
    delta, a, b, Fn, vn, vs, ar, Fd, ad = normal_state(law, p, c, md, y)
    o = np.int64(Y_CELL)
    if limits:
        cell_quantities(y, cm, sg, cp, W, c[C_MU], Fn, Fd, ar, ad, vs, nin, dy, o)
    else:
        cell_forces(y, cm, sg, cp, W, c[C_MU], Fn, Fd, ar, ad, vs, nin, dy, o)
    ev = (delta, a, b, Fn, cells_tangential_force(W, nin), vn, vs, ar, ad, nin)
    rigid_rates(c, y, ev, dy)
    return ev


@njit_llvm_inline
def cell_event(i, cm, sg, cp, W, ar, ad, vs):
    """Event function of cell ``i``: STICK -> SLIP when |f| passes its limit (relative
    hysteresis SLIP_HYST), SLIP -> STICK when the limit outruns the stick trial."""
    return cell_switch(i, cm, sg, cp, W[0, i], W[1, i], W[2, i], ar, ad, vs)


@njit_llvm_inline
def events_llvm(c, md, cm, sg, cp, W, ev, g):
    """All event functions into ``g`` (fire when g goes from <= 0 to > 0): the core's normal
    events (EV_*), the birth and release of the outermost cell, and one per cell."""
    delta, _a, _b, _Fn, _Ft, vn, vs, ar, ad, nin = ev
    for k in range(g.shape[0]):
        g[k] = -1.0
    comp = md[M_COMP] != 0.0
    g[EV_VN] = vn if comp else -vn
    if md[M_PHASE] == 0.0:
        g[EV_LIMIT] = delta - c[C_DLIM]
        g[EV_SWITCH] = delta - c[C_DSW]
    elif comp:
        g[EV_RELOAD] = delta - md[M_DM]
    else:
        g[EV_SEP] = md[M_DR] - delta
    dx = cp[CP_DX]
    if nin < cm.shape[0]:
        g[G_BIRTH] = ar - nin * dx
    if nin > 1 and cm[nin - 1] == STICK:  # a slipping edge cell leaves without an event
        g[G_REL] = (nin - 1) * dx - ar
    for i in range(nin):
        g[G_CELL + i] = cell_event(i, cm, sg, cp, W, ar, ad, vs)


@njit_no_refcount
def events(c, md, cm, sg, cp, W, ev, g):
    """``events_llvm`` as a function of its own, for the callers other than the midpoint check
    of a step (which inlines it)."""
    events_llvm(c, md, cm, sg, cp, W, ev, g)


@njit_no_refcount
def event_value(k, law, p, c, md, y, cm, sg, cp):
    """Event function ``k`` alone at state ``y``: the value ``events`` gives it, from only the
    quantities it needs (the normal contact, and for a cell's event that cell's limit and force,
    by the formulas of ``evaluate``). The event search calls it many times per event."""
    delta, a, b, _xs, _sl = geometry_llvm(c, y)
    w = y[S_SPIN]
    vn = y[S_VY] - w * a
    comp = md[M_COMP] != 0.0
    if k == EV_VN:
        return vn if comp else -vn
    if md[M_PHASE] == 0.0:
        if k == EV_LIMIT:
            return delta - c[C_DLIM]
        if k == EV_SWITCH:
            return delta - c[C_DSW]
    elif comp:
        if k == EV_RELOAD:
            return delta - md[M_DM]
    elif k == EV_SEP:
        return md[M_DR] - delta
    if k < G_BIRTH:
        return -1.0
    dx = cp[CP_DX]
    nin = n_in(cm)
    if k == G_BIRTH:
        ar = radius_llvm(law, p, md, delta)
        return ar - nin * dx if nin < cm.shape[0] else -1.0
    if k == G_REL:
        ar = radius_llvm(law, p, md, delta)
        return (nin - 1) * dx - ar if nin > 1 and cm[nin - 1] == STICK else -1.0
    i = k - G_CELL
    if i >= nin:
        return -1.0
    vs = y[S_VX] + w * b
    # one pass over the law: its radius is ``radius``'s to the bit (tests/contact)
    Fn, Fs, ar, As = normal_contact_llvm(law, p, md, delta)
    Fd = Fs * -vn
    ad = As * -vn
    L, Ld = limits_inv(i, dx, c[C_MU], Fn, Fd, ar, ad, 1.0 / ar if ar > 0.0 else 0.0)
    f = sg[i] * L if cm[i] == SLIP else y[Y_CELL + i]
    return cell_switch(i, cm, sg, cp, L, Ld, f, ar, ad, vs)


#: While the contact grows, the step loop ends a step this far past the predicted next cell
#: boundary (a birth; ``STEP_PAST`` = 1.05 while it recedes, as for the flexible rod). The cell
#: lengths have a kink there, and a sticking edge cell's force rate 2 G_1 l v_slip with it: at
#: 5 % of the step past the kink the step's error estimate saw it and rejected the step in
#: about one crossing of two; the prediction is good to about 2.5e-3 of the step (median), so a
#: margin of 1e-3 leaves the kink within a few thousandths of the step's end. While the contact
#: recedes, a sticking edge cell (stick rate f a'/l, stiff as l -> 0) can alternate between its
#: limit and sticking in steps cut this close (one random impact: 827 switches): 1.05 there.
BOUNDARY_PAST = 1.001


@njit_internal
def boundary_horizon(cm, cp, ar, ad, add):
    """Time [s] until the contact radius ``ar`` (rate ``ad``, acceleration ``add``) reaches the
    next cell boundary, where a cell is born or released and the cell lengths have a kink:
    the positive root of ar + ad t + add t^2 / 2 = boundary (inf when none lies ahead). The
    acceleration matters: a(t) is concave while the contact grows, and a linear prediction
    falls short of the boundary, which then costs one more, tiny step."""
    lin = boundary_time(cm, cp[CP_DX], ar, ad)
    if not (lin < math.inf):
        return lin
    d = lin * ad  # the distance to the boundary (the sign of ad)
    disc = ad * ad + 2.0 * add * d
    if not (disc >= 0.0):
        return math.inf  # the radius turns before the boundary
    return 2.0 * abs(d) / (abs(ad) + math.sqrt(disc))


@njit_internal
def stored_energy(cm, cp, W, ar):
    """Elastic energy stored in the cells, sum f_i^2 / (4 G_1 l_i) [J]."""
    e = 0.0
    for i in range(n_in(cm)):
        ln = cell_length(i, ar, cp[CP_DX])
        if ln > 0.0:
            e += W[2, i] * W[2, i] / (4.0 * cp[CP_G1] * ln)
    return e
