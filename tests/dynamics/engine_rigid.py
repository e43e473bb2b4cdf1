"""Rigid-body impulse solution of a planar impact with Coulomb friction (test oracle).

Stronge, Impact Mechanics (2000), Ch. 5, doi:10.1017/CBO9780511626432: with the normal impulse
P as the independent variable, the contact-point velocities of a body with fixed lever arms
(a, b) are linear in (P_t, P):

    v_t = v_t0 + B11 P_t - B12 P,   v_n = v_n0 - B12 P_t + B22 P,
    B11 = 1/m + b^2/I,  B12 = a b / I,  B22 = 1/m + a^2/I.

Slip with direction s: dP_t/dP = -s mu; stick: dP_t/dP = B12/B11 (needs mu >= |B12|/B11).
The impact ends when the work of the normal force, W(P) = int_0^P v_n dP', returns to
-(1 - e*^2) W_c; for the elastic (Hertz) contact e* = 1, i.e. W = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass


@dataclass(frozen=True)
class RigidResult:
    vt: float
    vn: float
    P: float
    Pt: float
    regime: str


def rigid_impact(
    m: float, inertia: float, a: float, b: float, vt0: float, vn0: float, mu: float
) -> RigidResult:
    B11 = 1.0 / m + b * b / inertia
    B12 = a * b / inertia
    B22 = 1.0 / m + a * a / inertia
    mu_c = abs(B12) / B11

    def slopes(mode: float) -> tuple[float, float]:
        if mode == 0.0:  # stick
            return 0.0, B22 - B12 * B12 / B11
        return -mode * mu * B11 - B12, mode * mu * B12 + B22

    if vt0 != 0.0:
        mode = math.copysign(1.0, vt0)
    elif mu >= mu_c:
        mode = 0.0
    else:
        mode = -math.copysign(1.0, B12) if B12 != 0.0 else 0.0
    P = Pt = W = 0.0
    vt, vn = vt0, vn0
    modes = [mode]
    for _ in range(10):
        st, sn = slopes(mode)
        # impulse to the next stick/slip transition
        x_tr = math.inf
        if mode != 0.0 and st * vt < 0.0:
            x_tr = -vt / st
        # impulse to the end: W + vn x + sn x^2 / 2 = 0 with v_n > 0
        disc = vn * vn - 2.0 * sn * W
        x_end = (-vn + math.sqrt(disc)) / sn if sn > 0.0 and disc >= 0.0 else math.inf
        if x_end <= x_tr:
            dPt = x_end * (B12 / B11 if mode == 0.0 else -mode * mu)
            P += x_end
            Pt += dPt
            vt += st * x_end
            vn += sn * x_end
            break
        x = x_tr
        W += vn * x + 0.5 * sn * x * x
        P += x
        Pt += x * (B12 / B11 if mode == 0.0 else -mode * mu)
        vt = 0.0
        vn += sn * x
        mode = 0.0 if mu >= mu_c else (-math.copysign(1.0, B12) if B12 != 0.0 else 0.0)
        modes.append(mode)
    slip_dirs = {md for md in modes if md != 0.0}
    if len(slip_dirs) > 1:
        regime = "reversal"
    elif 0.0 in modes:
        regime = "stick"
    else:
        regime = "slip"
    return RigidResult(vt=vt, vn=vn, P=P, Pt=Pt, regime=regime)
