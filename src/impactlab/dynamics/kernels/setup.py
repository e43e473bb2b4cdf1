"""Initialisation of one impact: input checks, the constants tuple, the mode at first touch and
the scales of the error control."""

from __future__ import annotations

import math

from numba import njit

from impactlab.bodies.layout import (
    BP_GSTAR,
    BP_HALF_LENGTH,
    BP_INERTIA,
    BP_KIND,
    BP_MASS,
    BP_RADIUS,
    KIND_ROD,
    KIND_SPHERE,
    NB,
)
from impactlab.contact.kernels import (
    CURVE_LENGTH,
    CURVE_MAGIC,
    NPARAM,
    P_DLIM,
    P_DSW,
    P_ESTAR,
    P_R,
    TABLE_HEADER,
    TABLE_MAGIC,
)
from impactlab.dynamics.kernels._jit import njit_internal
from impactlab.dynamics.kernels.friction import initial_friction_mode
from impactlab.dynamics.kernels.inputs import IN_ANGLE, IN_OK, input_problem
from impactlab.dynamics.kernels.layout import (
    C_A0,
    C_D,
    C_I,
    C_M,
    C_R,
    FR_IMPULSE,
    FR_MINDLIN,
    S_PHI,
    S_Q,
    S_SPIN,
    S_VX,
    S_VY,
    S_WORK,
    S_X,
    S_Y,
)
from impactlab.dynamics.kernels.status import (
    ST_BAD_ANGLE,
    ST_BAD_FRICTION,
    ST_BAD_INPUT,
    ST_OK,
    ST_RADIUS_MISMATCH,
)


@njit_internal
def check_inputs(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, rtol):
    """ST_OK, or the status code of the first invalid input (see ``impact``)."""
    for i in range(NB):
        if i == BP_GSTAR:
            continue
        if not math.isfinite(bp[i]):
            return ST_BAD_INPUT
    kind = bp[BP_KIND]
    if kind != KIND_ROD and kind != KIND_SPHERE:
        return ST_BAD_INPUT
    if not (
        bp[BP_RADIUS] > 0.0
        and bp[BP_MASS] > 0.0
        and bp[BP_INERTIA] > 0.0
        and bp[BP_HALF_LENGTH] >= 0.0
    ):
        return ST_BAD_INPUT
    if p.shape[0] != NPARAM and not (
        (p.shape[0] > NPARAM + TABLE_HEADER and p[NPARAM] == TABLE_MAGIC)
        or (p.shape[0] == NPARAM + CURVE_LENGTH and p[NPARAM] == CURVE_MAGIC)
    ):
        return ST_BAD_INPUT
    if not (
        p[P_ESTAR] > 0.0 and math.isfinite(p[P_ESTAR]) and p[P_R] > 0.0 and math.isfinite(p[P_R])
    ):
        return ST_BAD_INPUT
    if not (p[P_DLIM] > 0.0):  # inf allowed, NaN not
        return ST_BAD_INPUT
    if abs(p[P_R] - bp[BP_RADIUS]) > 1e-12 * bp[BP_RADIUS]:
        return ST_RADIUS_MISMATCH
    if not math.isfinite(th0):  # a sphere's is not read, but must be a number
        return ST_BAD_INPUT
    reach = bp[BP_HALF_LENGTH] + bp[BP_RADIUS]  # the farthest point of contact from C
    problem = input_problem(kind == KIND_ROD, th0, vx0, vy0, w0, reach, mu, g, rtol)
    if problem != IN_OK and problem != IN_ANGLE:
        return ST_BAD_INPUT
    if fric < FR_IMPULSE or fric > FR_MINDLIN:
        return ST_BAD_FRICTION
    if fric == FR_MINDLIN and mu > 0.0 and not (bp[BP_GSTAR] > 0.0 and math.isfinite(bp[BP_GSTAR])):
        return ST_BAD_FRICTION
    if problem == IN_ANGLE:
        return ST_BAD_ANGLE
    return ST_OK


@njit(cache=True, error_model="numpy")
def constants(p, bp, th0, mu, g, const_angle):
    """The constants tuple ``c`` (``C_*``) of an impact; a sphere is a rod with L/2 = 0 at
    pi/2."""
    kind = bp[BP_KIND]
    d = bp[BP_HALF_LENGTH] if kind == KIND_ROD else 0.0
    th = th0 if kind == KIND_ROD else 0.5 * math.pi
    R = bp[BP_RADIUS]
    m = bp[BP_MASS]
    inertia = bp[BP_INERTIA]
    s0 = math.sin(th)
    c0 = math.cos(th)
    a0 = d * c0
    b0 = d * s0 + R
    dsw = p[P_DSW] if p[P_DSW] > 0.0 else math.inf  # NaN or <= 0: no switch event
    return (
        d,
        R,
        m,
        inertia,
        g,
        th,
        s0,
        c0,
        mu,
        bp[BP_GSTAR],
        1.0 if const_angle else 0.0,
        a0,
        b0,
        p[P_DLIM],
        dsw,
        1.0 / m,
        1.0 / inertia,
    )


@njit_internal
def initial_mode(fric, p, c, w0, vn0, vt0):
    """The mode tuple ``md`` (``M_*``) at first touch: loading curve, compressing, the friction
    mode of the initial slip."""
    fm, sir = initial_friction_mode(fric, p, c, w0, vn0, vt0)
    #     phase, delta_m, delta_r, R_r, friction mode, compressing, impulse-ratio sign, a factor
    return (0.0, 0.0, 0.0, c[C_R], fm, 1.0, sir, 1.0)


@njit_internal
def error_scales(fric, p, c, vn0, sc):
    """(tstar, dstar, fscale): the Hertz time and interference scales t* [s], delta* [m] and
    the tangential force scale [N]; the absolute scales of the state (error control) into
    ``sc`` (length NS)."""
    d = c[C_D]
    R = c[C_R]
    m = c[C_M]
    inertia = c[C_I]
    a0 = c[C_A0]
    lever = d + R
    vstar = abs(vn0)  # velocity scale of the error control (e is relative to v_n0)
    meff = 1.0 / (1.0 / m + a0 * a0 / inertia)
    dstar = (15.0 * meff * vn0 * vn0 / (16.0 * p[P_ESTAR] * math.sqrt(R))) ** 0.4
    tstar = dstar / abs(vn0)
    fscale = meff * vstar / tstar
    sc[S_X] = dstar
    sc[S_Y] = dstar
    sc[S_PHI] = dstar / lever
    sc[S_VX] = vstar
    sc[S_VY] = vstar
    sc[S_SPIN] = vstar / lever
    sc[S_WORK] = meff * vn0 * vn0  # normal work scale
    sc[S_Q] = fscale if fric == FR_MINDLIN else 1e300
    return tstar, dstar, fscale
