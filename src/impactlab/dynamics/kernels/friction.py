"""Friction kernels of the three tangential models (impulse ratio, Coulomb, Mindlin).

The kernels take named scalars (``stick_force``, ``coulomb_decide``, ``friction_switch``,
``mindlin_trial_rate``); the model-level functions (``tangential_force``, ``friction_event``,
...) read the constants tuple ``c`` and the mode tuple ``md``. Every branch on the friction
model of the core lives in this module. Forces in N, velocities in m/s, stiffness in N/m.
"""

from __future__ import annotations

import math

from numba import njit

from impactlab.contact.kernels import P_ESTAR
from impactlab.dynamics.kernels._jit import njit_internal, njit_no_refcount
from impactlab.dynamics.kernels.layout import (
    C_A0,
    C_B0,
    C_CONST,
    C_GS,
    C_I,
    C_M,
    C_MU,
    FR_COULOMB,
    FR_IMPULSE,
    FR_MINDLIN,
    M_COMP,
    M_FM,
    M_SIR,
    S_Q,
    S_SPIN,
)
from impactlab.dynamics.kernels.normal import dforce_ddelta, dradius_ddelta, radius

# --- kernels with named scalar arguments ----------------------------------------------------


#: The lever arms' product a b [m^2] below this fraction of a^2 + b^2 is round-off: cos(pi/2)
#: is 6e-17, not 0, so a vertical rod's a is about 1e-17 m; impulse_ratio then applies no
#: tangential force, as for a sphere, instead of one of arbitrary sign.
LEVER_ROUNDOFF = 1e-12


@njit(cache=True, inline="always", error_model="numpy")
def slip_roundoff(vt0, vn0, spin, a0, b0):
    """Whether the slip velocity ``vt0`` [m/s] at first touch is round-off of its terms: a body
    that arrives rolling (vx = -spin R) has ``vt0`` of order 1e-16 m/s, not 0, whose sign is
    arbitrary; below ``LEVER_ROUNDOFF`` of |vn0| + |spin| (a0^2 + b0^2)^(1/2) it counts as 0."""
    scale = abs(vn0) + abs(spin) * math.sqrt(a0 * a0 + b0 * b0)
    return abs(vt0) <= LEVER_ROUNDOFF * scale


@njit(cache=True, inline="always", error_model="numpy")
def stick_force(spin, fn, a, b, mass, inertia, frozen):
    """Tangential force that keeps the contact point from slipping (d v_slip/dt = 0) [N].

    spin [rad/s]; fn normal force [N]; a, b lever arms [m]; mass [kg]; inertia [kg m^2];
    frozen: non-zero with constant-angle kinematics (no centripetal term)."""
    cent = 0.0 if frozen != 0.0 else a * spin * spin
    inv_i = 1.0 / inertia
    return (fn * a * b * inv_i - cent) / (1.0 / mass + b * b * inv_i)


@njit(cache=True, error_model="numpy")
def coulomb_decide(mu, spin, fn, a, b, mass, inertia, frozen):
    """Friction mode when the contact point has v_slip = 0: 0 stick, else the slip direction."""
    Fs = stick_force(spin, fn, a, b, mass, inertia, frozen)
    if fn > 0.0 or Fs != 0.0:
        if abs(Fs) <= mu * fn:
            return 0.0
        return -1.0 if Fs > 0.0 else 1.0
    # F_n = 0 and no centripetal term: the ratio F_t*/F_n as F_n -> 0+
    ratio = a * b / inertia / (1.0 / mass + b * b / inertia)
    if abs(ratio) <= mu:
        return 0.0
    return -1.0 if ratio > 0.0 else 1.0


