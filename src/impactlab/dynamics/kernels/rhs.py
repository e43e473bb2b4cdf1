"""The right-hand side of the equations of motion, the event functions and the total energy.

``evaluate`` computes the contact quantities once; ``derivative`` and ``events_from`` use them,
so that ``rhs_events`` (the last Dormand-Prince stage, FSAL) needs one force evaluation.
State and units: ``impactlab.dynamics.kernels.layout``.
"""

from __future__ import annotations

from numba import njit

from impactlab.contact.kernels import residual_depth
from impactlab.dynamics.kernels._jit import njit_internal, njit_llvm_inline, njit_no_refcount
from impactlab.dynamics.kernels.friction import (
    friction_event,
    tangential_force,
    tangential_state_rate,
)
from impactlab.dynamics.kernels.layout import (
    C_DLIM,
    C_DSW,
    C_G,
    C_I,
    C_II,
    C_IM,
    C_M,
    EV_FRIC,
    EV_LIMIT,
    EV_RELOAD,
    EV_SEP,
    EV_SWITCH,
    EV_VN,
    FR_MINDLIN,
    M_COMP,
    M_DM,
    M_DR,
    M_PHASE,
    S_Q,
    S_SPIN,
    S_VX,
    S_VY,
    S_Y,
)
from impactlab.dynamics.kernels.normal import geometry, normal_force


@njit_llvm_inline
def geometry_llvm(c, y):
    """``normal.geometry`` compiled once and inlined by LLVM (``kernels._jit``): the force
    evaluations of the time step (``evaluate``) and of the w-step (``approach._rhs_w``) share
    it, so that numba compiles it once for both."""
    return geometry(c, y)


@njit_llvm_inline
def normal_force_llvm(law, p, md, delta):
    """``normal.normal_force`` compiled once and inlined by LLVM (as ``geometry_llvm``)."""
    return normal_force(law, p, md, delta)


@njit_llvm_inline
def tangential_force_llvm(law, p, fric, c, md, delta, fn, spin, a, b, q):
    """``friction.tangential_force`` compiled once and inlined by LLVM (as ``geometry_llvm``)."""
    return tangential_force(law, p, fric, c, md, delta, fn, spin, a, b, q)


@njit(cache=True, inline="always", error_model="numpy")
def evaluate(law, p, fric, c, md, y):
    """(delta, a, b, F_n, F_t, v_n, v_slip, k_t) at state ``y`` in mode ``md``."""
    delta, a, b, _xs, _sl = geometry_llvm(c, y)
    Fn = normal_force_llvm(law, p, md, delta)
    w = y[S_SPIN]
    vn = y[S_VY] - w * a
    vs = y[S_VX] + w * b
    Ft, kt = tangential_force_llvm(law, p, fric, c, md, delta, Fn, w, a, b, y[S_Q])
    return delta, a, b, Fn, Ft, vn, vs, kt


@njit(cache=True, inline="always", error_model="numpy")
def derivative(fric, c, md, y, ev):
    """Time derivative of the state ``y`` from the evaluated quantities ``ev``, as a tuple."""
    _delta, a, b, Fn, Ft, vn, vs, kt = ev
    inv_m = c[C_IM]
    dq = tangential_state_rate(fric, md, kt, vs)
    return (
        y[S_VX],
        y[S_VY],
        y[S_SPIN],
        Ft * inv_m,
        Fn * inv_m - c[C_G],
        (b * Ft - a * Fn) * c[C_II],
        Fn * vn,
        dq,
    )


@njit(cache=True, inline="always", error_model="numpy")
def rhs(law, p, fric, c, md, y):
    """Time derivative of the state ``y`` (a tuple), as a tuple."""
    return derivative(fric, c, md, y, evaluate(law, p, fric, c, md, y))


@njit(cache=True, inline="always", error_model="numpy")
def events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, q):
    """Event functions (a tuple, index EV_*) from the evaluated contact quantities, oriented so
    that an event fires when g goes from <= 0 to > 0."""
    comp = md[M_COMP] != 0.0
    g_vn = vn if comp else -vn
    if md[M_PHASE] == 0.0:
        g_rel = -1.0
        g_sep = -1.0
        g_lim = delta - c[C_DLIM]
        g_sw = delta - c[C_DSW]
    else:
        g_rel = delta - md[M_DM] if comp else -1.0
        g_sep = -1.0 if comp else md[M_DR] - delta
        g_lim = -1.0
        g_sw = -1.0
    g_fr = friction_event(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, q)
    return (g_vn, g_rel, g_sep, g_lim, g_fr, g_sw)


