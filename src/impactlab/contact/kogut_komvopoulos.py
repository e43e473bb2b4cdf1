"""Kogut & Komvopoulos (2004): spherical indentation of an elastic-perfectly plastic solid,
as used by the paper (Sec. 3.3).

With the truncated radius r' = sqrt(R^2 - (R - delta)^2) = sqrt(delta (2R - delta)), the
truncated area a' = pi r'^2 and eps = E*/S_y:

- elastic (paper Eq. 20 with the prefactor corrected to 2 sqrt(2)/(3 pi)):
  F/(a' S_y) = (2 sqrt2/(3 pi)) eps delta/r', i.e. F = (2 sqrt2/3) E* delta r'
  = Hertz * sqrt(1 - delta/(2R)); the printed 4 sqrt2/(3 pi) gives twice Hertz;
- yield (published switch): delta/r' = 1.78 S_y/E*, i.e. delta_y = 2 R t_s^2 / (1 + t_s^2),
  t_s = 1.78/eps (the Hertz peak pressure is then 1.60 S_y);
- elastic-plastic (Eq. 21): F/(a' S_y) = [0.839 + ln(eps^0.656 (delta/r')^0.651)]
  / [2.192 - ln(eps^0.394 (delta/r')^0.419)];
- residual (Eq. 22): delta_r = delta_m (1 - 0.591 eps^-0.156) for delta_m > delta_y, else 0;
  unloading Hertzian with R_r from continuity.

Eq. 21 lies ~11 % above the elastic curve at the published switch for the paper's pair; the
default switches where Eq. 21 falls below the elastic curve (continuous, at ~2 delta_y);
``published_switch=1`` keeps the published switch and its jump. The hard limit is where
F/F_elastic has its minimum (beyond it Eq. 21 stiffens towards the pole where its denominator
vanishes), or delta = R.

Reference: L. Kogut, K. Komvopoulos, Analysis of the spherical indentation cycle for elastic-
perfectly plastic solids, J. Mater. Res. 19 (2004) 3641-3653, doi:10.1557/JMR.2004.0468.
See docs/laws/kogut-komvopoulos.md.
"""

from __future__ import annotations

import math

import numpy as np

from impactlab.contact import kernel_arrays as ka
from impactlab.contact import kernels as k
from impactlab.contact._common import (
    check_switch,
    curves,
    pair_constants,
    switch_point,
)
from impactlab.contact.base import ContactLaw, Parameter
from impactlab.contact.names import Law
from impactlab.contact.ranges import calibrated_max
from impactlab.materials import ContactPair


def _delta_at_ratio(t: float, R: float) -> float:
    """Interference where delta/r' = t (inverse of t(delta) = delta/sqrt(delta (2R - delta)))."""
    return 2.0 * R * t * t / (1.0 + t * t)


class KogutKomvopoulos(ContactLaw):
    law = Law.KOGUT_KOMVOPOULOS
    title = "Kogut-Komvopoulos indentation model, the paper's Sec. 3.3"
    reference = "Kogut, Komvopoulos, J. Mater. Res. 19 (2004) 3641-3653; paper Eqs. 20-22"
    validity = (
        "rigid sphere indenting an elastic-perfectly plastic half-space, frictionless; hard "
        "limit: minimum of F/F_elastic of Eq. 21 (before the pole of its denominator) or R"
    )
    parameters = (
        Parameter(
            "published_switch",
            0.0,
            "1",
            "0: switch from the elastic branch to Eq. 21 where Eq. 21 falls below it "
            "(continuous, default); 1: switch at delta/r' = 1.78 S_y/E* as published",
        ),
    )

    def _fill(self, p: np.ndarray, pair: ContactPair, values: dict[str, float]) -> dict[str, float]:
        published = check_switch(values["published_switch"])
        E, R, Sy, _ = pair_constants(p)
        eps = E / Sy
        ts = 1.78 / eps
        if ts >= 1.0:
            raise ValueError(
                f"Kogut-Komvopoulos needs E*/S_y > 1.78, got {eps!r}; check the materials"
            )
        res = 1.0 - 0.591 * eps**-0.156
        if not 0.0 < res < 1.0:
            raise ValueError(f"Kogut-Komvopoulos Eq. 22 is undefined for E*/S_y = {eps!r}")
        p[k.P_KK_EPS] = eps
        p[k.P_KK_RES] = res
        dy = _delta_at_ratio(ts, R)
        p[k.P_DY] = dy
        p[k.P_FY] = float(k.kk_elastic_force(p, dy))
        # Pole of Eq. 21: its denominator vanishes at ln t0 = (2.192 - 0.394 ln eps)/0.419.
        t0 = math.exp((2.192 - 0.394 * math.log(eps)) / 0.419)
        d_pole = _delta_at_ratio(t0, R) if t0 < 1.0 else R
        d_end = min(R, d_pole) * (1.0 - 1e-9)

        ep, el = curves(ka.GAP_KOGUT_KOMVOPOULOS, p)
        failure = (
            f"Kogut-Komvopoulos Eq. 21 never falls below the elastic curve for E*/S_y = {eps!r}; "
            "use published_switch=1"
        )
        search = (1e-4 * dy, d_end)
        d_sw, jump = switch_point(p, ka.GAP_KOGUT_KOMVOPOULOS, dy, search, published, failure)
        p[k.P_DSW] = d_sw
        # Hard limit: the minimum of F_ep / F_el beyond the switch.
        grid = np.geomspace(max(d_sw, dy), d_end, 2000)
        ratio = np.array([ep(float(x)) / el(float(x)) for x in grid])
        i = int(np.argmin(ratio))
        if 0 < i < grid.size - 1:
            from scipy.optimize import minimize_scalar  # on first use: light ``import impactlab``

            opt = minimize_scalar(
                lambda lx: ep(math.exp(lx)) / el(math.exp(lx)),
                bounds=(math.log(grid[i - 1]), math.log(grid[i + 1])),
                method="bounded",
                options={"xatol": 1e-10},
            )
            dlim = math.exp(float(opt.x))
        else:
            dlim = float(grid[i])
        p[k.P_DLIM] = dlim
        return {
            "eps": eps,
            "t_yield": ts,
            "delta_y": dy,
            "F_y": float(p[k.P_FY]),
            "switch_interference": d_sw,
            "switch_ratio": d_sw / dy,
            "switch_force": float(k.loading_force(k.KOGUT_KOMVOPOULOS, p, d_sw)),
            "published_jump": jump,
            "residual_ratio": res,
            "pole_interference": d_pole,
            "calibrated_max_interference": calibrated_max(self.law, dy, dlim, p),
        }
