"""Free-free Timoshenko bending modes of a uniform rod (shear deformation and rotary inertia).

Frequencies are the roots of the 4x4 free-free boundary determinant built from the exact
solutions of the Timoshenko beam equations (T. C. Huang, The effect of rotatory inertia and of
shear deformation on the frequency and normal mode equations of uniform beams with simple end
conditions, J. Appl. Mech. 28 (1961) 579-584, doi:10.1115/1.3641787; S. M. Han, H. Benaroya,
T. Wei, Dynamics of transversely vibrating beams using four engineering theories, J. Sound
Vib. 225 (1999) 935-988, doi:10.1006/jsvi.1999.2257), written in a basis of decaying
exponentials so that it stays well conditioned for high modes. The shapes come from the
determinant's null vector and are mass-normalised with the rotary inertia:
int (rho A W^2 + rho I Psi^2) ds = 1. W is the transverse displacement, Psi the rotation of the
cross-section, gamma = W' - Psi the shear angle; the rod and s are those of
``impactlab.bodies.rod_section`` (SI units).
"""

from __future__ import annotations

import functools
import itertools
import math
from collections.abc import Callable

import numpy as np

from impactlab.bodies.beam_modes import eb_frequencies
from impactlab.bodies.rod_section import RodSection, gauss

__all__ = ["timoshenko_cutoff", "timoshenko_frequencies", "timoshenko_shape_fn"]

#: A mode shape: s [m] -> (W, Psi, Psi', gamma) per unit modal coordinate.
ShapeFn = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]


def _consts(sec: RodSection) -> tuple[float, float, float, float, float]:
    return sec.rho_eff, sec.area, sec.second_moment, sec.E, sec.kappa * sec.G


def timoshenko_cutoff(sec: RodSection) -> float:
    """Cut-off frequency sqrt(kappa G A / (rho I)) [rad/s] of the second spectrum."""
    rho, A, I, _E, kG = _consts(sec)
    return math.sqrt(kG * A / (rho * I))


def _wavenumbers(sec: RodSection, om: np.ndarray) -> tuple[np.ndarray, ...]:
    """Roots of the Timoshenko dispersion relation for W = e^{lambda x} at the frequencies
    ``om`` [rad/s]: E I l^4 + l^2 (E I sig + rho I om^2) + sig (rho I om^2 - kGA) = 0,
    sig = rho om^2 / (kG). Returns (below, a, b, sig): below the cut-off (``below`` True)
    l^2 = a^2 > 0 and -b^2, above it l^2 = -a^2 and -b^2."""
    rho, A, I, E, kG = _consts(sec)
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


def _basis(sec: RodSection, om: float, x: np.ndarray) -> tuple[np.ndarray, ...]:
    """Basis functions (W, Psi, Psi', gamma/sig) of the Timoshenko equations at x in [0, L]
    (rows: the 4 basis functions). Below the cut-off: cos bx, sin bx, e^{-ax}, e^{-a(L-x)};
    above: cos bx, sin bx, cos ax, sin ax."""
    L = sec.length
    below, a_, b_, sig_ = _wavenumbers(sec, np.array([om]))
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


def _boundary(sec: RodSection, om: float) -> np.ndarray:
    """Unscaled 4x4 free-free boundary matrix at ``om`` [rad/s]: rows Psi'(0), gamma(0)/sig,
    Psi'(L), gamma(L)/sig (``_boundaries`` of one frequency)."""
    return _boundaries(sec, np.array([om]))[0]


def _matrix(sec: RodSection, om: float) -> np.ndarray:
    """The boundary matrix with its columns scaled to a largest entry of 1 (its determinant
    is then O(1) at every frequency)."""
    return _scaled(_boundaries(sec, np.array([om])))[0]


def _determinant(om: float, sec: RodSection) -> float:
    return float(np.linalg.det(_matrix(sec, om)))


