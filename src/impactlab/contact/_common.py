"""Helpers shared by several laws (Python side, run once per ``build``)."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from impactlab.contact import kernel_arrays as ka
from impactlab.contact import kernels as k
from impactlab.materials.pair import first_yield_factor

#: The radius [m] a law is built for: the sizes ``impactlab.bodies`` allows (its
#: ``SIZE_RANGE``, 1 nm to 10 km); beyond them a law's forces and interferences (Hertz's
#: E* R^1/2 delta^3/2 at first yield, (R / E*)^2) under- or overflow.
RADIUS_RANGE = (1e-9, 1e4)


def check_radius(R: float) -> float:
    """``R`` [m]; ValueError unless it lies within :data:`RADIUS_RANGE` (to 1e-9 relative, as
    the bodies' sizes)."""
    lo, hi = RADIUS_RANGE
    if not lo * (1.0 - 1e-9) <= R <= hi * (1.0 + 1e-9):
        raise ValueError(
            f"radius = {R!r} m lies outside the allowed range [{lo:g}, {hi:g}] m (the sizes of "
            "impactlab's bodies; beyond it the law's forces under- or overflow); check the value "
            "and its unit (SI: m)"
        )
    return R


def pair_constants(p: np.ndarray) -> tuple[float, float, float, float]:
    """(E* [Pa], R [m], S_y [Pa], nu) from a law's parameter vector ``p`` (``kernels.P_*``),
    filled by ``ContactLaw.build`` from the contact pair and the radius (ValueError for a
    radius outside :data:`RADIUS_RANGE`)."""
    R = check_radius(float(p[k.P_R]))
    return float(p[k.P_ESTAR]), R, float(p[k.P_SY]), float(p[k.P_NU])


def jg_C(nu: float) -> float:
    """Green's critical-pressure factor C(nu) = 1.295 exp(0.736 nu) (Green 2005; paper Eq. 15).

    It is the Hertz peak pressure at first yield divided by S_y (von Mises;
    ``materials.first_yield_factor``, which also picks the body that yields first).
    """
    return first_yield_factor(nu)


def jg_critical(E_star: float, R: float, S_y: float, nu: float) -> tuple[float, float]:
    """(delta_c [m], F_c [N]) of paper Eqs. 15 and 17 (Jackson & Green 2005).

    delta_c = (pi C S_y / (2 E*))^2 R, F_c = 4/3 (R/E*)^2 (pi C S_y / 2)^3 (= Hertz at delta_c).
    """
    C = jg_C(nu)
    R = check_radius(R)
    dc = (math.pi * C * S_y / (2.0 * E_star)) ** 2 * R
    fc = 4.0 / 3.0 * (R / E_star) ** 2 * (math.pi * C * S_y / 2.0) ** 3
    return dc, fc


def nearest_crossing(
    f_a: Callable[[float], float],
    f_b: Callable[[float], float],
    target: float,
    lo: float,
    hi: float,
    n: int = 3000,
    g_array: Callable[[np.ndarray], np.ndarray] | None = None,
) -> float | None:
    """The downward crossing of f_a through f_b in [lo, hi] nearest to ``target`` (in log
    distance), or None.

    A downward crossing is a root of g = f_a - f_b where g goes from > 0 to < 0 with growing x
    (f_a falls below f_b). Sign changes are searched on a logarithmic grid of ``n`` points and
    refined with brentq. ``g_array``, when given, evaluates f_a - f_b on the whole grid at once
    (same values, much faster than point-by-point calls).
    """
    from scipy.optimize import brentq  # on first use: ``import impactlab`` stays light

    d = np.geomspace(lo, hi, n)
    if g_array is not None:
        g = np.asarray(g_array(d), dtype=np.float64)
    else:
        g = np.array([f_a(float(x)) - f_b(float(x)) for x in d])
    change = np.flatnonzero((g[:-1] > 0.0) & (g[1:] <= 0.0))
    if change.size == 0:
        return None
    candidates: list[tuple[float, float, float]] = []  # (distance, a, b)
    for i in change:
        mid = math.sqrt(d[i] * d[i + 1])
        candidates.append((abs(math.log(mid / target)), float(d[i]), float(d[i + 1])))
    _, a, b = min(candidates)
    if f_a(b) - f_b(b) == 0.0:
        return b
    root = brentq(lambda x: f_a(x) - f_b(x), a, b, xtol=1e-15 * a, rtol=1e-14, maxiter=200)
    return float(root)


def curves(gap: int, p: np.ndarray) -> tuple[Callable[[float], float], Callable[[float], float]]:
    """(plastic, elastic): the elastic-plastic loading force and the elastic force it takes over
    from [N] at an interference [m], of the Jackson-Green family (``kernel_arrays
    .GAP_JACKSON_FAMILY``: Hertz) or Kogut-Komvopoulos (``GAP_KOGUT_KOMVOPOULOS``)."""
    if gap == ka.GAP_JACKSON_FAMILY:
        E, R = p[k.P_ESTAR], p[k.P_R]
        return (lambda x: float(k.jg_ep_force(p, x))), (lambda x: float(k.hertz_force(E, R, x)))
    return (lambda x: float(k.kk_ep_force(p, x))), (lambda x: float(k.kk_elastic_force(p, x)))


def switch_point(
    p: np.ndarray,
    gap: int,
    published_at: float,
    search: tuple[float, float],
    published: bool,
    failure: str,
) -> tuple[float, float]:
    """(switch interference, relative force jump at the published switch) of the law ``gap``
    (:func:`curves`): the published switch point ``published_at`` when ``published``, else the
    downward crossing of the elastic-plastic curve through the elastic one nearest to it within
    ``search`` = (lo, hi) (located on a grid, refined with brentq). ValueError with the message
    ``failure`` when there is none."""
    plastic, elastic = curves(gap, p)
    jump = plastic(published_at) / elastic(published_at) - 1.0
    if published:
        return published_at, jump
    found = nearest_crossing(
        plastic,
        elastic,
        published_at,
        *search,
        g_array=lambda d: ka.elastic_plastic_gap_array(gap, p, d),
    )
    if found is None:
        raise ValueError(failure)
    return found, jump


def check_switch(value: float, name: str = "published_switch") -> bool:
    """Validate a 0/1 switch parameter; True for 1."""
    if value not in (0.0, 1.0):
        raise ValueError(f"{name} must be 0 (continuous default) or 1 (published), got {value!r}")
    return value == 1.0
