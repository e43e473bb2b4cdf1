"""The free-free modal basis of a uniform rod of circular cross-section: what the compiled
flexible-rod integrator needs (SI units).

``modal_basis(section, n_axial, n_bending, theory)`` returns the circular frequencies of the
elastic modes and the values U (axial displacement), W (transverse displacement) and Psi
(section rotation) of each mass-normalised mode at the two ends (s = -L/2: end 0, the tip that
touches first; s = +L/2: end 1). Axial modes and Euler-Bernoulli bending modes are in closed
form (``impactlab.bodies.beam_modes``), Timoshenko bending modes from the exact free-free
solution (``impactlab.bodies.timoshenko``), and two optional axial residual pseudo-modes carry
the static compliance of all the truncated axial modes (``impactlab.bodies.residual``).
``rigid_modes`` are the three planar rigid-body modes (omega = 0). The sources are listed in
:data:`MODAL_REFERENCES`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from impactlab.bodies.beam_modes import axial_frequencies, axial_shape, eb_frequencies, eb_shape
from impactlab.bodies.residual import axial_residual_modes
from impactlab.bodies.rod_section import EULER_BERNOULLI, TIMOSHENKO, RodSection, check_theory
from impactlab.bodies.timoshenko import timoshenko_frequencies, timoshenko_shape_fn
from impactlab.references import Reference

__all__ = [
    "KIND_AXIAL",
    "KIND_AXIAL_RESIDUAL",
    "KIND_BENDING",
    "MODAL_REFERENCES",
    "ModalBasis",
    "modal_basis",
    "rigid_modes",
]

#: Most modes of either family (``impactlab.bodies.flexible_rod.MAX_MODES``: beyond it the
#: wavelengths fall below the diameter and the residual modes' eigenproblem degenerates).
_MAX_MODES = 128

KIND_AXIAL = 0  #: ``ModalBasis.kind`` of an axial mode
KIND_BENDING = 1  #: of a bending mode
KIND_AXIAL_RESIDUAL = 2  #: of an axial residual pseudo-mode

#: The sources of the modal model (to be merged into ``impactlab.references``).
MODAL_REFERENCES: tuple[Reference, ...] = (
    Reference(
        "cowper-1966",
        "G. R. Cowper, The shear coefficient in Timoshenko's beam theory, J. Appl. Mech. 33 "
        "(1966) 335-340",
        "10.1115/1.3625046",
    ),
    Reference(
        "han-benaroya-wei-1999",
        "S. M. Han, H. Benaroya, T. Wei, Dynamics of transversely vibrating beams using four "
        "engineering theories, J. Sound Vib. 225 (1999) 935-988",
        "10.1006/jsvi.1999.2257",
    ),
    Reference(
        "huang-1961",
        "T. C. Huang, The effect of rotatory inertia and of shear deformation on the frequency "
        "and normal mode equations of uniform beams with simple end conditions, J. Appl. Mech. "
        "28 (1961) 579-584",
    ),
    Reference(
        "blevins-1979",
        "R. D. Blevins, Formulas for Natural Frequency and Mode Shape, Van Nostrand Reinhold "
        "(1979)",
    ),
    Reference(
        "dickens-nakagawa-wittbrodt-1997",
        "J. M. Dickens, J. M. Nakagawa, M. J. Wittbrodt, A critique of mode acceleration and "
        "modal truncation augmentation methods for modal response analysis, Computers & "
        "Structures (1997)",
    ),
)


@dataclass(frozen=True)
class ModalBasis:
    """Elastic free-free modes (mass-normalised) and their values at the two ends.

    ``omega`` (M,) [rad/s]; ``kind`` (M,) ``KIND_AXIAL`` / ``KIND_BENDING`` /
    ``KIND_AXIAL_RESIDUAL``; ``U``, ``W``, ``Psi`` (2, M): axial displacement [m], transverse
    displacement [m] and section rotation [rad] per unit modal coordinate [kg^1/2 m] at end 0
    (s = -L/2) and end 1 (s = +L/2); ``inertia``: I_C [kg m^2] consistent with ``theory``.
    """

    section: RodSection
    theory: str
    omega: np.ndarray
    kind: np.ndarray
    U: np.ndarray
    W: np.ndarray
    Psi: np.ndarray
    inertia: float

    @property
    def n_modes(self) -> int:
        """Number of elastic modes M."""
        return int(self.omega.size)

    @property
    def frequencies_hz(self) -> np.ndarray:
        """omega / (2 pi) [Hz]."""
        return self.omega / (2 * math.pi)


def _bending(
    sec: RodSection, n: int, theory: str, ends: np.ndarray
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(omega, W, Psi) of the first n bending modes at ``ends``."""
    W = np.zeros((2, n))
    psi = np.zeros((2, n))
    if theory == EULER_BERNOULLI:
        om = eb_frequencies(sec, n)
        for k in range(1, n + 1):
            W[:, k - 1] = eb_shape(sec, k, ends, 0)
            psi[:, k - 1] = eb_shape(sec, k, ends, 1)
    else:
        om = timoshenko_frequencies(sec, n)
        for k in range(n):
            Wk, Pk, _dP, _g = timoshenko_shape_fn(sec, om[k])(ends)
            W[:, k] = Wk
            psi[:, k] = Pk
    return om, W, psi


