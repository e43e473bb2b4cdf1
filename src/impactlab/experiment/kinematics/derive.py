"""The impact quantities from the two free-flight fits: instant, velocities, e and mu."""

from __future__ import annotations

import math

import numpy as np
from scipy.optimize import brentq

from impactlab.bodies import lever_arms

__all__ = ["DERIVED", "derive"]

#: Names of the derived quantities, in the order of :func:`derive`'s output.
DERIVED = (
    "t_impact",
    "angle_in",
    "angle_out",
    "v_cx_in",
    "v_cy_in",
    "spin_in",
    "v_cx_out",
    "v_cy_out",
    "spin_out",
    "v_tip_x_in",
    "v_tip_y_in",
    "v_tip_x_out",
    "v_tip_y_out",
    "e",
    "mu",
    "dv_cx",
    "dv_cy",
    "v_cz_in",
    "v_cz_out",
)


def derive(
    x: np.ndarray,
    t_ref: float,
    tau_lo: float,
    tau_hi: float,
    g: float,
    half: float,
    R_tip: float,
    notes: list[str],
) -> np.ndarray:
    """The derived quantities (order ``DERIVED``) from the 16 fit coefficients (before, after).

    The impact instant is where the extrapolated tip heights of the two fits cross (between
    ``tau_lo`` and ``tau_hi`` [s] from ``t_ref``); there the angle, the velocities of C and of
    the contact point (lever arms of ``half`` = L/2 and ``R_tip`` [m]), e and mu follow. A note
    goes to ``notes`` when the heights do not cross."""
    a_, b_ = x[:8], x[8:]

    def tip_h(c: np.ndarray, tau: float) -> float:
        Y = c[2] + c[3] * tau - 0.5 * g * tau * tau
        return float(Y - half * math.sin(c[6] + c[7] * tau))

    def f(tau: float) -> float:
        return tip_h(a_, tau) - tip_h(b_, tau)

    flo, fhi = f(tau_lo), f(tau_hi)
    if flo > 0 > fhi:
        tau_i = float(brentq(f, tau_lo, tau_hi, xtol=1e-12))
    else:
        # no crossing between the segments: the linearised crossing, clipped
        tau_i = tau_lo - flo * (tau_hi - tau_lo) / (fhi - flo) if fhi != flo else 0.0
        tau_i = min(max(tau_i, tau_lo), tau_hi)
        if not notes:
            notes.append(
                "the extrapolated tip heights do not cross between the fits; the "
                "impact instant is approximate"
            )
    vals = []
    for c in (a_, b_):
        th = c[6] + c[7] * tau_i
        vx, vy, vz, om = c[1], c[3] - g * tau_i, c[5], c[7]
        ra, rb = lever_arms(half, R_tip, th)
        vals.append((th, vx, vy, om, vx + om * rb, vy - om * ra, vz))
    (thi, vxi, vyi, omi, txi, tyi, vzi), (tho, vxo, vyo, omo, txo, tyo, vzo) = vals
    dvx, dvy = vxo - vxi, vyo - vyi
    e = -tyo / tyi if tyi != 0 else math.nan
    mu = abs(dvx / dvy) if dvy != 0 else math.nan
    return np.array(
        [
            t_ref + tau_i,
            thi,
            tho,
            vxi,
            vyi,
            omi,
            vxo,
            vyo,
            omo,
            txi,
            tyi,
            txo,
            tyo,
            e,
            mu,
            dvx,
            dvy,
            vzi,
            vzo,
        ]
    )
