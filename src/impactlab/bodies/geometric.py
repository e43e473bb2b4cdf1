"""Geometric stiffness of the flexible rod: the axial force acting on the bending slope.

The second-order stretch of a beam in its floating frame adds the cubic potential
V_g = 1/2 int EA u' w'^2 ds = 1/2 sum_abc T_abc q_a q_b q_c with
T_abc = int EA U_a'(s) W_b'(s) W_c'(s) ds (a: axial modes and axial pseudo-modes; b, c: bending
modes; w' is the centreline slope, Psi + gamma for Timoshenko). This is the geometric
stiffening of flexible multibody dynamics (e.g. A. A. Shabana, Dynamics of Multibody Systems,
3rd ed., Cambridge University Press (2005), doi:10.1017/CBO9780511610523, its treatment of
geometric nonlinearity in the floating frame; section not confirmed here), neglected by the
linear modal model. It matters where the contact force approaches the rod's Euler load (the
paper's 70 deg drop: 12 kN, about 17 % of it). SI units.
"""

from __future__ import annotations

import numpy as np

from impactlab.bodies.beam_modes import axial_slope, eb_shape
from impactlab.bodies.modal import KIND_AXIAL, KIND_AXIAL_RESIDUAL, KIND_BENDING, ModalBasis
from impactlab.bodies.residual import axial_residual_slopes
from impactlab.bodies.rod_section import EULER_BERNOULLI, gauss
from impactlab.bodies.timoshenko import timoshenko_shape_fn

__all__ = ["geometric_tensor"]


def geometric_tensor(b: ModalBasis, panels: int = 48) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(T (na, nb, nb), axial indices (na,), bending indices (nb,)): the geometric-stiffness
    tensor of ``b`` (SI: V_g in J for modal coordinates in kg^1/2 m) by composite
    Gauss-Legendre quadrature on ``panels`` panels; the indices point into ``b.omega``."""
    sec = b.section
    L = sec.length
    ia = np.where(b.kind != KIND_BENDING)[0]
    ib = np.where(b.kind == KIND_BENDING)[0]
    x, w = gauss(L, panels)
    s = x - 0.5 * L
    dU = np.empty((s.size, ia.size))
    for j, idx in enumerate(ia):
        if b.kind[idx] == KIND_AXIAL:
            dU[:, j] = axial_slope(sec, int(idx) + 1, s)
    pseudo = [j for j, idx in enumerate(ia) if b.kind[idx] == KIND_AXIAL_RESIDUAL]
    if pseudo:
        n_ax = int(np.sum(b.kind == KIND_AXIAL))
        dU[:, pseudo] = axial_residual_slopes(sec, n_ax, s)
    dW = np.empty((s.size, ib.size))
    for j in range(ib.size):
        if b.theory == EULER_BERNOULLI:
            dW[:, j] = eb_shape(sec, j + 1, s, 1)
        else:
            _W, Pv, _dP, gam = timoshenko_shape_fn(sec, float(b.omega[ib[j]]))(s)
            dW[:, j] = Pv + gam
    EA = sec.E * sec.area
    T = np.einsum("q,qa,qb,qc->abc", w * EA, dU, dW, dW)
    return np.ascontiguousarray(T), ia.astype(np.int64), ib.astype(np.int64)