@njit_internal
def friction_switch(
    fric, mode, compressing, spin, q, fn, ft, v_slip, a, b, kt, mu, mass, inertia, frozen
):
    """New (friction mode, tangential state q) when the friction event fires."""
    if fric == FR_COULOMB:
        if mode != 0.0:  # slip velocity reached zero: stick, or slip the other way
            return coulomb_decide(mu, spin, fn, a, b, mass, inertia, frozen), q
        return (-1.0 if ft > 0.0 else 1.0), q  # stick broken: slip against the needed force
    if fric == FR_MINDLIN:
        if mode == 0.0:  # the elastic force reached the cap: gross slip
            if ft != 0.0:
                return (-1.0 if ft > 0.0 else 1.0), q
            return (1.0 if v_slip >= 0.0 else -1.0), q
        # the elastic trial points back inside the cone: stick with the capped force
        if compressing != 0.0:
            return 0.0, ft
        return 0.0, (-ft / kt if kt > 0.0 else 0.0)
    return mode, q


@njit_no_refcount
def mindlin_trial_rate(law, p, md, delta, fn, ft, vn, v_slip, kt, gstar):
    """(dF_t/dt of the elastic trial, dF_n/dt) for the Mindlin slip -> stick test; gstar: G*
    [Pa]. Called, not inlined: only a slipping Mindlin contact needs it, and its four
    difference quotients would be compiled into every copy of the event functions."""
    ddelta = -vn
    dFn = dforce_ddelta(law, p, md, delta, fn) * ddelta
    if md[M_COMP] != 0.0:
        return -kt * v_slip, dFn
    if kt <= 0.0:
        return 0.0, dFn
    dkt = 8.0 * gstar * dradius_ddelta(law, p, md, delta) * ddelta
    return dkt * ft / kt - kt * v_slip, dFn


# --- the models -------------------------------------------------------------------------------


@njit(cache=True, inline="always", error_model="numpy")
def tangential_force(law, p, fric, c, md, delta, fn, spin, a, b, q):
    """(F_t [N], k_t [N/m]) of the friction model in mode ``md`` (k_t: Mindlin only)."""
    Ft = 0.0
    kt = 0.0
    if fric == FR_IMPULSE:
        Ft = md[M_SIR] * c[C_MU] * fn
    elif fric == FR_COULOMB:
        fm = md[M_FM]
        if fm == 0.0:
            Ft = stick_force(spin, fn, a, b, c[C_M], c[C_I], c[C_CONST])
        else:
            Ft = -fm * c[C_MU] * fn
    elif fric == FR_MINDLIN:
        kt = 8.0 * c[C_GS] * radius(law, p, md, delta)
        fm = md[M_FM]
        if fm != 0.0:
            Ft = -fm * c[C_MU] * fn
        elif md[M_COMP] != 0.0:
            Ft = q
        else:
            Ft = -kt * q
    return Ft, kt


@njit(cache=True, inline="always", error_model="numpy")
def tangential_state_rate(fric, md, kt, v_slip):
    """dq/dt of the Mindlin tangential state (0 in gross slip and for the other models)."""
    dq = 0.0
    if fric == FR_MINDLIN and md[M_FM] == 0.0:
        dq = -kt * v_slip if md[M_COMP] != 0.0 else v_slip
    return dq


@njit(cache=True, inline="always", error_model="numpy")
def friction_event(law, p, fric, c, md, delta, fn, ft, vn, v_slip, kt, q):
    """Event function of the stick/slip switch (fires when it goes from <= 0 to > 0)."""
    fm = md[M_FM]
    mu = c[C_MU]
    g_fr = -1.0
    if fric == FR_COULOMB:
        g_fr = -fm * v_slip if fm != 0.0 else abs(ft) - mu * fn
    elif fric == FR_MINDLIN:
        if fm == 0.0:
            if md[M_COMP] != 0.0:
                g_fr = abs(ft) - mu * fn
            else:
                # displacement form: |xi| against its limit mu F_n / k_t, which vanishes at
                # separation (F_n ~ d^1.5, k_t ~ d^0.5): the crossing cannot hide behind the end
                g_fr = abs(q) - (mu * fn / kt if kt > 0.0 else 0.0)
        else:
            dft, dfn = mindlin_trial_rate(law, p, md, delta, fn, ft, vn, v_slip, kt, c[C_GS])
            g_fr = fm * dft + mu * dfn
    return g_fr