@njit(cache=True, inline="always", error_model="numpy")
def rhs_events(law, p, fric, c, md, y):
    """(derivative tuple, event tuple, evaluated quantities) at ``y`` with one force evaluation."""
    ev = evaluate(law, p, fric, c, md, y)
    delta, _a, _b, Fn, Ft, vn, vs, kt = ev
    der = derivative(fric, c, md, y, ev)
    return der, events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, y[S_Q]), ev


@njit_llvm_inline
def evaluate_stage(law, p, fric, c, md, y):
    """``evaluate`` for the Dormand-Prince stage loop of ``integrator.dp_step`` and for
    ``evaluate_cold``: compiled once by numba and inlined into both by LLVM
    (``kernels._jit.njit_llvm_inline``)."""
    return evaluate(law, p, fric, c, md, y)


@njit_no_refcount
def evaluate_cold(law, p, fric, c, md, y):
    """``evaluate`` as a call, for the callers off the step loop (see ``rhs_events_cold``):
    ``evaluate_stage`` inlined by LLVM, so that numba compiles the force evaluation once."""
    return evaluate_stage(law, p, fric, c, md, y)


@njit_internal
def events_cold(law, p, fric, c, md, evq, q):
    """Event tuple from the evaluated quantities ``evq`` (``events_from``), compiled once and
    called, for the callers off the time step's loop (``rhs_events_cold``, the w-steps of
    ``approach``, which read their events at five places, once per step)."""
    delta, _a, _b, Fn, Ft, vn, vs, kt = evq
    return events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, q)


@njit_no_refcount
def rhs_events_cold(law, p, fric, c, md, y):
    """``rhs_events`` compiled once as a function of its own, for the callers off the step loop
    (first touch, restarts, the ends of the contact): each copy of the force evaluation that
    numba inlines costs seconds of compilation. The force evaluation here is a call of
    ``evaluate_cold`` (not a copy of its own): the same numbers, about 2 s less to compile."""
    ev = evaluate_cold(law, p, fric, c, md, y)
    der = derivative(fric, c, md, y, ev)
    return der, events_cold(law, p, fric, c, md, ev, y[S_Q]), ev


@njit(cache=True, error_model="numpy")
def event_value(ev, law, p, fric, c, md, y):
    """Event function ``ev`` alone (as in ``events_from``): the kinematic events need no
    force evaluation."""
    if ev == EV_FRIC:
        delta, _a, _b, Fn, Ft, vn, vs, kt = evaluate_cold(law, p, fric, c, md, y)
        return friction_event(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, y[S_Q])
    delta, a, _b, _xs, _sl = geometry(c, y)
    comp = md[M_COMP] != 0.0
    if ev == EV_VN:
        vn = y[S_VY] - y[S_SPIN] * a
        return vn if comp else -vn
    if md[M_PHASE] == 0.0:
        if ev == EV_LIMIT:
            return delta - c[C_DLIM]
        if ev == EV_SWITCH:
            return delta - c[C_DSW]
        return -1.0
    if ev == EV_RELOAD:
        return delta - md[M_DM] if comp else -1.0
    if ev == EV_SEP:
        return -1.0 if comp else md[M_DR] - delta
    return -1.0


@njit(cache=True, error_model="numpy")
def energy(law, p, fric, c, md, y, Fn, Ft, delta, kt):
    """Total energy: kinetic + gravity potential (from first touch) + stored elastic [J]."""
    m = c[C_M]
    E = 0.5 * m * (y[S_VX] ** 2 + y[S_VY] ** 2) + 0.5 * c[C_I] * y[S_SPIN] ** 2
    E += m * c[C_G] * y[S_Y]
    if Fn > 0.0:
        dr = residual_depth(law, p, delta, Fn) if md[M_PHASE] == 0.0 else md[M_DR]
        E += 0.4 * Fn * (delta - dr)  # int_{dr}^{delta} of the Hertzian unloading curve
    if fric == FR_MINDLIN and kt > 0.0:
        E += 0.5 * Ft * Ft / kt
    return E
