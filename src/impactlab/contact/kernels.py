"""Compiled (numba) force evaluations of every contact law: the engine's inner loop calls these.

Contract (shared by all laws; SI units):

- A law is identified by an integer id (``HERTZ`` ... ``THORNTON``) and a float64 parameter
  vector ``p`` of length ``NPARAM``. Slots ``0..6`` are common to all laws (see ``P_*``); slots
  ``7..15`` are law-specific and documented below. Slot 7 (``P_DSW``) has the same meaning for
  every law.
- ``loading_force(law, p, delta)`` is the force on the virgin loading curve [N] for an
  interference ``delta`` [m] (0 for ``delta <= 0``).
- ``residual_depth(law, p, delta_m, F_m)`` is the residual depth delta_r [m] after unloading
  from the maximum (delta_m, F_m); ``0 <= delta_r < delta_m``.
- Unloading (and reloading below delta_m) is, for every law, Hertzian with a flattened radius
  R_r chosen for continuity at (delta_m, F_m): ``F = 4/3 E* sqrt(R_r) (delta - delta_r)^1.5``.
- The force and contact radius of a contact with its history (``turning_point``,
  ``contact_force``, ``loading_contact_radius``, ``contact_radius``) are in
  ``impactlab.contact.history_kernels``.
- ``p[P_DLIM]`` is the largest interference for which the law is valid (``R`` or less); the
  engine stops with a clear error beyond it.

Law-specific slots (filled by the law modules; do not write them by hand, use ``build``):

======================  ====  ==========================================================
law                     slot  meaning
======================  ====  ==========================================================
all                     7     P_DSW: interference where the loading curve leaves the
                                elastic curve [m] (``inf`` for Hertz)
Ghaednia/Jackson-Green  8     P_JG_DC: critical interference delta_c (Eq. 15) [m]
                        9     P_JG_FC: critical force F_c (Eq. 17) [N]
                        10    P_JG_C: C(nu) = 1.295 exp(0.736 nu)
                        11    P_JG_B: B = 0.14 exp(23 S_y / E*)
                        12    P_JG_K1: coefficient of the first exponential
                        13    P_JG_K2: coefficient of the second exponential
                        14    P_JG_M: exponent of delta* in the second term
                        15    P_JG_HARD: hardness model (0: Ghaednia cosine, 1: JG 2005)
Kogut-Komvopoulos       8     P_KK_EPS: E* / S_y
                        9     P_KK_RES: delta_r / delta_m = 1 - E_Rdelta (Eq. 22)
Brake                   8     P_BR_DP: delta_p (Eq. 26) [m]
                        9     P_BR_P0: P0 (Eq. 25) [Pa]
                        10    P_BR_N: Meyer index n
                        11    P_BR_AP: a_p = sqrt(2 R delta_p) [m]
Thornton                8     P_TH_PY: limiting contact pressure p_y [Pa]
Tabulated               8     P_TB_DC: delta_c of the pair (Jackson-Green) [m]
                        9     P_TB_FC: F_c of the pair [N]
                        10    P_TB_RATIO: E*/S_y of the curves' pair (for people)
                        11    P_TB_NU: nu of the curves' pair (for people)
======================  ====  ==========================================================

The tabulated law's curves follow ``p[NPARAM:]`` (``contact.curve_table``): its parameter
vectors are ``NPARAM + CURVE_LENGTH`` long (``param_length``).

Everything here is a pure function: no state is kept between calls, nothing is allocated.
Vectorised loops over these kernels (for building and plotting models) are in
``impactlab.contact.kernel_arrays``.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from impactlab.contact.curve_table import (  # noqa: F401  (CURVE_MAGIC: for the core)
    CURVE_LENGTH,
    CURVE_MAGIC,
    curve_force,
    curve_residual_ratio,
)
from impactlab.contact.table import HEADER as TABLE_HEADER  # noqa: F401  (re-exported for the core)
from impactlab.contact.table import TABLE_MAGIC, table_force  # noqa: F401

HERTZ = 0
GHAEDNIA = 1
JACKSON_GREEN = 2
KOGUT_KOMVOPOULOS = 3
BRAKE = 4
THORNTON = 5
TABULATED = 6
N_LAWS = 7

NPARAM = 16
P_ESTAR = 0  # reduced modulus E* [Pa]
P_R = 1  # radius of the sphere / rod tip [m]
P_SY = 2  # yield strength used by the law [Pa]
P_NU = 3  # Poisson's ratio used by the law
P_DY = 4  # yield onset delta_y by the law's own criterion [m] (inf for Hertz)
P_FY = 5  # force at yield onset F_y [N] (inf for Hertz)
P_DLIM = 6  # largest valid interference [m]
P_LAW0 = 7  # first law-specific slot

P_DSW = 7  # all laws: where the loading curve leaves the elastic curve [m]

P_JG_DC = 8
P_JG_FC = 9
P_JG_C = 10
P_JG_B = 11
P_JG_K1 = 12
P_JG_K2 = 13
P_JG_M = 14
P_JG_HARD = 15
JG_HARDNESS_GHAEDNIA = 0.0
JG_HARDNESS_JG2005 = 1.0

P_KK_EPS = 8
P_KK_RES = 9

P_BR_DP = 8
P_BR_P0 = 9
P_BR_N = 10
P_BR_AP = 11

P_TH_PY = 8

P_TB_DC = 8
P_TB_FC = 9
P_TB_RATIO = 10
P_TB_NU = 11


def param_length(law_id: int) -> int:
    """Length of a parameter vector of law ``law_id`` (without the polynomial table)."""
    return NPARAM + CURVE_LENGTH if law_id == TABULATED else NPARAM


#: The dimensionless interference delta/delta_c where the Jackson-Green contact-area fit starts.
JG_AREA_SWITCH = 1.9


# --------------------------------------------------------------------------------------------
# Hertz and the common unloading branch
# --------------------------------------------------------------------------------------------


@njit(cache=True, inline="always", error_model="numpy")
def hertz_force(E_star: float, R: float, delta: float) -> float:
    """Hertz sphere-on-flat force 4/3 E* sqrt(R) delta^1.5 [N]; 0 for delta <= 0."""
    if delta <= 0.0:
        return 0.0
    return 4.0 / 3.0 * E_star * math.sqrt(R) * delta * math.sqrt(delta)


@njit(cache=True, inline="always", error_model="numpy")
def unloading_radius(E_star: float, delta_m: float, F_m: float, delta_r: float) -> float:
    """Flattened radius R_r [m] making the Hertzian unloading curve pass through (delta_m, F_m)."""
    d = delta_m - delta_r
    if d <= 0.0:
        return math.inf
    c = 3.0 * F_m / (4.0 * E_star)
    return c * c / (d * d * d)


@njit(cache=True, inline="always", error_model="numpy")
def unloading_force(E_star: float, R_r: float, delta_r: float, delta: float) -> float:
    """Hertzian unloading force 4/3 E* sqrt(R_r) (delta - delta_r)^1.5 [N]; 0 below delta_r."""
    d = delta - delta_r
    if d <= 0.0:
        return 0.0
    return 4.0 / 3.0 * E_star * math.sqrt(R_r) * d * math.sqrt(d)


@njit(cache=True, inline="always", error_model="numpy")
def _sech(y: float) -> float:
    """sech(y) for y >= 0 without overflow."""
    e = math.exp(-y)
    return 2.0 * e / (1.0 + e * e)


# --------------------------------------------------------------------------------------------
# Ghaednia et al. (2016) and Jackson-Green (2005): one family, different constants
# --------------------------------------------------------------------------------------------


@njit(cache=True, inline="always", error_model="numpy")
def jg_contact_radius(p: np.ndarray, delta: float) -> float:
    """Jackson-Green contact radius r = sqrt(R delta (delta / (1.9 delta_c))^B) [m]
    (JG 2005; paper Eq. 17 with its misprint corrected: delta, not delta_y, under the root)."""
    dc = p[P_JG_DC]
    return math.sqrt(p[P_R] * delta * (delta / (JG_AREA_SWITCH * dc)) ** p[P_JG_B])


#: log(1.9): the area fit's (delta / (1.9 delta_c))^B written as exp(B (log(ds) - log 1.9)).
_LOG_AREA_SWITCH = math.log(JG_AREA_SWITCH)


@njit(cache=True, error_model="numpy")
def jg_ep_force(p: np.ndarray, delta: float) -> float:
    """Elastic-plastic force of the Jackson-Green family [N] (paper Eq. 16 / JG 2005 Eq. 17),
    evaluated at any delta > 0 (no switch logic).

    Every power of delta* = delta/delta_c comes from one logarithm (the engine's inner loop
    evaluates this about a hundred times per impact): delta*^(5/12) and delta*^(5/9) are the
    3rd and 4th powers of delta*^(5/36), and the area fit
    a/R = sqrt(delta/R) (delta*/1.9)^(B/2) (as ``jg_contact_radius``)."""
    if delta <= 0.0:
        return 0.0
    lds = math.log(delta / p[P_JG_DC])
    rr = math.sqrt(delta / p[P_R]) * math.exp(0.5 * p[P_JG_B] * (lds - _LOG_AREA_SWITCH))
    if p[P_JG_HARD] == JG_HARDNESS_GHAEDNIA:
        h = 2.84 - 0.92 * (1.0 - math.cos(math.pi * rr))
    else:
        h = 2.84 * (1.0 - math.exp(-0.82 * rr ** (-0.7)))
    q = math.exp((5.0 / 36.0) * lds)  # delta*^(5/36)
    q3 = q * q * q
    t1 = math.exp(1.5 * lds - p[P_JG_K1] * q3)
    t2 = 4.0 * h / p[P_JG_C] * (1.0 - math.exp(-p[P_JG_K2] * q3 * q)) * math.exp(p[P_JG_M] * lds)
    return p[P_JG_FC] * (t1 + t2)


@njit(cache=True, inline="always", error_model="numpy")
def _jg_loading(p: np.ndarray, delta: float) -> float:
    if delta < p[P_DSW]:
        return hertz_force(p[P_ESTAR], p[P_R], delta)
    return jg_ep_force(p, delta)


@njit(cache=True, inline="always", error_model="numpy")
def _jg_residual(p: np.ndarray, delta_m: float) -> float:
    """Paper Eq. 19: delta_r/delta_m = 0.8 [1 - ((delta_m/delta_c + 5.5)/6.5)^-2]."""
    dc = p[P_JG_DC]
    if delta_m <= dc:
        return 0.0
    q = (delta_m / dc + 5.5) / 6.5
    return delta_m * 0.8 * (1.0 - 1.0 / (q * q))


# --------------------------------------------------------------------------------------------
# Kogut-Komvopoulos (2004)
# --------------------------------------------------------------------------------------------


@njit(cache=True, inline="always", error_model="numpy")
def kk_elastic_force(p: np.ndarray, delta: float) -> float:
    """Elastic branch, paper Eq. 20 with the prefactor 2 sqrt(2)/(3 pi) (not 4 sqrt(2)/(3 pi)):
    F = a' S_y (2 sqrt2 / (3 pi)) (E* delta / (S_y r')) = (2 sqrt2 / 3) E* delta r' [N],
    which is Hertz times sqrt(1 - delta/(2R))."""
    if delta <= 0.0:
        return 0.0
    R = p[P_R]
    rp = math.sqrt(delta * (2.0 * R - delta))
    return 2.0 * math.sqrt(2.0) / 3.0 * p[P_ESTAR] * delta * rp


@njit(cache=True, error_model="numpy")
def kk_ep_force(p: np.ndarray, delta: float) -> float:
    """Elastic-plastic branch, paper Eq. 21 [N], evaluated at any 0 < delta < R (no switch)."""
    if delta <= 0.0:
        return 0.0
    R = p[P_R]
    rp2 = delta * (2.0 * R - delta)
    t = delta / math.sqrt(rp2)
    le = math.log(p[P_KK_EPS])
    lt = math.log(t)
    num = 0.839 + 0.656 * le + 0.651 * lt
    den = 2.192 - 0.394 * le - 0.419 * lt
    if den <= 0.0:
        return math.inf
    return math.pi * rp2 * p[P_SY] * num / den


@njit(cache=True, inline="always", error_model="numpy")
def _kk_loading(p: np.ndarray, delta: float) -> float:
    if delta < p[P_DSW]:
        return kk_elastic_force(p, delta)
    return kk_ep_force(p, delta)


# --------------------------------------------------------------------------------------------
# Brake (2015)
# --------------------------------------------------------------------------------------------


@njit(cache=True, error_model="numpy")
def brake_eq24_force(p: np.ndarray, delta: float) -> float:
    """Brake's transition, paper Eq. 24 as printed (with sqrt(R) and a = sqrt(2 R delta)) [N],
    for delta > delta_y; no clamp."""
    R = p[P_R]
    dy = p[P_DY]
    dp = p[P_BR_DP]
    n = p[P_BR_N]
    ne = n - 2.0
    x = (delta - dy) / (dp - dy)
    fh = hertz_force(p[P_ESTAR], R, delta)
    ap = p[P_BR_AP]
    a = math.sqrt(2.0 * R * delta)
    fp = p[P_BR_P0] * math.pi * ap * ap * (a / ap) ** n
    return _sech((1.0 + ne) * x) * fh + (1.0 - _sech((1.0 - ne) * x)) * fp


@njit(cache=True, inline="always", error_model="numpy")
def _brake_loading(p: np.ndarray, delta: float) -> float:
    fh = hertz_force(p[P_ESTAR], p[P_R], delta)
    if delta <= p[P_DY]:
        return fh
    f = brake_eq24_force(p, delta)
    return f if f < fh else fh


# --------------------------------------------------------------------------------------------
# Thornton (1997)
# --------------------------------------------------------------------------------------------


@njit(cache=True, inline="always", error_model="numpy")
def _thornton_loading(p: np.ndarray, delta: float) -> float:
    dy = p[P_DY]
    if delta <= dy:
        return hertz_force(p[P_ESTAR], p[P_R], delta)
    return p[P_FY] + math.pi * p[P_TH_PY] * p[P_R] * (delta - dy)


# --------------------------------------------------------------------------------------------
# Dispatch
# --------------------------------------------------------------------------------------------


@njit(cache=True, error_model="numpy")
def loading_force(law: int, p: np.ndarray, delta: float) -> float:
    """Force on the loading curve of ``law`` at interference ``delta`` [N] (from the table
    appended to ``p`` where there is one and it covers ``delta``: ``contact.table``)."""
    if delta <= 0.0:
        return 0.0
    if delta >= p[P_DSW]:
        f = table_force(p, NPARAM, delta)
        if f >= 0.0:
            return f
    if law == HERTZ:
        return hertz_force(p[P_ESTAR], p[P_R], delta)
    if law == GHAEDNIA or law == JACKSON_GREEN:
        return _jg_loading(p, delta)
    if law == KOGUT_KOMVOPOULOS:
        return _kk_loading(p, delta)
    if law == BRAKE:
        return _brake_loading(p, delta)
    if law == THORNTON:
        return _thornton_loading(p, delta)
    if law == TABULATED:
        if delta < p[P_DSW]:
            return hertz_force(p[P_ESTAR], p[P_R], delta)
        return curve_force(p, NPARAM, delta)
    return math.nan


@njit(cache=True, error_model="numpy")
def residual_depth(law: int, p: np.ndarray, delta_m: float, F_m: float) -> float:
    """Residual depth delta_r after unloading from (delta_m, F_m) [m]; 0 <= delta_r < delta_m."""
    if law == HERTZ or delta_m <= 0.0 or F_m <= 0.0:
        return 0.0
    if law == GHAEDNIA or law == JACKSON_GREEN:
        return _jg_residual(p, delta_m)
    if law == KOGUT_KOMVOPOULOS:
        if delta_m <= p[P_DY]:
            return 0.0
        return delta_m * p[P_KK_RES]
    if law == BRAKE:
        # delta_r = delta_m [1 - F_m / ((4/3) E* sqrt(R) delta_m^1.5)] (Brake 2015; paper Eq. 27
        # corrected); F_m never exceeds the Hertz force (the loading curve is clamped to it).
        fh = hertz_force(p[P_ESTAR], p[P_R], delta_m)
        d = delta_m * (1.0 - F_m / fh)
        return d if d > 0.0 else 0.0
    if law == THORNTON:
        # Thornton: unloading keeps the contact radius a_m = sqrt(R delta_m):
        # R_p = 4 E* a_m^3 / (3 F_m), delta_r = delta_m - a_m^2 / R_p.
        if delta_m <= p[P_DY]:
            return 0.0
        d = delta_m - 3.0 * F_m / (4.0 * p[P_ESTAR] * math.sqrt(p[P_R] * delta_m))
        return d if d > 0.0 else 0.0
    if law == TABULATED:
        return delta_m * curve_residual_ratio(p, NPARAM, delta_m)
    return math.nan
