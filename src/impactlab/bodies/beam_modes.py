"""Closed-form free-free modes of a uniform rod: axial (elementary rod theory) and
Euler-Bernoulli bending (SI units; the rod and its coordinate s are those of
``impactlab.bodies.rod_section``).

* Axial modes: omega_k = k pi c / L, c = sqrt(E / rho), U_k = sqrt(2 / m) cos(k pi x / L) with
  x = s + L/2 (Rayleigh-Love lateral inertia neglected: its relative frequency shift,
  about (nu k pi r_g / L)^2 / 2, is below 2e-3 for k <= 5 for the paper's rod).
* Euler-Bernoulli bending modes: cos(beta L) cosh(beta L) = 1 (beta_k L = 4.730041, 7.853205,
  10.995608, 14.137165, 17.278760, ...), omega_k = beta_k^2 sqrt(E I / (rho A)),
  W_k = [cosh bx + cos bx - sigma_k (sinh bx + sin bx)] / sqrt(m),
  sigma_k = (cosh bL - cos bL) / (sinh bL - sin bL); R. D. Blevins, Formulas for Natural
  Frequency and Mode Shape, Van Nostrand Reinhold (1979), the free-free beam entry of its
  table of single-span beams; L. Meirovitch, Fundamentals of Vibrations, McGraw-Hill (2001),
  the free-free beam example of the chapter on distributed-parameter systems (neither table
  nor section number is confirmed here). The shapes are evaluated in an overflow-free form.

All modes are mass-normalised (int rho A U^2 ds = 1, int rho A W^2 ds = 1).
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.bodies.rod_section import RodSection

__all__ = [
    "BETA_L_TABLE",
    "axial_frequencies",
    "axial_shape",
    "axial_slope",
    "eb_beta_l",
    "eb_frequencies",
    "eb_shape",
]

#: beta_k L of the first free-free Euler-Bernoulli modes, to 10 digits (the reference values
#: of the tests; e.g. Blevins 1979).
BETA_L_TABLE = (4.730040745, 7.853204624, 10.995607838, 14.137165491, 17.278759657)


def axial_frequencies(sec: RodSection, n: int) -> np.ndarray:
    """omega_k = k pi c / L [rad/s], k = 1..n."""
    k = np.arange(1, n + 1)
    return k * math.pi * sec.bar_speed / sec.length


def axial_shape(sec: RodSection, k: int, s: np.ndarray) -> np.ndarray:
    """Mass-normalised axial mode k (>= 1) at s [m]: sqrt(2/m) cos(k pi (s + L/2) / L)
    [m per unit modal coordinate, kg^-1/2]."""
    x = np.asarray(s, dtype=float) + 0.5 * sec.length
    return math.sqrt(2.0 / sec.mass) * np.cos(k * math.pi * x / sec.length)


def axial_slope(sec: RodSection, k: int, s: np.ndarray) -> np.ndarray:
    """d/ds of ``axial_shape`` at s [kg^-1/2 m^-1]."""
    x = np.asarray(s, dtype=float) + 0.5 * sec.length
    L = sec.length
    return -math.sqrt(2.0 / sec.mass) * (k * math.pi / L) * np.sin(k * math.pi * x / L)


def _cos_minus_sech(x: float) -> float:
    """cos x - 1 / cosh x (beyond x = 700, where cosh overflows, sech x = 2 e^-x)."""
    if x < 700.0:
        return math.cos(x) - 1.0 / math.cosh(x)
    return math.cos(x) - 2.0 * math.exp(-x)


def eb_beta_l(n: int) -> np.ndarray:
    """Roots beta_k L (k = 1..n) of cos(x) cosh(x) = 1, solved as cos x - 1/cosh x = 0 (well
    conditioned) by Brent's method next to (2k + 1) pi / 2."""
    from scipy.optimize import brentq  # on first use: ``import impactlab`` stays light

    out = np.empty(n)
    for k in range(1, n + 1):
        x0 = (2 * k + 1) * math.pi / 2.0
        out[k - 1] = brentq(
            _cos_minus_sech, x0 - 0.3, x0 + 0.3, xtol=1e-15, rtol=1e-15, maxiter=200
        )
    return out


def eb_frequencies(sec: RodSection, n: int) -> np.ndarray:
    """omega_k = (beta_k L)^2 / L^2 sqrt(E I / (rho A)) [rad/s], k = 1..n."""
    bl = eb_beta_l(n)
    return bl**2 / sec.length**2 * math.sqrt(sec.E * sec.second_moment / sec.rho_a)


def _eb_parts(bl: float, xi: np.ndarray) -> tuple[np.ndarray, ...]:
    """(phi, phi', phi'', phi''') / beta^j of the unnormalised free-free shape
    phi = cosh + cos - sigma (sinh + sin) at xi = x / L in [0, 1], overflow-free."""
    b = bl
    z = b * xi
    eb = math.exp(-b)
    den = 0.5 * (1.0 - eb * eb) - math.sin(b) * eb  # (sinh b - sin b) e^-b
    one_minus = ((math.cos(b) - math.sin(b)) * eb - eb * eb) / den  # 1 - sigma
    one_plus = 2.0 - one_minus
    sigma = 1.0 - one_minus
    A = one_minus * math.exp(b)  # finite: (1 - sigma) ~ e^-b
    ezb = np.exp(z - b)
    emz = np.exp(-z)
    ch_m_ss = 0.5 * (A * ezb + one_plus * emz)  # cosh z - sigma sinh z
    sh_m_sc = 0.5 * (A * ezb - one_plus * emz)  # sinh z - sigma cosh z
    c = np.cos(z)
    s = np.sin(z)
    phi = ch_m_ss + c - sigma * s
    d1 = sh_m_sc - s - sigma * c
    d2 = ch_m_ss - c + sigma * s
    d3 = sh_m_sc + s + sigma * c
    return phi, d1, d2, d3


def eb_shape(sec: RodSection, k: int, s: np.ndarray, deriv: int = 0) -> np.ndarray:
    """Mass-normalised Euler-Bernoulli bending mode k (>= 1) at s [m]; ``deriv`` = 0..3 gives
    W, W' (the section rotation Psi), W'', W''' (derivatives with respect to s)."""
    bl = eb_beta_l(k)[-1]
    L = sec.length
    xi = (np.asarray(s, dtype=float) + 0.5 * L) / L
    parts = _eb_parts(bl, xi)
    beta = bl / L
    return parts[deriv] * beta**deriv / math.sqrt(sec.mass)
