"""How many free-free Timoshenko bending frequencies lie below a frequency: a count that
misses none (the Wittrick-Williams algorithm), and the roots it finds where a scan missed them.

W. H. Wittrick, F. W. Williams, A general algorithm for computing natural frequencies of
elastic structures, Q. J. Mech. Appl. Math. 24 (1971) 263-284, doi:10.1093/qjmam/24.3.263;
for Timoshenko members W. P. Howson, F. W. Williams, Natural frequencies of frames with
axially loaded Timoshenko members, J. Sound Vib. 26 (1973) 503-515,
doi:10.1016/S0022-460X(73)80216-0. The number of natural frequencies below omega is
J(omega) = J0(omega) + s{K(omega)}: s the number of negative eigenvalues of the structure's
exact dynamic stiffness matrix K, J0 the natural frequencies below omega of its members with
their ends clamped. The rod is cut into N equal members so short that none has a clamped
frequency below omega, so J0 = 0, and

    J(omega) = s{K(omega)} = 2 + (bending modes below omega),

the 2 being the rigid translation and rotation (frequency 0). A member of length l clamped at
both ends (W = Psi = 0) has, by its Rayleigh quotient with Poincare's inequality
int f'^2 >= (pi / l)^2 int f^2 = x int f^2 for W and Psi and
(a - b)^2 >= (1 - e) a^2 - (1 / e - 1) b^2 for the shear angle W' - Psi (0 < e < 1, chosen as
1 - e = t / (1 + t) with t = x E I / (2 kappa G A)), no frequency below

    omega_l^2 = min(E x / (2 rho), kappa G x t / (rho (1 + t))),

the shear beam's and, for a long member, half the Euler-Bernoulli beam's clamped bound; N
makes omega_l > omega. The member's dynamic stiffness comes from the exact solutions of
``timoshenko_solutions`` (end forces -Q(0), -M(0), Q(l), M(l) with Q = kappa G A (W' - Psi),
M = E I Psi', against the end displacements W(0), Psi(0), W(l), Psi(l)). SI units.
"""

from __future__ import annotations

import dataclasses
import functools
import math

import numpy as np

from impactlab.bodies import timoshenko_solutions as tim
from impactlab.bodies.rod_section import RodSection

__all__ = ["bending_modes_below", "roots_between"]

#: Members a little shorter than the bound requires (a margin on omega_l > omega).
_MARGIN = 0.9
#: The relative width to which bisections of the count narrow a root's bracket before Brent's
#: method refines it (the count is exact away from a root, not within round-off of one).
_BRACKET = 1e-9


def _member_length(sec: RodSection, om: float) -> float:
    """The longest member [m] none of whose clamped frequencies lies below ``om`` [rad/s]
    (omega_l = om, see module: x = (pi / l)^2 from the two bounds' quadratics)."""
    rho, A, I, E, kG = tim.section_constants(sec)
    w2 = om * om
    a = E * I / (2.0 * kG * A)  # t = a x
    c = kG / rho
    x_rotation = 2.0 * rho * w2 / E
    x_shear = (w2 * a + math.sqrt(w2 * w2 * a * a + 4.0 * c * a * w2)) / (2.0 * c * a)
    return math.pi / math.sqrt(max(x_rotation, x_shear))


def _member_stiffness(sec: RodSection, length: float, om: float) -> np.ndarray:
    """The exact 4x4 dynamic stiffness [N/m, N, N m] of a member of ``length`` [m] of the rod
    at ``om`` [rad/s], symmetric (its two halves averaged: they agree to round-off)."""
    _rho, A, I, E, kG = tim.section_constants(sec)
    member = dataclasses.replace(sec, length=length, mass=sec.mass * length / sec.length)
    W, P, dP, G = tim.basis(member, om, np.array([0.0, length]))
    sig = float(tim.wavenumbers(member, np.array([om]))[3][0])
    Q = kG * A * sig * G  # shear force per basis function at both ends
    M = E * I * dP
    ends = np.array([W[:, 0], P[:, 0], W[:, 1], P[:, 1]])
    forces = np.array([-Q[:, 0], -M[:, 0], Q[:, 1], M[:, 1]])
    K = forces @ np.linalg.inv(ends)
    return 0.5 * (K + K.T)


