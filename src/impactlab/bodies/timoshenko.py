"""Free-free Timoshenko bending modes of a uniform rod (shear deformation and rotary inertia).

Frequencies are the roots of the 4x4 free-free boundary determinant built from the exact
solutions of the Timoshenko beam equations (``timoshenko_solutions``: Huang 1961,
doi:10.1115/1.3641787; Han, Benaroya, Wei 1999, doi:10.1006/jsvi.1999.2257), checked against the
count of frequencies below the last (``timoshenko_count``). The shapes come from the
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
from impactlab.bodies.timoshenko_count import bending_modes_below, roots_between
from impactlab.bodies.timoshenko_solutions import (
    basis,
    boundary_matrix,
    determinant,
    determinants,
    scaled_matrix,
    section_constants,
    timoshenko_cutoff,
    wavenumbers,
)

__all__ = ["timoshenko_cutoff", "timoshenko_frequencies", "timoshenko_shape_fn"]

#: A mode shape: s [m] -> (W, Psi, Psi', gamma) per unit modal coordinate.
ShapeFn = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]


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
    vals = determinants(sec, grid)

    def refine(lo: float, hi: float, scale: float) -> None:
        r = brentq(determinant, lo, hi, args=(sec,), xtol=1e-13 * lo, rtol=1e-15, maxiter=200)
        if abs(determinant(r, sec)) < 1e-6 * scale:  # not a jump (relative: a thin rod's
            roots.append(float(r))  # determinants are all of 1e-22 or less)

    for i in range(len(grid) - 1):
        if vals[i] == 0.0:
            roots.append(float(grid[i]))
        elif vals[i] * vals[i + 1] < 0.0 and not grid[i] < cut < grid[i + 1]:
            refine(float(grid[i]), float(grid[i + 1]), max(abs(vals[i]), abs(vals[i + 1])))
        elif i > 0 and grid[i] > cut and _dips(vals[i - 1], vals[i], vals[i + 1]):
            inner = _crossing(sec, float(grid[i - 1]), float(grid[i + 1]), float(vals[i]))
            if inner is not None:  # two roots between grid[i - 1] and grid[i + 1]
                scale = max(abs(vals[i - 1]), abs(vals[i + 1]))
                refine(float(grid[i - 1]), inner, scale)
                refine(inner, float(grid[i + 1]), scale)
        if len(roots) >= n:
            break
    return np.array(_counted(sec, sorted(roots)[:n], n, float(grid[0]), float(grid[-1])))


def _counted(sec: RodSection, roots: list[float], n: int, start: float, end: float) -> list[float]:
    """The first ``n`` frequencies [rad/s]: ``roots`` (the scan's, ascending, at most n, found
    between ``start`` and ``end``) checked against the count of the frequencies below the last
    (``timoshenko_count``). Where the scan missed roots (two within a grid step whose dip falls
    between grid points) or took a false one, the roots of every interval between the
    midpoints of the scan's whose count differs from one are found again from the count (a
    root the scan found among them kept to the bit), and the missing ones above the last."""
    top = roots[-1] * (1.0 + 1e-9) if roots else end
    if len(roots) == n and bending_modes_below(sec, top) == n:
        return roots
    edges = [start] + [0.5 * (a + b) for a, b in itertools.pairwise(roots)] + [top]
    counts = [bending_modes_below(sec, om) for om in edges]
    out = roots_between(sec, 1e-3 * start, start, 0, counts[0])  # below the scan's grid
    for j, root in enumerate(roots):
        if counts[j + 1] - counts[j] == 1:
            out.append(root)
        else:
            found = roots_between(sec, edges[j], edges[j + 1], counts[j], counts[j + 1])
            out += [root if abs(r - root) <= 1e-12 * root else r for r in found]
    if not roots:
        out += roots_between(sec, start, top, counts[0], counts[-1])
    hi = top
    while len(out) < n:  # the next ones above the scan's last
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
        lambda om: sign * determinant(om, sec),
        bounds=(lo, hi),
        method="bounded",
        options={"xatol": 1e-12 * lo},
    )
    return float(res.x) if sign * determinant(float(res.x), sec) < 0.0 else None


def timoshenko_shape_fn(sec: RodSection, om: float) -> ShapeFn:
    """The mass-normalised Timoshenko mode of frequency ``om`` [rad/s] as a function
    s -> (W, Psi, Psi', gamma) (s in [-L/2, L/2] [m]); sign: W(-L/2) > 0."""
    raw = boundary_matrix(sec, om)
    scale = np.max(np.abs(raw), axis=0)
    _u, _s, vt = np.linalg.svd(scaled_matrix(sec, om))
    coef = vt[-1] / np.where(scale > 0, scale, 1.0)
    L = sec.length
    rho, A, I, _E, _kg = section_constants(sec)
    sig = float(wavenumbers(sec, np.array([om]))[3][0])
    x, w = gauss(L, 64)
    Wb, Pb, _dPb, _Gb = basis(sec, om, x)
    norm2 = float(np.sum(w * (rho * A * (coef @ Wb) ** 2 + rho * I * (coef @ Pb) ** 2)))
    w0 = float(coef @ basis(sec, om, np.array([0.0]))[0][:, 0])
    c = coef / math.sqrt(norm2) * (1.0 if w0 >= 0 else -1.0)

    def shape(s: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        wb, pb, dpb, gb = basis(sec, om, np.asarray(s, dtype=float) + 0.5 * L)
        return c @ wb, c @ pb, c @ dpb, (c @ gb) * sig

    return shape
