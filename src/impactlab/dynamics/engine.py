"""The compiled impact engine: planar rigid body (rod or sphere) on a flat, one contact.

Everything here runs in numba ``nopython`` mode: the equations of motion, the normal contact
history (loading / unloading / reloading), the three friction models and all phase switches,
integrated by an embedded Dormand-Prince 5(4) pair with its 4th-order dense output
(Dormand & Prince, J. Comput. Appl. Math. 6 (1980) 19, doi:10.1016/0771-050X(80)90013-3;
dense output: Shampine, Math. Comp. 46 (1986) 135, doi:10.1090/S0025-5718-1986-0815836-3) and
event location on the dense output (Illinois regula falsi). The equations, conventions and
event logic are documented in ``docs/engine/index.md``.

State vector (SI): ``[dx, dy, phi, vx, vy, omega, W, q]`` with dx, dy the displacement of the
centre of mass from its position at first touch, phi the rotation (counter-clockwise), W the
work of the normal force on the body (W = int F_n v_n dt) and q the tangential state of the
Mindlin model (the tangential force while the contact grows, the elastic tangential displacement
while it shrinks).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit, prange

from impactlab.bodies import (
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
from impactlab.contact import kernels as _k
from impactlab.contact.kernels import (
    NPARAM,
    P_DLIM,
    P_DSW,
    P_ESTAR,
    P_R,
    loading_force,
    residual_depth,
    unloading_force,
    unloading_radius,
)
from impactlab.contact.kernels import contact_radius as _contact_radius

# --- friction ids (public ones in impactlab.friction) ----------------------------------------
FR_NONE = -1  # internal: mu == 0
FR_IMPULSE = 0
FR_COULOMB = 1
FR_MINDLIN = 2

# --- state ------------------------------------------------------------------------------------
NS = 8
S_X = 0
S_Y = 1
S_PHI = 2
S_VX = 3
S_VY = 4
S_W = 5
S_WORK = 6
S_Q = 7

# --- constants vector --------------------------------------------------------------------------
C_D = 0  # L/2 [m]
C_R = 1  # tip radius [m]
C_M = 2  # mass [kg]
C_I = 3  # inertia [kg m^2]
C_G = 4  # gravity [m/s^2]
C_TH0 = 5  # initial angle [rad]
C_S0 = 6  # sin th0
C_C0 = 7  # cos th0
C_MU = 8  # friction coefficient
C_GS = 9  # G* [Pa]
C_CONST = 10  # 1: constant-angle kinematics
C_A0 = 11  # a at th0
C_B0 = 12  # b at th0
C_DLIM = 13  # law validity limit [m]
C_DSW = 14  # interference where the loading curve leaves the elastic curve [m] (inf: none)
NC = 15

# --- mode vector ---------------------------------------------------------------------------------
M_PHASE = 0  # 0 loading curve, 1 unloading/reloading curve
M_DM = 1  # delta_m of the current unloading branch [m]
M_DR = 2  # delta_r [m]
M_RR = 3  # R_r [m]
M_FM = 4  # friction mode: 0 stick (coulomb) / elastic (mindlin); +-1 slip direction
M_COMP = 5  # 1 while the contact point approaches the flat (delta increasing)
M_SIR = 6  # impulse_ratio: F_t = M_SIR * mu * F_n
M_AF = 7  # unloading contact-radius factor: continuity of k_t at the turning point (Mindlin)
NM = 8

# --- events -----------------------------------------------------------------------------------
EV_VN = 0
EV_RELOAD = 1
EV_SEP = 2
EV_LIMIT = 3
EV_FRIC = 4
EV_SWITCH = 5  # the loading curve leaves the elastic curve (p[P_DSW]): restart the integration
NEV = 6

# --- status codes -------------------------------------------------------------------------------
ST_OK = 0
ST_LAW_LIMIT = 1
ST_NOT_APPROACHING = 2
ST_NO_SEPARATION = 3
ST_BAD_INPUT = 4
ST_NAN = 5
ST_STEP_UNDERFLOW = 6
ST_BAD_ANGLE = 7
ST_RADIUS_MISMATCH = 8
ST_TOO_MANY_EVENTS = 9
ST_BAD_FRICTION = 10

STATUS_MESSAGES: dict[int, str] = {
    ST_OK: "ok",
    ST_LAW_LIMIT: "the interference exceeded the contact law's validity range (delta > P_DLIM)",
    ST_NOT_APPROACHING: "the contact point does not approach the flat (normal velocity >= 0)",
    ST_NO_SEPARATION: "no separation within the step limit",
    ST_BAD_INPUT: "invalid input: a body, law, initial-state, mu or tolerance value is not finite "
    "or out of range",
    ST_NAN: "the contact law returned a non-finite value (law not available or outside its "
    "domain)",
    ST_STEP_UNDERFLOW: "step-size underflow: the integrator could not meet the tolerance",
    ST_BAD_ANGLE: "angle outside (0, pi/2] radians",
    ST_RADIUS_MISMATCH: "the law's radius P_R differs from the body's tip radius",
    ST_TOO_MANY_EVENTS: "too many phase or stick/slip switches (chattering)",
    ST_BAD_FRICTION: "unknown friction id, or the Mindlin model without G* in the body vector",
}

# --- regimes ----------------------------------------------------------------------------------
REGIME_FRICTIONLESS = 0
REGIME_SLIP = 1
REGIME_STICK = 2
REGIME_REVERSAL = 3
REGIME_NAMES: dict[int, str] = {
    REGIME_FRICTIONLESS: "frictionless",
    REGIME_SLIP: "slip",
    REGIME_STICK: "stick",
    REGIME_REVERSAL: "reversal",
}

# --- outputs ------------------------------------------------------------------------------------
OUTPUT_FIELDS: tuple[str, ...] = (
    "e",  # normal (kinematic) COR at the contact point, -v_n,out / v_n,in
    "e_energy",  # energetic COR (Stronge), sqrt(-W_restitution / W_compression)
    "vx_out",  # [m/s]
    "vy_out",  # [m/s]
    "spin_out",  # [rad/s]
    "delta_max",  # [m]
    "delta_p",  # residual depth of the unloading branch at separation [m]
    "sliding_length",  # int v_slip dt [m]
    "contact_travel",  # displacement of the contact point along the flat [m]
    "duration",  # [s]
    "mean_force",  # normal impulse / duration [N]
    "max_force",  # [N]
    "normal_impulse",  # [N s]
    "tangential_impulse",  # [N s]
    "energy_dissipated",  # [J]
    "stick_time",  # [s]
    "regime",  # code, REGIME_NAMES
    "vn_in",  # normal velocity of the contact point at first touch [m/s]
    "vt_in",  # slip velocity of the contact point at first touch [m/s]
    "vn_out",  # at separation [m/s]
    "vt_out",  # at separation [m/s]
    "angle_out",  # rod angle at separation [rad]
    "t_max",  # time of the maximum interference [s]
    "n_steps",  # accepted + rejected integration steps
    "energy_rise",  # largest rise of the total energy / initial kinetic energy (diagnostics)
    "friction_excess",  # largest (|F_t| - mu F_n) / max_force (diagnostics, coulomb/mindlin)
)
N_OUT = len(OUTPUT_FIELDS)
O = {name: i for i, name in enumerate(OUTPUT_FIELDS)}
O_E = O["e"]
O_EE = O["e_energy"]
O_VX = O["vx_out"]
O_VY = O["vy_out"]
O_W = O["spin_out"]
O_DMAX = O["delta_max"]
O_DP = O["delta_p"]
O_SL = O["sliding_length"]
O_CT = O["contact_travel"]
O_T = O["duration"]
O_FMEAN = O["mean_force"]
O_FMAX = O["max_force"]
O_PN = O["normal_impulse"]
O_PT = O["tangential_impulse"]
O_ED = O["energy_dissipated"]
O_STICK = O["stick_time"]
O_REG = O["regime"]
O_VNIN = O["vn_in"]
O_VTIN = O["vt_in"]
O_VNOUT = O["vn_out"]
O_VTOUT = O["vt_out"]
O_ANG = O["angle_out"]
O_TMAX = O["t_max"]
O_NST = O["n_steps"]
O_ERISE = O["energy_rise"]
O_FEX = O["friction_excess"]

# --- history columns ------------------------------------------------------------------------------
HISTORY_FIELDS: tuple[str, ...] = (
    "t",  # [s]
    "penetration",  # delta [m]
    "normal_force",  # F_n [N]
    "tangential_force",  # F_t [N] (on the body, +x)
    "contact_x",  # contact point position along the flat, from the first contact point [m]
    "slip_velocity",  # v_slip of the body point at the contact [m/s]
    "x",  # centre of mass x (origin: first contact point) [m]
    "y",  # centre of mass y [m]
    "phi",  # rotation since first touch (counter-clockwise) [rad]
    "vx",  # [m/s]
    "vy",  # [m/s]
    "omega",  # [rad/s]
    "normal_velocity",  # v_n of the contact point [m/s]
    "phase",  # 0 loading curve, 1 unloading/reloading curve
    "stick",  # 1 stick (coulomb) / no gross slip (mindlin), 0 slip
    "energy",  # kinetic + potential (from first touch) + stored elastic [J]
)
NH = len(HISTORY_FIELDS)

DEFAULT_RTOL = 3e-8
MAX_STEPS = 200_000
MAX_EVENTS = 20_000
HISTORY_SUBSTEPS = 4

# --- Dormand-Prince 5(4) tableau (Dormand & Prince 1980) and Shampine's dense output -------------
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = (9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                           -5103.0 / 18656.0)
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
E1, E3, E4, E5, E6, E7 = (-71.0 / 57600.0, 71.0 / 16695.0, -71.0 / 1920.0, 17253.0 / 339200.0,
                          -22.0 / 525.0, 1.0 / 40.0)
#: Dormand-Prince stage coefficients: row s holds a_{s,j} (row 6 = the 5th-order weights b_j,
#: so stage 6 is evaluated at the new point: FSAL).
DP_A = np.array([
    [0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
    [A21, 0.0, 0.0, 0.0, 0.0, 0.0],
    [A31, A32, 0.0, 0.0, 0.0, 0.0],
    [A41, A42, A43, 0.0, 0.0, 0.0],
    [A51, A52, A53, A54, 0.0, 0.0],
    [A61, A62, A63, A64, A65, 0.0],
    [B1, 0.0, B3, B4, B5, B6],
])
DP_E = np.array([E1, 0.0, E3, E4, E5, E6, E7])
DENSE_P = np.array([
    [1.0, -8048581381.0 / 2820520608.0, 8663915743.0 / 2820520608.0,
     -12715105075.0 / 11282082432.0],
    [0.0, 0.0, 0.0, 0.0],
    [0.0, 131558114200.0 / 32700410799.0, -68118460800.0 / 10900136933.0,
     87487479700.0 / 32700410799.0],
    [0.0, -1754552775.0 / 470086768.0, 14199869525.0 / 1410260304.0,
     -10690763975.0 / 1880347072.0],
    [0.0, 127303824393.0 / 49829197408.0, -318862633887.0 / 49829197408.0,
     701980252875.0 / 199316789632.0],
    [0.0, -282668133.0 / 205662961.0, 2019193451.0 / 616988883.0,
     -1453857185.0 / 822651844.0],
    [0.0, 40617522.0 / 29380423.0, -110615467.0 / 29380423.0, 69997945.0 / 29380423.0],
])


# ================================================================================================
# physics
# ================================================================================================


@njit(cache=True, inline="always", error_model="numpy")
def _geometry(c, y):
    """(delta, a, b, contact travel, sliding length) for state ``y``.

    a, b: horizontal and vertical lever arms from C to the contact point (paper Eq. 1)."""
    d = c[C_D]
    phi = y[S_PHI]
    if c[C_CONST] != 0.0:
        a = c[C_A0]
        b = c[C_B0]
        delta = a * phi - y[S_Y]
        xs = y[S_X] + d * c[C_S0] * phi
        slide = y[S_X] + b * phi
    else:
        th = c[C_TH0] + phi
        s = math.sin(th)
        co = math.cos(th)
        a = d * co
        b = d * s + c[C_R]
        delta = d * (s - c[C_S0]) - y[S_Y]
        xs = y[S_X] - d * (co - c[C_C0])
        slide = xs + c[C_R] * phi
    return delta, a, b, xs, slide


@njit(cache=True, inline="always", error_model="numpy")
def _normal_force(law, p, md, delta):
    if md[M_PHASE] == 0.0:
        return loading_force(law, p, delta)
    return unloading_force(p[P_ESTAR], md[M_RR], md[M_DR], delta)


@njit(cache=True, inline="always", error_model="numpy")
def _radius(law, p, md, delta):
    """Contact radius [m] on the current branch. Phase 1: the unloading curve of
    ``contact_radius`` (also at delta = delta_m, where it would return the loading radius),
    scaled by md[M_AF] so that it starts from the loading radius at the turning point."""
    if md[M_PHASE] == 0.0:
        return _contact_radius(law, p, delta, delta, 0.0, p[P_R])
    return md[M_AF] * _contact_radius(law, p, delta, math.inf, md[M_DR], md[M_RR])


@njit(cache=True, inline="always", error_model="numpy")
def _dforce_ddelta(law, p, md, delta, Fn):
    """dF_n/d delta on the current branch [N/m]."""
    if md[M_PHASE] != 0.0:
        d = delta - md[M_DR]
        return 1.5 * Fn / d if d > 0.0 else 0.0
    if delta <= 0.0:
        return 0.0
    h = 1e-6 * delta
    return (loading_force(law, p, delta + h) - loading_force(law, p, delta - h)) / (2.0 * h)


@njit(cache=True, inline="always", error_model="numpy")
def _dradius_ddelta(law, p, md, delta):
    """d a / d delta on the current branch (central difference)."""
    base = 0.0 if md[M_PHASE] == 0.0 else md[M_DR]
    d = delta - base
    if d <= 0.0:
        return 0.0
    h = 1e-6 * d
    return (_radius(law, p, md, delta + h) - _radius(law, p, md, delta - h)) / (2.0 * h)


@njit(cache=True, inline="always", error_model="numpy")
def _stick_force(c, w, Fn, a, b):
    """Tangential force that keeps the contact point from slipping (d v_slip/dt = 0) [N]."""
    cent = 0.0 if c[C_CONST] != 0.0 else a * w * w
    inv_i = 1.0 / c[C_I]
    return (Fn * a * b * inv_i - cent) / (1.0 / c[C_M] + b * b * inv_i)


@njit(cache=True, inline="always", error_model="numpy")
def _evaluate(law, p, fric, c, md, y):
    """(delta, a, b, F_n, F_t, v_n, v_slip, k_t) at state ``y`` in mode ``md``."""
    delta, a, b, _xs, _sl = _geometry(c, y)
    Fn = _normal_force(law, p, md, delta)
    w = y[S_W]
    vn = y[S_VY] - w * a
    vs = y[S_VX] + w * b
    Ft = 0.0
    kt = 0.0
    if fric == FR_IMPULSE:
        Ft = md[M_SIR] * c[C_MU] * Fn
    elif fric == FR_COULOMB:
        fm = md[M_FM]
        if fm == 0.0:
            Ft = _stick_force(c, w, Fn, a, b)
        else:
            Ft = -fm * c[C_MU] * Fn
    elif fric == FR_MINDLIN:
        kt = 8.0 * c[C_GS] * _radius(law, p, md, delta)
        fm = md[M_FM]
        if fm != 0.0:
            Ft = -fm * c[C_MU] * Fn
        elif md[M_COMP] != 0.0:
            Ft = y[S_Q]
        else:
            Ft = -kt * y[S_Q]
    return delta, a, b, Fn, Ft, vn, vs, kt


@njit(cache=True, inline="always", error_model="numpy")
def _rhs(law, p, fric, c, md, y):
    """Time derivative of the state ``y`` (a tuple), as a tuple."""
    delta, a, b, Fn, Ft, vn, vs, kt = _evaluate(law, p, fric, c, md, y)
    m = c[C_M]
    dq = 0.0
    if fric == FR_MINDLIN and md[M_FM] == 0.0:
        dq = -kt * vs if md[M_COMP] != 0.0 else vs
    return (y[S_VX], y[S_VY], y[S_W], Ft / m, Fn / m - c[C_G], (b * Ft - a * Fn) / c[C_I],
            Fn * vn, dq)


@njit(cache=True, inline="always", error_model="numpy")
def _mindlin_trial_rate(law, p, c, md, delta, Fn, Ft, vn, vs, kt):
    """(dF_t/dt of the elastic trial, dF_n/dt) for the Mindlin slip -> stick test."""
    ddelta = -vn
    dFn = _dforce_ddelta(law, p, md, delta, Fn) * ddelta
    if md[M_COMP] != 0.0:
        return -kt * vs, dFn
    if kt <= 0.0:
        return 0.0, dFn
    dkt = 8.0 * c[C_GS] * _dradius_ddelta(law, p, md, delta) * ddelta
    return dkt * Ft / kt - kt * vs, dFn


@njit(cache=True, inline="always", error_model="numpy")
def _events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, q):
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
    fm = md[M_FM]
    mu = c[C_MU]
    g_fr = -1.0
    if fric == FR_COULOMB:
        if fm != 0.0:
            g_fr = -fm * vs
        else:
            g_fr = abs(Ft) - mu * Fn
    elif fric == FR_MINDLIN:
        if fm == 0.0:
            if md[M_COMP] != 0.0:
                g_fr = abs(Ft) - mu * Fn
            else:
                # displacement form: |xi| against its limit mu F_n / k_t, which vanishes at
                # separation (F_n ~ d^1.5, k_t ~ d^0.5): the crossing cannot hide behind the end
                g_fr = abs(q) - (mu * Fn / kt if kt > 0.0 else 0.0)
        else:
            dft, dfn = _mindlin_trial_rate(law, p, c, md, delta, Fn, Ft, vn, vs, kt)
            g_fr = fm * dft + mu * dfn
    return (g_vn, g_rel, g_sep, g_lim, g_fr, g_sw)


@njit(cache=True, inline="always", error_model="numpy")
def _events(law, p, fric, c, md, y):
    """Event functions at state ``y`` (see ``_events_from``)."""
    delta, a, b, Fn, Ft, vn, vs, kt = _evaluate(law, p, fric, c, md, y)
    return _events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, y[S_Q])


@njit(cache=True, inline="always", error_model="numpy")
def _rhs_events(law, p, fric, c, md, y):
    """(derivative tuple, event tuple, evaluated quantities) at ``y`` with one force evaluation."""
    ev = _evaluate(law, p, fric, c, md, y)
    delta, a, b, Fn, Ft, vn, vs, kt = ev
    m = c[C_M]
    dq = 0.0
    if fric == FR_MINDLIN and md[M_FM] == 0.0:
        dq = -kt * vs if md[M_COMP] != 0.0 else vs
    der = (y[S_VX], y[S_VY], y[S_W], Ft / m, Fn / m - c[C_G], (b * Ft - a * Fn) / c[C_I],
           Fn * vn, dq)
    return der, _events_from(law, p, fric, c, md, delta, Fn, Ft, vn, vs, kt, y[S_Q]), ev


@njit(cache=True, error_model="numpy")
def _energy(law, p, fric, c, md, y, Fn, Ft, delta, kt):
    """Total energy: kinetic + gravity potential (from first touch) + stored elastic [J]."""
    m = c[C_M]
    E = 0.5 * m * (y[S_VX] ** 2 + y[S_VY] ** 2) + 0.5 * c[C_I] * y[S_W] ** 2
    E += m * c[C_G] * y[S_Y]
    if Fn > 0.0:
        if md[M_PHASE] == 0.0:
            dr = residual_depth(law, p, delta, Fn)
        else:
            dr = md[M_DR]
        E += 0.4 * Fn * (delta - dr)  # int_{dr}^{delta} of the Hertzian unloading curve
    if fric == FR_MINDLIN and kt > 0.0:
        E += 0.5 * Ft * Ft / kt
    return E


@njit(cache=True, error_model="numpy")
def _coulomb_decide(c, w, Fn, a, b):
    """Friction mode when the contact point has v_slip = 0: 0 stick, else the slip direction."""
    mu = c[C_MU]
    Fs = _stick_force(c, w, Fn, a, b)
    if Fn > 0.0 or Fs != 0.0:
        if abs(Fs) <= mu * Fn:
            return 0.0
        return -1.0 if Fs > 0.0 else 1.0
    # F_n = 0 and no centripetal term: the ratio F_t*/F_n as F_n -> 0+
    ratio = a * b / c[C_I] / (1.0 / c[C_M] + b * b / c[C_I])
    if abs(ratio) <= mu:
        return 0.0
    return -1.0 if ratio > 0.0 else 1.0


@njit(cache=True, error_model="numpy")
def _friction_switch(fric, c, fm, comp, w, q, Fn, Ft, vs, a, b, kt):
    """New (friction mode, tangential state) when the friction event fires."""
    if fric == FR_COULOMB:
        if fm != 0.0:  # slip velocity reached zero: stick, or slip the other way
            return _coulomb_decide(c, w, Fn, a, b), q
        return (-1.0 if Ft > 0.0 else 1.0), q  # stick broken: slip against the needed force
    if fric == FR_MINDLIN:
        if fm == 0.0:  # the elastic force reached the cap: gross slip
            if Ft != 0.0:
                return (-1.0 if Ft > 0.0 else 1.0), q
            return (1.0 if vs >= 0.0 else -1.0), q
        # the elastic trial points back inside the cone: stick with the capped force
        if comp != 0.0:
            return 0.0, Ft
        return 0.0, (-Ft / kt if kt > 0.0 else 0.0)
    return fm, q


# ================================================================================================
# integrator helpers
# ================================================================================================


@njit(cache=True, error_model="numpy")
def _dense(y0, K, h, theta, Q, out):
    """Dense output at t0 + theta h (Q = K^T P, computed by the caller)."""
    t2 = theta * theta
    t3 = t2 * theta
    t4 = t3 * theta
    for i in range(NS):
        out[i] = y0[i] + h * (Q[i, 0] * theta + Q[i, 1] * t2 + Q[i, 2] * t3 + Q[i, 3] * t4)


@njit(cache=True, error_model="numpy")
def _dense_coeffs(K, Q):
    for i in range(NS):
        for j in range(4):
            s = 0.0
            for st in range(7):
                s += K[st, i] * DENSE_P[st, j]
            Q[i, j] = s


@njit(cache=True, inline="always", error_model="numpy")
def _tuple(y):
    return (y[0], y[1], y[2], y[3], y[4], y[5], y[6], y[7])


@njit(cache=True, error_model="numpy")
def _event_value(ev, law, p, fric, c, md, y):
    """Event function ``ev`` alone (as in ``_events_from``): the kinematic events need no
    force evaluation."""
    if ev == EV_FRIC:
        return _events(law, p, fric, c, md, y)[EV_FRIC]
    delta, a, b, _xs, _sl = _geometry(c, y)
    comp = md[M_COMP] != 0.0
    if ev == EV_VN:
        vn = y[S_VY] - y[S_W] * a
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
def _locate(ev, g0, g1, law, p, fric, c, md, y0, K, h, Q, yt):
    """theta in (0, 1] where event ``ev`` fires (g goes from <= 0 to > 0): Illinois method on
    the dense output. Returns the bracket end where g > 0."""
    a = 0.0
    fa = g0
    b = 1.0
    fb = g1
    side = 0
    prev = 2.0
    for _ in range(100):
        th = (a * fb - b * fa) / (fb - fa)
        if not (a < th < b):
            th = 0.5 * (a + b)
        _dense(y0, K, h, th, Q, yt)
        f = _event_value(ev, law, p, fric, c, md, _tuple(yt))
        if f > 0.0:
            b = th
            fb = f
            if side == 1:
                fa *= 0.5
            side = 1
        else:
            a = th
            fa = f
            if side == -1:
                fb *= 0.5
            side = -1
        if b - a <= 1e-14 or abs(th - prev) <= 1e-14:
            break
        prev = th
    return b


@njit(cache=True, error_model="numpy")
def _trial_step(law, p, fric, c, md, y, k0, h, rtol, sc, Ks, out):
    """One Dormand-Prince step of size ``h`` from ``y`` (derivative ``k0``): 5th-order result in
    ``out``, returns the scaled error norm (as in the main loop)."""
    st = np.empty(NS)
    for i in range(NS):
        Ks[0, i] = k0[i]
    for stage in range(1, 7):
        for i in range(NS):
            acc = 0.0
            for j in range(stage):
                acc += DP_A[stage, j] * Ks[j, i]
            st[i] = y[i] + h * acc
        r = _rhs(law, p, fric, c, md, _tuple(st))
        for i in range(NS):
            Ks[stage, i] = r[i]
    err = 0.0
    for i in range(NS):
        ei = 0.0
        for j in range(7):
            ei += DP_E[j] * Ks[j, i]
        out[i] = st[i]
        q = h * ei / (rtol * (sc[i] + max(abs(y[i]), abs(st[i]))))
        err += q * q
    return math.sqrt(err / NS)


@njit(cache=True, error_model="numpy")
def _integrate_to(law, p, fric, c, md, y, k0, H, rtol, sc, out):
    """Integrate from ``y`` over exactly ``H`` with error control (the state at an event is
    recomputed this way, not taken from the 4th-order dense output; near a separation the force
    vanishes like (delta - delta_r)^1.5 and the step size adapts to it). Returns the number of
    steps taken."""
    Ks = np.empty((7, NS))
    cur = y.copy()
    kc = k0.copy()
    done = 0.0
    hh = H
    n = 0
    while n < 200:
        n += 1
        rem = H - done
        last = hh >= rem * (1.0 - 1e-12)
        if last:
            hh = rem
        err = _trial_step(law, p, fric, c, md, cur, kc, hh, rtol, sc, Ks, out)
        if not (err <= 1.0) and hh > 1e-6 * H:
            hh *= max(0.2, 0.9 * err ** -0.2) if math.isfinite(err) else 0.25
            continue
        if last:
            break
        done += hh
        for i in range(NS):
            cur[i] = out[i]
            kc[i] = Ks[6, i]
        hh *= min(5.0, 0.9 * err ** -0.2) if err > 0.0 else 5.0
    return n


@njit(cache=True, error_model="numpy")
def _record(hist, n, t, law, p, fric, c, md, y):
    """Append one history row (growing the buffer); returns (hist, n + 1)."""
    if n >= hist.shape[0]:
        new = np.empty((2 * hist.shape[0] + 16, NH))
        new[:n] = hist[:n]
        hist = new
    delta, a, b, Fn, Ft, vn, vs, kt = _evaluate(law, p, fric, c, md, y)
    _d, _a, _b, xs, _sl = _geometry(c, y)
    row = hist[n]
    row[0] = t
    row[1] = delta
    row[2] = Fn
    row[3] = Ft
    row[4] = xs
    row[5] = vs
    row[6] = c[C_D] * c[C_C0] + y[S_X]
    row[7] = c[C_D] * c[C_S0] + c[C_R] + y[S_Y]
    row[8] = y[S_PHI]
    row[9] = y[S_VX]
    row[10] = y[S_VY]
    row[11] = y[S_W]
    row[12] = vn
    row[13] = md[M_PHASE]
    row[14] = 1.0 if (fric == FR_COULOMB or fric == FR_MINDLIN) and md[M_FM] == 0.0 else 0.0
    row[15] = _energy(law, p, fric, c, md, y, Fn, Ft, delta, kt)
    return hist, n + 1


# ================================================================================================
# the impact
# ================================================================================================


@njit(cache=True, error_model="numpy")
def _check_inputs(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, rtol):
    for i in range(NB):
        if i == BP_GSTAR:
            continue
        if not math.isfinite(bp[i]):
            return ST_BAD_INPUT
    kind = bp[BP_KIND]
    if kind != KIND_ROD and kind != KIND_SPHERE:
        return ST_BAD_INPUT
    if not (bp[BP_RADIUS] > 0.0 and bp[BP_MASS] > 0.0 and bp[BP_INERTIA] > 0.0
            and bp[BP_HALF_LENGTH] >= 0.0):
        return ST_BAD_INPUT
    if p.shape[0] != NPARAM:
        return ST_BAD_INPUT
    if not (p[P_ESTAR] > 0.0 and math.isfinite(p[P_ESTAR]) and p[P_R] > 0.0
            and math.isfinite(p[P_R])):
        return ST_BAD_INPUT
    if not (p[P_DLIM] > 0.0):  # inf allowed, NaN not
        return ST_BAD_INPUT
    if abs(p[P_R] - bp[BP_RADIUS]) > 1e-12 * bp[BP_RADIUS]:
        return ST_RADIUS_MISMATCH
    if not (math.isfinite(vx0) and math.isfinite(vy0) and math.isfinite(w0)
            and math.isfinite(th0)):
        return ST_BAD_INPUT
    if not (math.isfinite(mu) and mu >= 0.0):
        return ST_BAD_INPUT
    if not (math.isfinite(g) and g >= 0.0):
        return ST_BAD_INPUT
    if not (rtol > 1e-14 and rtol < 1e-2):
        return ST_BAD_INPUT
    if fric < 0 or fric > 2:
        return ST_BAD_FRICTION
    if fric == FR_MINDLIN and mu > 0.0 and not (bp[BP_GSTAR] > 0.0
                                                 and math.isfinite(bp[BP_GSTAR])):
        return ST_BAD_FRICTION
    if kind == KIND_ROD and not (th0 > 0.0 and th0 <= 0.5 * math.pi + 1e-12):
        return ST_BAD_ANGLE
    return ST_OK


@njit(cache=True, error_model="numpy")
def impact(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, const_angle, rtol, record, diag, out):
    """Simulate one impact; fills ``out`` (OUTPUT_FIELDS) and returns (status, history, n).

    law: contact-law id; p: law parameters (NPARAM); fric: friction id; bp: body vector (NB);
    th0 [rad], vx0, vy0 [m/s], w0 [rad/s]: initial state at first touch; mu: friction
    coefficient; g: gravity [m/s^2] (0: off); const_angle: freeze the lever arms at th0;
    rtol: relative tolerance; record: keep the history; diag: compute the energy diagnostics.
    """
    for i in range(out.shape[0]):
        out[i] = math.nan
    hist = np.empty((256 if record else 0, NH))
    nh = 0
    status = _check_inputs(law, p, fric, bp, th0, vx0, vy0, w0, mu, g, rtol)
    if status != ST_OK:
        return status, hist[:0], 0

    if mu == 0.0:
        fric = FR_NONE
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
    c = (d, R, m, inertia, g, th, s0, c0, mu, bp[BP_GSTAR], 1.0 if const_angle else 0.0,
         a0, b0, p[P_DLIM], dsw)

    vn0 = vy0 - w0 * a0
    vt0 = vx0 + w0 * b0
    out[O_VNIN] = vn0
    out[O_VTIN] = vt0
    if not (vn0 < 0.0):
        return ST_NOT_APPROACHING, hist[:0], 0

    # --- mode: phase, delta_m, delta_r, R_r, friction mode, compressing, impulse-ratio sign
    ph = 0.0
    dm = 0.0
    dr = 0.0
    rr = R
    fm = 0.0
    comp = 1.0
    sir = 0.0
    af = 1.0
    if fric == FR_IMPULSE:
        if vt0 != 0.0:
            sir = -1.0 if vt0 > 0.0 else 1.0
        else:
            ab = a0 * b0
            sir = 1.0 if ab > 0.0 else (-1.0 if ab < 0.0 else 0.0)
    elif fric == FR_COULOMB:
        if vt0 != 0.0:
            fm = 1.0 if vt0 > 0.0 else -1.0
        else:
            fm = _coulomb_decide(c, w0, 0.0, a0, b0)
    elif fric == FR_MINDLIN:
        # At first touch the contact is Hertzian: |F_t| / (mu F_n) -> 4 G* |v_t| / (mu E* |v_n|).
        if vt0 != 0.0 and 4.0 * c[C_GS] * abs(vt0) > mu * p[P_ESTAR] * abs(vn0):
            fm = 1.0 if vt0 > 0.0 else -1.0
    md = (ph, dm, dr, rr, fm, comp, sir, af)

    # --- scales for the error control
    lever = d + R
    vstar = abs(vn0)  # velocity scale of the error control (e is relative to v_n0)
    meff = 1.0 / (1.0 / m + a0 * a0 / inertia)
    dstar = (15.0 * meff * vn0 * vn0 / (16.0 * p[P_ESTAR] * math.sqrt(R))) ** 0.4
    tstar = dstar / abs(vn0)
    fscale = meff * vstar / tstar
    sc = np.empty(NS)
    sc[S_X] = dstar
    sc[S_Y] = dstar
    sc[S_PHI] = dstar / lever
    sc[S_VX] = vstar
    sc[S_VY] = vstar
    sc[S_W] = vstar / lever
    sc[S_WORK] = meff * vn0 * vn0  # normal work scale
    sc[S_Q] = fscale if fric == FR_MINDLIN else 1e300
    hmax = tstar
    hmin = 1e-14 * tstar

    y = np.zeros(NS)
    y[S_VX] = vx0
    y[S_VY] = vy0
    y[S_W] = w0
    ynew = np.empty(NS)
    yt = np.empty(NS)
    yev = np.empty(NS)
    k2 = np.empty(NS)
    K = np.empty((7, NS))
    Q = np.empty((NS, 4))

    t = 0.0
    h = 0.02 * tstar * rtol ** 0.2
    r, gold, evq = _rhs_events(law, p, fric, c, md, _tuple(y))
    for i in range(NS):
        K[0, i] = r[i]
    gnew = gold
    if record:
        hist, nh = _record(hist, nh, t, law, p, fric, c, md, _tuple(y))

    e0 = 0.5 * m * (vx0 * vx0 + vy0 * vy0) + 0.5 * inertia * w0 * w0
    emin = e0
    erise = 0.0
    fexcess = 0.0
    fmax = 0.0
    dmax = 0.0
    tmax = 0.0
    vs_pos = 0.0
    vs_neg = 0.0
    stick_time = 0.0
    w_mark = 0.0
    w_comp = 0.0
    w_rest = 0.0
    nsteps = 0
    nevents = 0
    status = ST_NO_SEPARATION
    finished = False
    frictional = fric == FR_COULOMB or fric == FR_MINDLIN

    while nsteps < MAX_STEPS:
        nsteps += 1
        if h > hmax:
            h = hmax
        # ---- one Dormand-Prince step (stage 6 is the new point: FSAL)
        for stage in range(1, 7):
            for i in range(NS):
                acc = 0.0
                for j in range(stage):
                    acc += DP_A[stage, j] * K[j, i]
                k2[i] = y[i] + h * acc
            if stage < 6:
                r = _rhs(law, p, fric, c, md, _tuple(k2))
            else:
                r, gnew, evq = _rhs_events(law, p, fric, c, md, _tuple(k2))
            for i in range(NS):
                K[stage, i] = r[i]
        err = 0.0
        for i in range(NS):
            ei = 0.0
            for j in range(7):
                ei += DP_E[j] * K[j, i]
            ynew[i] = k2[i]
            scale = rtol * (sc[i] + max(abs(y[i]), abs(ynew[i])))
            q = h * ei / scale
            err += q * q
        err = math.sqrt(err / NS)
        if not math.isfinite(err):
            # a non-finite force inside the step (law failure or outside its domain)
            h *= 0.25
            if h < hmin:
                status = ST_NAN
                break
            continue
        if err > 1.0:
            h *= max(0.2, 0.9 * err ** -0.2)
            if h < hmin:
                status = ST_STEP_UNDERFLOW
                break
            continue
        # ---- accepted: events in this step?
        ev = -1
        theta = 2.0
        fired = False
        for j in range(NEV):
            if gold[j] <= 0.0 and gnew[j] > 0.0:
                fired = True
        if fired or record:
            _dense_coeffs(K, Q)
        if fired:
            for j in range(NEV):
                if gold[j] <= 0.0 and gnew[j] > 0.0:
                    thj = _locate(j, gold[j], gnew[j], law, p, fric, c, md, y, K, h, Q, yt)
                    if thj < theta:
                        theta = thj
                        ev = j
        if ev >= 0:
            tend = t + theta * h
        else:
            theta = 1.0
            for i in range(NS):
                yev[i] = ynew[i]
            tend = t + h
        if record:
            for j in range(1, HISTORY_SUBSTEPS):
                thj = j / HISTORY_SUBSTEPS
                if thj >= theta:
                    break
                _dense(y, K, h, thj, Q, yt)
                hist, nh = _record(hist, nh, t + thj * h, law, p, fric, c, md, _tuple(yt))
        if ev >= 0:
            nsteps += _integrate_to(law, p, fric, c, md, y, K[0], theta * h, rtol, sc, yev) - 1
        # ---- statistics over the accepted (possibly truncated) step, in the old mode
        if frictional and fm == 0.0:
            stick_time += tend - t
        yv = _tuple(yev)
        if ev >= 0:
            evq = _evaluate(law, p, fric, c, md, yv)
        delta, a, b, Fn, Ft, vn, vs, kt = evq
        if not (math.isfinite(Fn) and math.isfinite(Ft)):
            status = ST_NAN
            break
        if Fn > fmax:
            fmax = Fn
        if delta > dmax:
            dmax = delta
            tmax = tend
        if vs > vs_pos:
            vs_pos = vs
        if vs < vs_neg:
            vs_neg = vs
        if diag:
            en = _energy(law, p, fric, c, md, yv, Fn, Ft, delta, kt)
            if en - emin > erise:
                erise = en - emin
            if en < emin:
                emin = en
            if frictional:
                ex = abs(Ft) - mu * Fn
                if ex > fexcess:
                    fexcess = ex
        t = tend
        for i in range(NS):
            y[i] = yev[i]
        # ---- step size for the next step
        if err == 0.0:
            fac = 10.0
        else:
            fac = min(10.0, 0.9 * err ** -0.2)
        h *= fac
        if ev < 0:
            for i in range(NS):
                K[0, i] = K[6, i]
            gold = gnew
            if record:
                hist, nh = _record(hist, nh, t, law, p, fric, c, md, yv)
            continue
        # ---- handle the event at (t, y)
        nevents += 1
        if nevents > MAX_EVENTS:
            status = ST_TOO_MANY_EVENTS
            break
        if record:
            hist, nh = _record(hist, nh, t, law, p, fric, c, md, yv)
        if ev == EV_SEP:
            w_rest += y[S_WORK] - w_mark
            status = ST_OK
            finished = True
            break
        if ev == EV_LIMIT:
            status = ST_LAW_LIMIT
            break
        if ev == EV_SWITCH:  # passed once: later reloading happens beyond it
            c = (c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7], c[8], c[9], c[10], c[11], c[12],
                 c[13], math.inf)
        if ev == EV_VN:
            if comp != 0.0:
                w_comp += y[S_WORK] - w_mark
                w_mark = y[S_WORK]
                if ph == 0.0:
                    Fm = loading_force(law, p, delta)
                    dri = residual_depth(law, p, delta, Fm)
                    if not (math.isfinite(Fm) and math.isfinite(dri) and dri >= 0.0
                            and dri < delta):
                        status = ST_NAN
                        break
                    dm = delta
                    dr = dri
                    rr = unloading_radius(p[P_ESTAR], delta, Fm, dri)
                    ph = 1.0
                    if fric == FR_MINDLIN:
                        a_unl = _contact_radius(law, p, delta, math.inf, dr, rr)
                        a_load = _contact_radius(law, p, delta, delta, 0.0, p[P_R])
                        af = a_load / a_unl if a_unl > 0.0 else 1.0
                comp = 0.0
                md = (ph, dm, dr, rr, fm, comp, sir, af)
                if fric == FR_MINDLIN and fm == 0.0:
                    # from the force to the elastic displacement; where the law's contact
                    # radius jumps at the turning point, keep F if k_t grows (the new annulus
                    # carries no traction) and keep xi if it shrinks: never creates energy
                    ktn = 8.0 * c[C_GS] * _radius(law, p, md, delta)
                    kref = ktn if ktn >= kt else kt
                    y[S_Q] = -Ft / kref if kref > 0.0 else 0.0
            else:
                w_rest += y[S_WORK] - w_mark
                w_mark = y[S_WORK]
                comp = 1.0
                if fric == FR_MINDLIN and fm == 0.0:
                    y[S_Q] = Ft
        elif ev == EV_RELOAD:
            ph = 0.0
            if fric == FR_MINDLIN and fm == 0.0:
                md = (ph, dm, dr, rr, fm, comp, sir, af)
                ktn = 8.0 * c[C_GS] * _radius(law, p, md, delta)
                y[S_Q] = Ft if (ktn >= kt or kt <= 0.0) else Ft * ktn / kt
        elif ev == EV_FRIC:
            fm, y[S_Q] = _friction_switch(fric, c, fm, comp, y[S_W], y[S_Q], Fn, Ft, vs, a, b,
                                          kt)
        md = (ph, dm, dr, rr, fm, comp, sir, af)
        if fric == FR_MINDLIN:
            sc[S_Q] = fscale if comp != 0.0 else dstar
        r, gold, evq = _rhs_events(law, p, fric, c, md, _tuple(y))
        # a restart can find the friction state already outside its domain (e.g. the friction
        # cap drops with a jump of the loading curve): switch at once, at the same instant
        for _ in range(3):
            if not (frictional and gold[EV_FRIC] > 0.0):
                break
            delta, a, b, Fn, Ft, vn, vs, kt = evq
            fm, y[S_Q] = _friction_switch(fric, c, fm, comp, y[S_W], y[S_Q], Fn, Ft, vs, a, b,
                                          kt)
            md = (ph, dm, dr, rr, fm, comp, sir, af)
            r, gold, evq = _rhs_events(law, p, fric, c, md, _tuple(y))
        for i in range(NS):
            K[0, i] = r[i]

    out[O_NST] = nsteps
    out[O_DMAX] = dmax
    out[O_FMAX] = fmax
    out[O_TMAX] = tmax
    out[O_T] = t
    if not finished:
        return status, hist[:nh], nh

    # ---- results at separation
    delta, a, b, xs, slide = _geometry(c, _tuple(y))
    vx = y[S_VX]
    vy = y[S_VY]
    w = y[S_W]
    vn = vy - w * a
    vt = vx + w * b
    out[O_E] = -vn / vn0
    out[O_EE] = math.sqrt(max(0.0, -w_rest / w_comp)) if w_comp < 0.0 else math.nan
    out[O_VX] = vx
    out[O_VY] = vy
    out[O_W] = w
    out[O_DP] = dr
    out[O_SL] = slide
    out[O_CT] = xs
    pn = m * (vy - vy0) + m * g * t
    out[O_PN] = pn
    out[O_FMEAN] = pn / t
    out[O_PT] = m * (vx - vx0)
    e_end = 0.5 * m * (vx * vx + vy * vy) + 0.5 * inertia * w * w + m * g * y[S_Y]
    out[O_ED] = e0 - e_end
    out[O_STICK] = stick_time
    vtol = 1e-6 * vstar
    if fric == FR_NONE:
        reg = REGIME_FRICTIONLESS
    elif vs_pos > vtol and vs_neg < -vtol:
        reg = REGIME_REVERSAL
    elif fric == FR_IMPULSE and ((sir > 0.0 and vs_pos > vtol) or (sir < 0.0 and vs_neg < -vtol)):
        # the contact point slid along the constant friction force (friction doing work on the
        # body): the paper's Eq. 7 is outside its validity (mu beyond mu_c)
        reg = REGIME_REVERSAL
    elif stick_time > 1e-9 * t:
        reg = REGIME_STICK
    else:
        reg = REGIME_SLIP
    out[O_REG] = reg
    out[O_VNOUT] = vn
    out[O_VTOUT] = vt
    out[O_ANG] = th0 + y[S_PHI] if kind == KIND_ROD else math.nan
    if diag:
        out[O_ERISE] = erise / e0
        out[O_FEX] = fexcess / fmax if fmax > 0.0 else 0.0
    return ST_OK, hist[:nh], nh


@njit(cache=True, parallel=True, error_model="numpy")
def impact_batch(law, lp, fric, bpa, init, mu, g, const_angle, rtol, diag, out, status):
    """Run ``init.shape[0]`` impacts in parallel (numba prange). ``lp``: (1 or N, NPARAM);
    ``bpa``: (1 or N, NB); ``init``: (N, 4) [angle, vx, vy, spin]; ``mu``: (N,)."""
    n = init.shape[0]
    shared_p = lp.shape[0] == 1
    shared_b = bpa.shape[0] == 1
    for i in prange(n):
        pi = lp[0] if shared_p else lp[i]
        bi = bpa[0] if shared_b else bpa[i]
        st, _h, _n = impact(law, pi, fric, bi, init[i, 0], init[i, 1], init[i, 2], init[i, 3],
                            mu[i], g, const_angle, rtol, False, diag, out[i])
        status[i] = st


@njit(cache=True, error_model="numpy")
def residual_caps(law, p, delta):
    """(delta_r, R_r) of the unloading branch from virgin loading to each ``delta`` [m]."""
    n = delta.shape[0]
    dr = np.zeros(n)
    rr = np.full(n, np.inf)
    for i in range(n):
        dm = delta[i]
        if dm <= 0.0:
            continue
        Fm = loading_force(law, p, dm)
        dri = residual_depth(law, p, dm, Fm)
        dr[i] = dri
        rr[i] = unloading_radius(p[P_ESTAR], dm, Fm, dri)
    return dr, rr


DISPATCHERS = (
    _geometry, _normal_force, _radius, _dforce_ddelta, _dradius_ddelta, _stick_force, _evaluate,
    _rhs, _mindlin_trial_rate, _events_from, _events, _rhs_events, _energy, _coulomb_decide,
    _friction_switch, _dense, _dense_coeffs, _event_value, _locate, _tuple, _trial_step,
    _integrate_to, _record, _check_inputs, impact, impact_batch, residual_caps,
)


def _contact_dispatchers() -> list[object]:
    from numba.core.registry import CPUDispatcher

    return [v for v in vars(_k).values() if isinstance(v, CPUDispatcher)]


from impactlab.dynamics import _cache  # noqa: E402

_cache.refresh([*DISPATCHERS, *_contact_dispatchers()], "engine")
