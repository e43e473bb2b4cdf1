"""The exact solutions of the Timoshenko beam equations of a uniform rod (shear deformation and
rotary inertia), and the free-free boundary determinant whose roots are its bending frequencies.

T. C. Huang, The effect of rotatory inertia and of shear deformation on the frequency and normal
mode equations of uniform beams with simple end conditions, J. Appl. Mech. 28 (1961) 579-584,
doi:10.1115/1.3641787; S. M. Han, H. Benaroya, T. Wei, Dynamics of transversely vibrating beams
using four engineering theories, J. Sound Vib. 225 (1999) 935-988, doi:10.1006/jsvi.1999.2257.
Written in a basis of decaying exponentials so that it stays well conditioned for high modes. W
is the transverse displacement, Psi the rotation of the cross-section, gamma = W' - Psi the
shear angle; the rod and s are those of ``impactlab.bodies.rod_section`` (SI units).
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.bodies.rod_section import RodSection

__all__ = [
    "basis",
    "boundary_matrix",
    "determinant",
    "determinants",
    "scaled_matrix",
    "section_constants",
    "timoshenko_cutoff",
    "wavenumbers",
]


def section_constants(sec: RodSection) -> tuple[float, float, float, float, float]:
    return sec.rho_eff, sec.area, sec.second_moment, sec.E, sec.kappa * sec.G


def timoshenko_cutoff(sec: RodSection) -> float:
    """Cut-off frequency sqrt(kappa G A / (rho I)) [rad/s] of the second spectrum."""
    rho, A, I, _E, kG = section_constants(sec)
    return math.sqrt(kG * A / (rho * I))


def wavenumbers(sec: RodSection, om: np.ndarray) -> tuple[np.ndarray, ...]:
    """Roots of the Timoshenko dispersion relation for W = e^{lambda x} at the frequencies
    ``om`` [rad/s]: E I l^4 + l^2 (E I sig + rho I om^2) + sig (rho I om^2 - kGA) = 0,
    sig = rho om^2 / (kG). Returns (below, a, b, sig): below the cut-off (``below`` True)
    l^2 = a^2 > 0 and -b^2, above it l^2 = -a^2 and -b^2."""
    rho, A, I, E, kG = section_constants(sec)
    sig = rho * om * om / kG
    p = sig + rho * om * om / E
    q = sig * (rho * om * om / E - kG * A / (E * I))
    disc = np.sqrt(p * p - 4.0 * q)
    l2p = 0.5 * (-p + disc)
    b = np.sqrt(-(0.5 * (-p - disc)))
    below = l2p > 0.0
    return below, np.sqrt(np.where(below, l2p, -l2p)), b, sig


def _oscillating(
    beta: float, sig: float, x: np.ndarray, rows: tuple[np.ndarray, ...], i: int
) -> None:
    """Rows i, i+1 of the basis: cos(beta x), sin(beta x) and their Psi, Psi', gamma/sig."""
    W, P, dP, G = rows
    cb = np.cos(beta * x)
    sb = np.sin(beta * x)
    f = (sig - beta * beta) / beta
    W[i] = cb
    P[i] = f * sb
    dP[i] = (sig - beta * beta) * cb
    G[i] = -sb / beta
    W[i + 1] = sb
    P[i + 1] = -f * cb
    dP[i + 1] = (sig - beta * beta) * sb
    G[i + 1] = cb / beta