@njit(cache=True, inline="always", error_model="numpy")
def frictional(fric):
    """True for the models with a stick state (Coulomb, Mindlin)."""
    return fric == FR_COULOMB or fric == FR_MINDLIN


@njit(cache=True, inline="always", error_model="numpy")
def sticking(fric, md):
    """True in stick (Coulomb) or without gross slip (Mindlin)."""
    return (fric == FR_COULOMB or fric == FR_MINDLIN) and md[M_FM] == 0.0


@njit_internal
def initial_friction_mode(fric, p, c, spin, vn0, vt0):
    """(friction mode, impulse-ratio sign) at first touch; vn0, vt0: normal and slip velocity
    of the contact point [m/s]."""
    fm = 0.0
    sir = 0.0
    mu = c[C_MU]
    if fric == FR_IMPULSE:
        if not slip_roundoff(vt0, vn0, spin, c[C_A0], c[C_B0]):
            sir = -1.0 if vt0 > 0.0 else 1.0
        else:  # the sign of a b; zero within round-off (a vertical rod: a = (L/2) cos(pi/2))
            ab = c[C_A0] * c[C_B0]
            tol = LEVER_ROUNDOFF * (c[C_A0] * c[C_A0] + c[C_B0] * c[C_B0])
            sir = 1.0 if ab > tol else (-1.0 if ab < -tol else 0.0)
    elif fric == FR_COULOMB:
        if vt0 != 0.0:
            fm = 1.0 if vt0 > 0.0 else -1.0
        else:
            fm = coulomb_decide(mu, spin, 0.0, c[C_A0], c[C_B0], c[C_M], c[C_I], c[C_CONST])
    elif (
        fric == FR_MINDLIN and vt0 != 0.0 and 4.0 * c[C_GS] * abs(vt0) > mu * p[P_ESTAR] * abs(vn0)
    ):
        # At first touch the contact is Hertzian: |F_t| / (mu F_n) -> 4 G* |v_t| / (mu E* |v_n|).
        fm = 1.0 if vt0 > 0.0 else -1.0
    return fm, sir


@njit(cache=True, error_model="numpy")
def switch_friction(fric, c, md, y, evq):
    """``friction_switch`` at state ``y`` with the evaluated quantities ``evq``."""
    _delta, a, b, Fn, Ft, _vn, vs, kt = evq
    return friction_switch(
        fric,
        md[M_FM],
        md[M_COMP],
        y[S_SPIN],
        y[S_Q],
        Fn,
        Ft,
        vs,
        a,
        b,
        kt,
        c[C_MU],
        c[C_M],
        c[C_I],
        c[C_CONST],
    )


@njit(cache=True, inline="always", error_model="numpy")
def mindlin_state_at_turn(law, p, c, md, delta, ft, kt):
    """Elastic displacement that replaces the force ``ft`` as the Mindlin state when the
    contact starts to shrink (mode ``md`` already on the unloading branch). Where the law's
    contact radius jumps at the turning point, keep F if k_t grows (the new annulus carries no
    traction) and keep xi if it shrinks: never creates energy."""
    ktn = 8.0 * c[C_GS] * radius(law, p, md, delta)
    kref = ktn if ktn >= kt else kt
    return -ft / kref if kref > 0.0 else 0.0


@njit(cache=True, inline="always", error_model="numpy")
def mindlin_state_at_reload(law, p, c, md, delta, ft, kt):
    """Mindlin force state when reloading returns to the loading curve (mode ``md`` already on
    it): scaled down if k_t drops, kept otherwise."""
    ktn = 8.0 * c[C_GS] * radius(law, p, md, delta)
    return ft if (ktn >= kt or kt <= 0.0) else ft * ktn / kt
