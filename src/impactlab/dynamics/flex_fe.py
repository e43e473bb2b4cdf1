"""A corotational Timoshenko finite-element rod: the independent discretisation behind
``impactlab.dynamics.flex_reference`` (SI units).

Why independent of the modal model: no modes and no floating frame. The rod is ``n_elements``
two-node planar beam elements in absolute nodal coordinates (x_i, y_i, theta_i) with the
corotational formulation for large rigid rotations (M. A. Crisfield, Non-linear Finite Element
Analysis of Solids and Structures, Vol. 1, Wiley (1991), its chapter on corotational beam
elements; chapter number not confirmed here): each element's local deformations are the
stretch l - l0 and the two nodal rotations relative to the chord, and its internal forces are
the exact gradient of the strain energy

    U_e = 1/2 EA (l - l0)^2 / l0 + 1/2 [t1 t2] K_b [t1 t2]^T,
    K_b = EI / (l0 (1 + Phi)) [[4 + Phi, 2 - Phi], [2 - Phi, 4 + Phi]],  Phi = 12 EI / (kGA l0^2),

the shear-flexible Timoshenko beam element, exact in statics (J. S. Przemieniecki, Theory of
Matrix Structural Analysis, McGraw-Hill (1968), its beam element with shear deformation;
section not confirmed here). Masses are lumped: rho A l0 / 2 and
the rotary inertia rho I l0 / 2 per element end. All inertial couplings (centrifugal,
Coriolis) and the geometric nonlinearity are therefore kept; the scheme converges to the
Timoshenko beam at O(h^2) in the frequencies.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.bodies.flexible_rod import FlexibleRod

__all__ = ["CorotationalRod"]


class CorotationalRod:
    """A uniform rod of ``n_elements`` corotational Timoshenko elements with hemispherical ends
    of radius R centred on the end nodes, at ``angle`` [rad] to the flat, node 0 (the tip)
    touching the flat y = 0 at x = 0. Lengths [m], mass [kg], moduli [Pa], g [m/s^2]."""

    def __init__(
        self,
        n_elements: int,
        section: tuple[float, float, float, float, float, float],
        tip_radius: float,
        angle: float,
        gravity: float,
    ) -> None:
        """``section`` = (L, m, E, nu, d, kappa)."""
        L, m, E, nu, d, kappa = section
        self.Ne = int(n_elements)
        self.L, self.m, self.R, self.th0, self.g = L, m, tip_radius, angle, gravity
        h = L / self.Ne
        self.h = h
        A = math.pi * d * d / 4.0
        Iy = math.pi * d**4 / 64.0
        G = E / (2.0 * (1.0 + nu))
        self.EA = E * A
        self.EI = E * Iy
        phi = 12.0 * self.EI / (kappa * G * A * h * h)
        c = self.EI / (h * (1.0 + phi))
        self.kb11 = c * (4.0 + phi)
        self.kb12 = c * (2.0 - phi)
        nn = self.Ne + 1
        self.nn = nn
        self.mass = np.full(nn, m / L * h)
        self.J = np.full(nn, m / L * Iy / A * h)
        for a in (self.mass, self.J):
            a[0] *= 0.5
            a[-1] *= 0.5
        self.minv = np.empty(3 * nn)
        self.minv[0::3] = 1.0 / self.mass
        self.minv[1::3] = 1.0 / self.mass
        self.minv[2::3] = 1.0 / self.J
        s = np.arange(nn) * h
        sc = s - np.sum(self.mass * s) / m
        self.Ic0 = float(np.sum(self.mass * sc * sc) + np.sum(self.J))  # undeformed I_C
        self.X0 = np.zeros(3 * nn)
        self.X0[0::3] = s * math.cos(angle)
        self.X0[1::3] = tip_radius + s * math.sin(angle)

    @classmethod
    def from_body(
        cls, body: FlexibleRod, n_elements: int, angle: float, gravity: float
    ) -> CorotationalRod:
        """The mesh of ``body`` (its length, mass, material, diameter, shear coefficient)."""
        sec = body.section
        return cls(
            n_elements,
            (sec.length, sec.mass, sec.E, sec.nu, sec.d, sec.kappa),
            body.tip_radius,
            angle,
            gravity,
        )

    def internal(self, X: np.ndarray) -> tuple[np.ndarray, float]:
        """Internal force vector (gradient of the strain energy) [N, N m] and the strain
        energy [J] at the nodal coordinates X."""
        x = X[0::3]
        y = X[1::3]
        t = X[2::3]
        dx = x[1:] - x[:-1]
        dy = y[1:] - y[:-1]
        lc = np.hypot(dx, dy)
        c = dx / lc
        s = dy / lc
        alpha = np.arctan2(dy, dx) - self.th0
        alpha = (alpha + math.pi) % (2 * math.pi) - math.pi
        t1 = t[:-1] - alpha
        t2 = t[1:] - alpha
        u = lc - self.h
        N = self.EA * u / self.h
        M1 = self.kb11 * t1 + self.kb12 * t2
        M2 = self.kb12 * t1 + self.kb11 * t2
        Ms = (M1 + M2) / lc
        f = np.zeros_like(X)
        fx = -c * N - s * Ms
        fy = -s * N + c * Ms
        f[0:-3:3] += fx
        f[1:-3:3] += fy
        f[2:-3:3] += M1
        f[3::3] -= fx
        f[4::3] -= fy
        f[5::3] += M2
        U = 0.5 * np.sum(N * u) + 0.5 * np.sum(M1 * t1 + M2 * t2)
        return f, float(U)

    def energy(self, yy: np.ndarray) -> float:
        """Kinetic + strain + gravity energy [J] (gravity from the initial pose) of the state
        yy = (X, V, ...)."""
        nd = 3 * self.nn
        X = yy[:nd]
        V = yy[nd : 2 * nd]
        _f, U = self.internal(X)
        T = 0.5 * np.sum(V * V / self.minv)
        Vg = self.g * np.sum(self.mass * (X[1::3] - self.X0[1::3]))
        return float(T + U + Vg)

    def rigid_motion(self, X: np.ndarray, V: np.ndarray) -> tuple[float, float, float, float]:
        """(vx, vy, spin, I_C) of the rigid motion: total momentum, and the angular momentum
        about the centre of mass over the undeformed I_C, the rigid body's (the modal model's
        frame spin; the deformed I_C rings with the axial modes, 1e-4 after the paper's 70 deg
        drop, and a spin over it with them) [m/s, m/s, rad/s, kg m^2]."""
        ms, m = self.mass, self.m
        xc = np.sum(ms * X[0::3]) / m
        yc = np.sum(ms * X[1::3]) / m
        vxc = np.sum(ms * V[0::3]) / m
        vyc = np.sum(ms * V[1::3]) / m
        rx = X[0::3] - xc
        ry = X[1::3] - yc
        Lc = np.sum(ms * (rx * (V[1::3] - vyc) - ry * (V[0::3] - vxc))) + np.sum(self.J * V[2::3])
        return float(vxc), float(vyc), float(Lc / self.Ic0), self.Ic0

    def eigenfrequencies(self, n: int) -> np.ndarray:
        """Lowest n elastic circular frequencies [rad/s] of the model linearised about the
        initial pose (finite-difference stiffness; the three rigid modes dropped)."""
        X = self.X0.copy()
        nd = X.size
        K = np.empty((nd, nd))
        eps = 1e-7
        for j in range(nd):
            Xp = X.copy()
            Xp[j] += eps
            Xm = X.copy()
            Xm[j] -= eps
            K[:, j] = (self.internal(Xp)[0] - self.internal(Xm)[0]) / (2 * eps)
        K = 0.5 * (K + K.T)
        sq = np.sqrt(self.minv)
        w2 = np.sort(np.linalg.eigvalsh(sq[:, None] * K * sq[None, :]))[3:]
        return np.sqrt(np.abs(w2[:n]))
