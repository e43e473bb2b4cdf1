"""Quasi-static energy bookkeeping of a contact law: loading work, rebound of a point mass.

For a point mass m hitting the flat at normal speed V with the contact law as the only force,
the maximum interference delta_m solves W(delta_m) = 1/2 m V^2 with W the work of the loading
curve, and the rebound energy is the work returned by the unloading branch, so
e = sqrt(W_out / W_in). This is exact for the law (no integration of the motion in time) and is
what Thornton's closed form assumes; it is a reference for the impact engine's tests.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

from impactlab._validation import check_nonnegative, check_positive
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.contact.curve_table import curve_nodes


@dataclass(frozen=True)
class ReboundResult:
    """Quasi-static normal rebound of a point mass (SI units)."""

    mass: float
    speed: float
    delta_m: float
    F_m: float
    delta_r: float
    R_r: float
    work_in: float
    work_out: float

    @property
    def restitution(self) -> float:
        """Coefficient of restitution e = sqrt(work_out / work_in)."""
        return math.sqrt(self.work_out / self.work_in) if self.work_in > 0.0 else 1.0


def _breakpoints(model: ContactModel, upper: float) -> list[float]:
    pts = {model.switch_interference, model.yield_onset[0]}
    dc = model.details.get("delta_c")
    if dc is not None:
        pts.add(k.JG_AREA_SWITCH * dc)
    if model.law_id == k.TABULATED:  # the nodes of its table, where the cubics join
        pts.update(curve_nodes(model.params).tolist())
    return sorted(x for x in pts if 0.0 < x < upper and math.isfinite(x))


def loading_work(model: ContactModel, delta_m: float) -> float:
    """Work of the loading curve from 0 to ``delta_m`` [J] (numerical quadrature)."""
    from scipy.integrate import quad  # on first use: ``import impactlab`` stays light

    dm = float(model.check_interference(check_nonnegative("delta_m", delta_m, "m")))
    if dm == 0.0:
        return 0.0
    law, p = model.law_id, model.params
    edges = [0.0, *_breakpoints(model, dm), dm]
    total = 0.0
    for a, b in itertools.pairwise(edges):
        val, _ = quad(
            lambda x: k.loading_force(law, p, x), a, b, epsabs=0.0, epsrel=1e-11, limit=200
        )
        total += val
    return total


def quasi_static_rebound(model: ContactModel, mass: float, speed: float) -> ReboundResult:
    """Rebound of a point mass ``mass`` [kg] hitting the flat at normal ``speed`` [m/s].

    ValueError if the maximum interference would exceed the law's validity limit.
    """
    from scipy.optimize import brentq  # on first use: ``import impactlab`` stays light

    m = check_positive("mass", mass, "kg")
    v = check_positive("speed", speed, "m/s")
    w_in = 0.5 * m * v * v
    dlim = model.max_interference
    w_lim = loading_work(model, dlim)
    if w_lim < w_in:
        raise ValueError(
            f"speed = {v!r} m/s drives the {model.name!r} law past its validity limit "
            f"(delta > {dlim!r} m); the largest admissible speed is "
            f"{math.sqrt(2.0 * w_lim / m):.6g} m/s"
        )
    hi = min(dlim, 1e-12 * model.radius)
    while loading_work(model, hi) < w_in:
        hi = min(dlim, hi * 4.0)
    dm = brentq(lambda x: loading_work(model, x) - w_in, 0.0, hi, xtol=1e-16, rtol=1e-13)
    branch = model.unload(dm)
    return ReboundResult(
        mass=m,
        speed=v,
        delta_m=branch.delta_m,
        F_m=branch.F_m,
        delta_r=branch.delta_r,
        R_r=branch.R_r,
        work_in=w_in,
        work_out=branch.energy_returned(),
    )
