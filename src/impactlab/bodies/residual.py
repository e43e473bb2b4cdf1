"""Axial residual pseudo-modes: the static compliance of every truncated axial mode, in two
coordinates (modal truncation augmentation).

References: J. M. Dickens, J. M. Nakagawa, M. J. Wittbrodt, A critique of mode acceleration and
modal truncation augmentation methods for modal response analysis, Computers & Structures
(1997) (volume, pages and DOI not confirmed here); the residual attachment modes of
R. R. Craig Jr., A. J. Kurdila, Fundamentals of Structural Dynamics, 2nd ed., Wiley (2006), in
its chapter on component-mode synthesis (section number not confirmed here).

With unit axial forces at the two ends (a, b in {0, 1}: s = -L/2 and +L/2), the residual
vectors r_a = sum_{k > N} phi_k U_k(a) / omega_k^2 span the pseudo-modes. Their stiffness and
mass matrices, G_ab = sum_{k > N} U_k(a) U_k(b) / omega_k^2 and H_ab = sum U U / omega^4, are in
closed form (U_k(0)^2 = 2/m, U_k(1) = (-1)^k U_k(0), omega_k = k pi c / L; the tails of
sum 1/k^2 and 1/k^4 over even and odd k from their totals pi^2/24, pi^2/8, pi^4/1440,
pi^4/96). G x = omega^2 H x gives two mass-normalised modes, orthogonal to every retained
mode, whose static compliance at the ends is the exact tail G: the end compliance of the axial
model is exact in statics for any N (SI units).
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.bodies.rod_section import RodSection

__all__ = ["axial_residual_modes", "axial_residual_slopes"]


def _tail_matrices(sec: RodSection, n_axial: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(G, lam, X): the residual stiffness matrix, and the eigenvalues and eigenvectors of
    G x = lam H x with H the residual mass matrix."""
    k = np.arange(1, n_axial + 1, dtype=float)
    ev = k[k % 2 == 0]
    od = k[k % 2 == 1]
    t2e = math.pi**2 / 24 - np.sum(1 / ev**2)
    t2o = math.pi**2 / 8 - np.sum(1 / od**2)
    t4e = math.pi**4 / 1440 - np.sum(1 / ev**4)
    t4o = math.pi**4 / 96 - np.sum(1 / od**4)
    s = math.pi * sec.bar_speed / sec.length
    u2 = 2.0 / sec.mass
    G = u2 / s**2 * np.array([[t2e + t2o, t2e - t2o], [t2e - t2o, t2e + t2o]])
    H = u2 / s**4 * np.array([[t4e + t4o, t4e - t4o], [t4e - t4o, t4e + t4o]])
    from scipy.linalg import eigh  # on first use: ``import impactlab`` stays light

    lam, X = eigh(G, H)
    return G, lam, X


def axial_residual_modes(sec: RodSection, n_axial: int) -> tuple[np.ndarray, np.ndarray]:
    """The two pseudo-modes above ``n_axial`` retained axial modes: (omega (2,) [rad/s],
    U (2 ends, 2 modes): their axial end values per unit modal coordinate)."""
    if n_axial < 1:
        raise ValueError(f"axial residual modes need n_axial >= 1, got {n_axial!r}")
    G, lam, X = _tail_matrices(sec, n_axial)
    return np.sqrt(lam), G @ X


def axial_residual_slopes(
    sec: RodSection, n_axial: int, s: np.ndarray, kmax: int = 20000
) -> np.ndarray:
    """d/ds of the two pseudo-modes at s [m] (the series summed to k = ``kmax``); shape
    (s.size, 2)."""
    L = sec.length
    x = np.asarray(s, dtype=float) + 0.5 * L
    sc = math.pi * sec.bar_speed / L
    u2 = 2.0 / sec.mass
    _G, _lam, X = _tail_matrices(sec, n_axial)
    kk = np.arange(n_axial + 1, kmax + 1, dtype=float)
    # r_a'(s) = sum_k U_k'(s) U_k(a) / om_k^2, U_k = sqrt(u2) cos(k pi x / L)
    dU = (
        -math.sqrt(u2)
        * (kk[None, :] * math.pi / L)
        * np.sin(kk[None, :] * math.pi * x[:, None] / L)
    )
    w = 1.0 / (kk * sc) ** 2
    r0 = dU @ (math.sqrt(u2) * np.ones_like(kk) * w)
    r1 = dU @ (math.sqrt(u2) * (-1.0) ** kk * w)
    return np.stack([r0, r1], axis=1) @ X