def basis(sec: RodSection, om: float, x: np.ndarray) -> tuple[np.ndarray, ...]:
    """Basis functions (W, Psi, Psi', gamma/sig) of the Timoshenko equations at x in [0, L]
    (rows: the 4 basis functions). Below the cut-off: cos bx, sin bx, e^{-ax}, e^{-a(L-x)};
    above: cos bx, sin bx, cos ax, sin ax."""
    L = sec.length
    below, a_, b_, sig_ = wavenumbers(sec, np.array([om]))
    kind, a, b, sig = 0 if below[0] else 1, float(a_[0]), float(b_[0]), float(sig_[0])
    x = np.asarray(x, dtype=float)
    W = np.empty((4, *x.shape))
    rows = (W, np.empty_like(W), np.empty_like(W), np.empty_like(W))
    _oscillating(b, sig, x, rows, 0)
    if kind == 0:
        for i, (lam, e) in enumerate(((-a, np.exp(-a * x)), (a, np.exp(-a * (L - x))))):
            rows[0][2 + i] = e
            rows[1][2 + i] = (lam * lam + sig) / lam * e
            rows[2][2 + i] = (lam * lam + sig) * e
            rows[3][2 + i] = -e / lam
    else:
        _oscillating(a, sig, x, rows, 2)
    return rows


def boundary_matrix(sec: RodSection, om: float) -> np.ndarray:
    """Unscaled 4x4 free-free boundary matrix at ``om`` [rad/s]: rows Psi'(0), gamma(0)/sig,
    Psi'(L), gamma(L)/sig (``_boundaries`` of one frequency)."""
    return _boundaries(sec, np.array([om]))[0]


def scaled_matrix(sec: RodSection, om: float) -> np.ndarray:
    """The boundary matrix with its columns scaled to a largest entry of 1 (its determinant
    is then O(1) at every frequency)."""
    return _scaled(_boundaries(sec, np.array([om])))[0]


def determinant(om: float, sec: RodSection) -> float:
    return float(np.linalg.det(scaled_matrix(sec, om)))


def determinants(sec: RodSection, oms: np.ndarray) -> np.ndarray:
    """``determinant`` at every frequency of ``oms`` [rad/s] at once (the root scan's grid)."""
    return np.asarray(np.linalg.det(_scaled(_boundaries(sec, np.asarray(oms, dtype=float)))))


def _scaled(Mx: np.ndarray) -> np.ndarray:
    """Boundary matrices (frequencies, 4, 4) with each column scaled to a largest entry of 1."""
    n = np.max(np.abs(Mx), axis=1, keepdims=True)
    return np.where(n > 0, Mx / np.where(n > 0, n, 1.0), Mx)


def _end_rows(beta: np.ndarray, sig: np.ndarray, c: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``_oscillating``'s Psi' and gamma/sig of cos(beta x) and sin(beta x) at one end, from
    their values ``c`` and ``s`` there, per frequency: shape (frequencies, 2, 2) (rows Psi',
    gamma/sig; columns the cosine, the sine)."""
    k = sig - beta * beta
    return np.stack([np.stack([k * c, k * s], -1), np.stack([-s / beta, c / beta], -1)], 1)


def _boundaries(sec: RodSection, om: np.ndarray) -> np.ndarray:
    """The unscaled boundary matrices (frequencies, 4, 4) at the frequencies ``om`` [rad/s]:
    ``wavenumbers`` and ``basis`` at x = 0 and L, as array operations over the frequencies
    (the same operations, so one frequency's matrix is the same to the bit at any count)."""
    below, a, b, sig = wavenumbers(sec, om)  # below the cut-off: e^{-ax}, e^{-a(L-x)}
    L = sec.length
    one, zero = np.ones_like(om), np.zeros_like(om)
    Mx = np.empty((om.shape[0], 4, 4))
    Mx[:, 0:2, 0:2] = _end_rows(b, sig, one, zero)
    Mx[:, 2:4, 0:2] = _end_rows(b, sig, np.cos(b * L), np.sin(b * L))
    decay = np.exp(-a * L)
    for row, x_is_0 in ((0, True), (2, False)):
        osc = (
            _end_rows(a, sig, one, zero)
            if x_is_0
            else _end_rows(a, sig, np.cos(a * L), np.sin(a * L))
        )
        for i, lam in enumerate((-a, a)):
            e = (one if i == 0 else decay) if x_is_0 else (decay if i == 0 else one)
            Mx[:, row, 2 + i] = np.where(below, (lam * lam + sig) * e, osc[:, 0, i])
            Mx[:, row + 1, 2 + i] = np.where(below, -e / lam, osc[:, 1, i])
    return Mx