def _determinants(sec: RodSection, oms: np.ndarray) -> np.ndarray:
    """``_determinant`` at every frequency of ``oms`` [rad/s] at once (the root scan's grid)."""
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
    ``_wavenumbers`` and ``_basis`` at x = 0 and L, as array operations over the frequencies
    (the same operations, so one frequency's matrix is the same to the bit at any count)."""
    below, a, b, sig = _wavenumbers(sec, om)  # below the cut-off: e^{-ax}, e^{-a(L-x)}
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


def timoshenko_frequencies(sec: RodSection, n: int) -> np.ndarray:
    """First n free-free Timoshenko bending frequencies [rad/s] (``_frequencies``; kept for
    the last sections and counts asked for: a rod's default counts and its modal basis ask
    for the same ones)."""
    return np.array(_frequencies(sec, int(n)))


@functools.lru_cache(maxsize=128)
def _frequencies(sec: RodSection, n: int) -> np.ndarray:
    """First n free-free Timoshenko bending frequencies [rad/s]: roots of the boundary
    determinant, bracketed on a grid finer than the mode spacing and refined by Brent's
    method (sign changes through a pole or across the cut-off are rejected). Above the
    cut-off the two spectra can put two roots within one grid step, where the determinant
    dips to zero and back without a sign change between grid points: at each such dip
    (a local minimum of |det| between three grid points of one sign) the determinant's
    extremum is located, and where it crosses zero both roots are refined there. The first n
    are then checked against the count of the frequencies below the last (``_counted``)."""
    from scipy.optimize import brentq  # on first use: ``import impactlab`` stays light

    om_eb = eb_frequencies(sec, n + 2)
    cut = timoshenko_cutoff(sec)
    roots: list[float] = []
    grid = np.geomspace(0.3 * om_eb[0], 1.05 * om_eb[-1], 400 * (n + 2))
    grid = grid[np.abs(grid / cut - 1.0) > 1e-6]  # degenerate basis at the cut-off
    vals = _determinants(sec, grid)

    def refine(lo: float, hi: float) -> None:
        r = brentq(_determinant, lo, hi, args=(sec,), xtol=1e-13 * lo, rtol=1e-15, maxiter=200)
        if abs(_determinant(r, sec)) < 1e-6:  # not a pole
            roots.append(float(r))

    for i in range(len(grid) - 1):
        if vals[i] == 0.0:
            roots.append(float(grid[i]))
        elif vals[i] * vals[i + 1] < 0.0 and not grid[i] < cut < grid[i + 1]:
            refine(float(grid[i]), float(grid[i + 1]))
        elif i > 0 and grid[i] > cut and _dips(vals[i - 1], vals[i], vals[i + 1]):
            inner = _crossing(sec, float(grid[i - 1]), float(grid[i + 1]), float(vals[i]))
            if inner is not None:  # two roots between grid[i - 1] and grid[i + 1]
                refine(float(grid[i - 1]), inner)
                refine(inner, float(grid[i + 1]))
        if len(roots) >= n:
            break
    if len(roots) < n:
        raise RuntimeError(f"found only {len(roots)} Timoshenko roots below {grid[-1]:.4g} rad/s")
    return np.array(_counted(sec, sorted(roots)[:n], float(grid[0])))


def _counted(sec: RodSection, roots: list[float], start: float) -> list[float]:
    """``roots`` [rad/s] (the scan's first n, ascending) checked against the count of the
    frequencies below the last (``timoshenko_count``): where the scan missed roots (two
    within a grid step whose dip falls between grid points) or took a false one, the roots
    of every interval between the midpoints of the scan's whose count differs from one are
    found again from the count; the others are kept to the bit."""
    from impactlab.bodies.timoshenko_count import bending_modes_below, roots_between

    n = len(roots)
    top = roots[-1] * (1.0 + 1e-9)
    if bending_modes_below(sec, top) == n:
        return roots
    edges = [start] + [0.5 * (a + b) for a, b in itertools.pairwise(roots)] + [top]
    counts = [bending_modes_below(sec, om) for om in edges]
    out = roots_between(sec, 1e-3 * start, start, 0, counts[0])  # below the scan's grid
    for j, root in enumerate(roots):
        if counts[j + 1] - counts[j] == 1:
            out.append(root)
        else:
            out += roots_between(sec, edges[j], edges[j + 1], counts[j], counts[j + 1])
    hi = top
    while len(out) < n:  # false roots taken out: the next ones above the scan's last
        lo, hi = hi, hi * 1.05
        c_lo, c_hi = bending_modes_below(sec, lo), bending_modes_below(sec, hi)
        out += roots_between(sec, lo, hi, c_lo, c_hi)
    return sorted(out)[:n]


def _dips(before: float, here: float, after: float) -> bool:
    """True where |det| has a local minimum at a grid point between two of the same sign."""
    same_sign = before * here > 0.0 and here * after > 0.0
    return same_sign and abs(here) < abs(before) and abs(here) < abs(after)


def _crossing(sec: RodSection, lo: float, hi: float, here: float) -> float | None:
    """The frequency in (lo, hi) [rad/s] where the determinant, of the sign of ``here`` at the
    grid points, reaches its extremum towards zero, if it crosses zero there; else None."""
    from scipy.optimize import minimize_scalar

    sign = 1.0 if here > 0.0 else -1.0
    res = minimize_scalar(
        lambda om: sign * _determinant(om, sec),
        bounds=(lo, hi),
        method="bounded",
        options={"xatol": 1e-12 * lo},
    )
    return float(res.x) if sign * _determinant(float(res.x), sec) < 0.0 else None


def timoshenko_shape_fn(sec: RodSection, om: float) -> ShapeFn:
    """The mass-normalised Timoshenko mode of frequency ``om`` [rad/s] as a function
    s -> (W, Psi, Psi', gamma) (s in [-L/2, L/2] [m]); sign: W(-L/2) > 0."""
    raw = _boundary(sec, om)
    scale = np.max(np.abs(raw), axis=0)
    _u, _s, vt = np.linalg.svd(_matrix(sec, om))
    coef = vt[-1] / np.where(scale > 0, scale, 1.0)
    L = sec.length
    rho, A, I, _E, _kg = _consts(sec)
    sig = float(_wavenumbers(sec, np.array([om]))[3][0])
    x, w = gauss(L, 64)
    Wb, Pb, _dPb, _Gb = _basis(sec, om, x)
    norm2 = float(np.sum(w * (rho * A * (coef @ Wb) ** 2 + rho * I * (coef @ Pb) ** 2)))
    w0 = float(coef @ _basis(sec, om, np.array([0.0]))[0][:, 0])
    c = coef / math.sqrt(norm2) * (1.0 if w0 >= 0 else -1.0)

    def shape(s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        wb, pb, dpb, gb = _basis(sec, om, np.asarray(s, dtype=float) + 0.5 * L)
        return c @ wb, c @ pb, c @ dpb, (c @ gb) * sig

    return shape