def modal_basis(
    sec: RodSection,
    n_axial: int,
    n_bending: int,
    theory: str = TIMOSHENKO,
    inertia: float | None = None,
    axial_residual: bool = False,
) -> ModalBasis:
    """``n_axial`` axial + ``n_bending`` bending modes (that order, each by frequency) with
    their end values; ``axial_residual`` appends the two axial residual pseudo-modes.
    ``inertia`` overrides the rigid body's I_C [kg m^2] (default: ``sec.inertia(theory)``)."""
    check_theory(theory)
    for name, n in (("n_axial", n_axial), ("n_bending", n_bending)):
        if not isinstance(n, int | np.integer) or isinstance(n, bool) or n < 0:
            raise ValueError(f"{name} must be an integer >= 0, got {n!r}")
        if n > _MAX_MODES:
            raise ValueError(f"{name} must be at most {_MAX_MODES}, got {int(n)}")
    if axial_residual and n_axial < 1:
        raise ValueError("axial_residual needs n_axial >= 1")
    M = n_axial + n_bending + (2 if axial_residual else 0)
    om = np.zeros(M)
    kind = np.zeros(M, dtype=np.int64)
    U = np.zeros((2, M))
    W = np.zeros((2, M))
    psi = np.zeros((2, M))
    ends = np.array([-0.5 * sec.length, 0.5 * sec.length])
    if n_axial:
        om[:n_axial] = axial_frequencies(sec, n_axial)
        for k in range(1, n_axial + 1):
            U[:, k - 1] = axial_shape(sec, k, ends)
    if n_bending:
        j1 = n_axial + n_bending
        kind[n_axial:j1] = KIND_BENDING
        om[n_axial:j1], W[:, n_axial:j1], psi[:, n_axial:j1] = _bending(
            sec, n_bending, theory, ends
        )
    if axial_residual:
        j0 = n_axial + n_bending
        om[j0:], U[:, j0:] = axial_residual_modes(sec, n_axial)
        kind[j0:] = KIND_AXIAL_RESIDUAL
    I_C = sec.inertia(theory) if inertia is None else float(inertia)
    for a in (om, kind, U, W, psi):
        a.setflags(write=False)
    return ModalBasis(sec, theory, om, kind, U, W, psi, I_C)


def rigid_modes(
    sec: RodSection, s: np.ndarray, theory: str = EULER_BERNOULLI
) -> tuple[tuple[np.ndarray, np.ndarray, np.ndarray], ...]:
    """The three planar rigid modes (omega = 0) at s [m], mass-normalised: (U, W, Psi) for the
    axial translation, the transverse translation and the rotation about C."""
    s = np.asarray(s, dtype=float)
    m = sec.mass
    I_C = sec.inertia(theory)
    one = np.ones_like(s)
    zero = np.zeros_like(s)
    return (
        (one / math.sqrt(m), zero, zero),
        (zero, one / math.sqrt(m), zero),
        (zero, s / math.sqrt(I_C), one / math.sqrt(I_C)),
    )
