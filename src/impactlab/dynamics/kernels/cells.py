"""The partial-slip cells (``friction="partial_slip"``), body-independent: cell modes, the cell
parameters, lengths, limits, stick rates, the stick/slip event function, births and switches.
The partial-slip engine (``slipcore``, a rigid body) and the flexible rod (``flexcore``, per
end) keep the cell forces in their own state arrays at an offset ``o`` and call these kernels.

Mindlin-Deresiewicz partial slip with arbitrary normal and tangential history (Mindlin 1949,
doi:10.1115/1.4009973; Mindlin & Deresiewicz 1953, doi:10.1115/1.4010702) in its exact
one-dimensional form by the method of dimensionality reduction (Popov & Hess,
doi:10.1007/978-3-642-53876-6): a line of elastic-perfectly-plastic elements of stiffness
G_1 = 4 G* per unit length on |x| < a, cut into cells of width dx (mirrored to -x); cell i
carries the force f_i of both halves, F_t = -sum f_i, its limit is L_i = mu F_n g_i(a) with
sum L_i = mu F_n. Derivation, validity and limits: docs/verification/index.md ("Partial slip").
Valid while the contact is Hertzian in shape (the limits use the Hertzian line load).
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.dynamics.kernels._jit import njit_internal

# --- cell modes (an entry of the mode array ``cm``) --------------------------------------------
OUT = 0  #: not (or no longer) in contact: f = 0
STICK = 1  #: df/dt = 2 G_1 l v_slip (+ the share of a receding edge cell)
SLIP = 2  #: f = s L (on its moving Coulomb limit)

# --- cell parameters (a float vector ``cp``) ---------------------------------------------------
CP_G1 = 0  #: G_1 = 4 G* [Pa]: tangential stiffness per unit length of the MDR line
CP_DX = 1  #: cell width [m]
CP_VTOL = 2  #: slip-rate hysteresis of the slip -> stick test [m/s]
CP_FTOL = 3  #: force hysteresis of the stick -> slip test [N]

#: Relative hysteresis of the stick -> slip test.
SLIP_HYST = 1e-9
#: Cells over the estimated largest contact radius (``friction.PARTIAL_SLIP_CELLS``; its
#: accuracy against the exact solution, by psi1, on the verification page).
N_CELLS = 16
#: A step ends this far past the predicted next cell boundary (a kink of the cell lengths).
STEP_PAST = 1.05


@njit(cache=True, inline="always", error_model="numpy")
def n_in(cm):
    """Number of cells in contact (born inwards-out, released outside-in)."""
    n = 0
    while n < cm.shape[0] and cm[n] != OUT:
        n += 1
    return n


@njit(cache=True, inline="always", error_model="numpy")
def any_stuck(cm):
    """True while at least one cell sticks (no gross slip)."""
    found = False
    for i in range(cm.shape[0]):
        found = found or cm[i] == STICK
    return found


@njit(cache=True, inline="always", error_model="numpy")
def cell_length(i, a, dx):
    """Length [m] of cell ``i`` inside the contact radius ``a`` [m]."""
    ln = a - i * dx
    return 0.0 if ln < 0.0 else (dx if ln > dx else ln)


@njit(cache=True, inline="always", error_model="numpy")
def stick_rate(i, f, a, ad, vs, cp):
    """df_i/dt [N/s] of cell ``i`` (force ``f`` [N]) in STICK: new material enters
    unstressed, material leaving a receding edge cell takes its share of the force."""
    ln = cell_length(i, a, cp[CP_DX])
    r = 2.0 * cp[CP_G1] * ln * vs
    if ad < 0.0 and 0.0 < ln < cp[CP_DX]:
        r += f * ad / ln
    return r


@njit(cache=True, inline="always", error_model="numpy")
def limits(i, dx, mu, Fn, Fd, ar, ad):
    """(L_i [N], dL_i/dt [N/s]) of cell ``i``: mu F_n g_i(a) and its rate (F_n' = Fd,
    a' = ad), g_i = (3/2a)(r - l) - (r^3 - l^3)/(2a^3), l = i dx, r = min((i + 1) dx, a)."""
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
def limits_inv(i, dx, mu, Fn, Fd, ar, ad, u):
    """``limits`` without a division, from the reciprocal radius ``u`` = 1/``ar`` [1/m] that
    the caller computes once for all cells: an inner cell (r = l + dx) has
    g_i = 1.5 dx u - 0.5 (r^3 - l^3) u^3, dg_i/da = -1.5 dx u^2 + 1.5 (r^3 - l^3) u^4; the edge
    cell (r = a), with x = (a - l)/a, g_i = x^2 (1.5 - 0.5 x), dg_i/da = 1.5 x (1 - x)(2 - x) u
    (the same g_i, free of the cancellation of its O(x) terms). Equal to ``limits`` to
    round-off; the partial-slip engine's form (the flexible rod keeps ``limits``)."""
    lo = i * dx
    if not (lo < ar and Fn > 0.0):
        return 0.0, 0.0
    if lo + dx > ar:  # the edge cell
        x = (ar - lo) * u
        g = x * x * (1.5 - 0.5 * x)
        dg = 1.5 * x * (1.0 - x) * (2.0 - x) * u
    else:
        r = lo + dx
        r3 = r * r * r - lo * lo * lo
        u2 = u * u
        g = max(0.0, u * (1.5 * dx - 0.5 * r3 * u2))  # >= 0 despite round-off
        dg = u2 * (1.5 * r3 * u2 - 1.5 * dx)
    return mu * Fn * g, mu * (Fd * g + Fn * dg * ad)


@njit(cache=True, inline="always", error_model="numpy")
def cell_switch(i, cm, sg, cp, limit, rate, fi, ar, ad, vs):
    """Event function of cell ``i`` (its limit ``limit`` [N], the limit's rate ``rate`` [N/s], its
    force ``fi`` [N]): STICK -> SLIP when |f| passes its limit (relative hysteresis SLIP_HYST),
    SLIP -> STICK when the limit outruns the stick trial (fires when it goes from <= 0 to > 0).
    Scalars, not arrays: no array views on the event functions' path."""
    if cm[i] == STICK:
        return abs(fi) - limit * (1.0 + SLIP_HYST) - cp[CP_FTOL]
    if cm[i] == SLIP and ar > i * cp[CP_DX]:
        ln = cell_length(i, ar, cp[CP_DX])
        trial = stick_rate(i, fi, ar, ad, vs, cp)
        return rate - sg[i] * trial - 2.0 * cp[CP_G1] * ln * cp[CP_VTOL]
    return -1.0


@njit_internal
def birth(i, y, o, cm, sg, cp, mu, estar, Fn, vn, vs, ar, ad):
    """Cell ``i`` (force y[o + i]) enters the contact unstressed. Near its inner end the limit
    grows like 1.5 mu F_n l^2/a^2 and the stick trial like G_1 |v_slip| l^2/a': it is born
    slipping (towards v_slip) iff G_1 |v_slip| a^2 > 1.5 mu F_n a' (at first touch, a = 0:
    G_1 |v_slip| > mu E* |v_n|), else sticking."""
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


@njit_internal
def to_slip(i, y, o, cm, sg, L):
    """Cell ``i`` starts to slip in the direction of its force, clamped to its limit."""
    cm[i] = SLIP
    sg[i] = 1.0 if y[o + i] > 0.0 else -1.0
    y[o + i] = sg[i] * L[i]


@njit_internal
def to_stick(i, y, o, cm, sg, L):
    """Cell ``i`` sticks with the force it had on its limit."""
    y[o + i] = sg[i] * L[i]
    cm[i] = STICK


@njit(cache=True, inline="always", error_model="numpy")
def boundary_time(cm, dx, ar, ad):
    """Time [s] until the contact radius ``ar`` (rate ``ad``) reaches the next cell boundary,
    where a cell is born or released and the cell lengths have a kink (inf when none lies
    ahead)."""
    nin = n_in(cm)
    if ad > 0.0 and nin < cm.shape[0]:
        return (nin * dx - ar) / ad
    if ad < 0.0 and nin > 1:
        return ((nin - 1) * dx - ar) / ad
    return math.inf


@njit(cache=True, inline="always", error_model="numpy")
def release(y, o, cm, nin):
    """The outermost of the ``nin`` cells in contact leaves it, at zero force."""
    cm[nin - 1] = OUT
    y[o + nin - 1] = 0.0


@njit(cache=True, error_model="numpy")
def apply_due(y, o, cm, sg, cp, L, Ld, f, mu, estar, Fn, vn, vs, ar, ad):
    """Apply the first birth or release already due (the contact radius ``ar`` beyond a cell
    boundary by 1e-9 of a cell), else every stick/slip switch already due (the tests of
    ``cell_switch`` without their tolerances' sign change); False when none is. A restart
    calls it until it returns False: several cells can change mode within one step, and only
    the first event is located."""
    nin = n_in(cm)
    dx = cp[CP_DX]
    if nin < cm.shape[0] and ad > 0.0 and ar > nin * dx + 1e-9 * dx:
        birth(nin, y, o, cm, sg, cp, mu, estar, Fn, vn, vs, ar, ad)
        return True
    if nin > 1 and ad < 0.0 and ar < (nin - 1) * dx - 1e-9 * dx:
        release(y, o, cm, nin)
        return True
    changed = False
    for i in range(nin):
        if cm[i] == STICK:
            if abs(f[i]) > L[i] * (1.0 + SLIP_HYST) + cp[CP_FTOL]:
                to_slip(i, y, o, cm, sg, L)
                changed = True
        elif cm[i] == SLIP and ar > i * dx:
            ln = cell_length(i, ar, dx)
            trial = stick_rate(i, f[i], ar, ad, vs, cp)
            if Ld[i] - sg[i] * trial > 2.0 * cp[CP_G1] * ln * cp[CP_VTOL]:
                to_stick(i, y, o, cm, sg, L)
                changed = True
    return changed