@functools.lru_cache(maxsize=128)
def _unit_rod(sec: RodSection) -> tuple[RodSection, float]:
    """The rod scaled to L = 1 m, E = 1 Pa, rho = 1 kg/m^3 (its L/d, nu and kappa kept: the
    same frequencies, times L / sqrt(E / rho)), and that factor [s]: the count is made on it,
    whatever the rod's size (a rod of 0.2 mm has determinants of 1e-22 and stiffnesses of
    every magnitude)."""
    rho, _a, _i, E, _kg = tim.section_constants(sec)
    d = float(sec.diameter) / sec.length  # type: ignore[arg-type]
    unit = RodSection(
        length=1.0,
        mass=math.pi * d * d / 4.0,
        density=1.0,
        E=1.0,
        nu=sec.nu,
        diameter=d,
        shear_coefficient=sec.shear_coefficient,
    )
    return unit, sec.length / math.sqrt(E / rho)


def bending_modes_below(sec: RodSection, om: float) -> int:
    """The number of free-free Timoshenko bending frequencies of ``sec`` below ``om`` [rad/s]
    (``om`` > 0; within 1e-6 of the cut-off, where the solutions' basis degenerates, counted
    just above it): see module. Counted on the rod scaled to unit size (``_unit_rod``), with
    each rotation in units of the member length (a congruence: the same signs)."""
    unit, factor = _unit_rod(sec)
    om = _probe(unit, om * factor)
    n_members = max(1, math.ceil(1.0 / (_MARGIN * _member_length(unit, om))))
    length = 1.0 / n_members
    scale = np.array([1.0, 1.0 / length, 1.0, 1.0 / length])
    k = _member_stiffness(unit, length, om) * np.outer(scale, scale) * length**3
    K = np.zeros((2 * n_members + 2, 2 * n_members + 2))
    for j in range(n_members):
        K[2 * j : 2 * j + 4, 2 * j : 2 * j + 4] += k
    return int(np.count_nonzero(np.linalg.eigvalsh(K) < 0.0)) - 2


def _probe(sec: RodSection, om: float) -> float:
    """``om`` [rad/s], moved off the cut-off's neighbourhood (as the scan's grid)."""
    cut = tim.timoshenko_cutoff(sec)
    return cut * (1.0 + 2e-6) if abs(om / cut - 1.0) <= 1e-6 else om


def roots_between(sec: RodSection, lo: float, hi: float, c_lo: int, c_hi: int) -> list[float]:
    """The ``c_hi - c_lo`` bending frequencies [rad/s] in (lo, hi), given the counts below
    ``lo`` and ``hi``: each isolated by bisecting the count, then refined by Brent's method on
    the boundary determinant (as the scan's roots), or by the count alone where the
    determinant does not change sign across the bracket."""
    if c_hi <= c_lo:
        return []
    if c_hi - c_lo > 1 and hi - lo > 4e-16 * hi:
        mid = _probe(sec, 0.5 * (lo + hi))
        c_mid = bending_modes_below(sec, mid)
        return roots_between(sec, lo, mid, c_lo, c_mid) + roots_between(sec, mid, hi, c_mid, c_hi)
    if c_hi - c_lo > 1:  # coincident to round-off
        return [0.5 * (lo + hi)] * (c_hi - c_lo)
    return [_one_root(sec, lo, hi, c_lo)]


def _one_root(sec: RodSection, lo: float, hi: float, c_lo: int) -> float:
    """The one bending frequency [rad/s] in (lo, hi) above ``c_lo`` modes."""
    from scipy.optimize import brentq  # on first use: ``import impactlab`` stays light

    while hi - lo > _BRACKET * hi:
        mid = _probe(sec, 0.5 * (lo + hi))
        if not lo < mid < hi:
            break
        if bending_modes_below(sec, mid) > c_lo:
            hi = mid
        else:
            lo = mid
    d_lo, d_hi = tim.determinant(lo, sec), tim.determinant(hi, sec)
    if d_lo * d_hi < 0.0:
        return float(
            brentq(tim.determinant, lo, hi, args=(sec,), xtol=1e-13 * lo, rtol=1e-15, maxiter=200)
        )
    return 0.5 * (lo + hi)
