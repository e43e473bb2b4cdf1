"""The exact Mindlin-Deresiewicz reference for an elastic sphere's oblique Hertz impact (no
gravity, no initial spin), independent of the ``partial_slip`` engine: the method of
dimensionality reduction (Popov & Hess, Facta Univ. Mech. Eng. 12 (2014) 1) with uniform
elements on 1.02 times the Hertz estimate of the largest contact radius and a fixed-step
velocity-Verlet integration (no cells, no events). It computes ``NU_EXACT`` of
``impactlab.verification.partial_slip``: ``python -m impactlab.verification.partial_slip_mdr``
prints its rows (3200 elements, 128 000 steps each; minutes). With 1600 and 3200 elements e_t
agrees to 5e-6 at every row; ``MBF_EXACT`` and ``KGS_EXACT`` (the older 600-element reference)
are reproduced to 4e-5.
"""

from __future__ import annotations

import math

import numba
import numpy as np

from impactlab.materials import ContactPair
from impactlab.verification.partial_slip import NU_EXACT, SphereCase, nu_case

__all__ = ["exact_sphere", "nu_table"]


@numba.njit(cache=False)
def _mdr(
    m: float, inertia: float, radius: float, e_star: float, g_star: float, mu: float,
    vn: float, vt: float, n_el: int, n_steps: int,
) -> tuple[float, float, float]:  # fmt: skip
    """(normal velocity out, tangential velocity out [m/s], spin out [rad/s]) of a sphere of
    mass ``m`` [kg], ``inertia`` [kg m^2] and ``radius`` [m] hitting a flat at approach speed
    ``vn`` > 0 and tangential speed ``vt`` [m/s]: ``n_el`` elements, ``n_steps`` steps over the
    Hertz duration."""
    d_max = (15.0 * m * vn**2 / (16.0 * e_star * math.sqrt(radius))) ** 0.4
    dt = 2.9432 * d_max / vn / n_steps
    h = 1.02 * math.sqrt(radius * d_max) / n_el
    x = (np.arange(n_el) + 0.5) * h
    w = np.zeros(n_el)  # element displacements [m]
    g1 = 4.0 * g_star  # tangential stiffness per unit length of the line [Pa]
    d, vd, vx, om, fn, ft = 0.0, vn, vt, 0.0, 0.0, 0.0
    started = False
    while True:
        vd_h = vd - 0.5 * dt * fn / m
        vx_h = vx + 0.5 * dt * ft / m
        om_h = om + 0.5 * dt * radius * ft / inertia
        vs = vx_h + om_h * radius  # slip velocity of the contact point
        d += vd_h * dt
        a = math.sqrt(radius * d) if d > 0.0 else 0.0
        s = 0.0
        for j in range(n_el):
            if x[j] < a:
                lim = mu * e_star * (d - x[j] * x[j] / radius) / g1
                w[j] = min(max(w[j] + vs * dt, -lim), lim)
                s += w[j]
            else:
                w[j] = 0.0
        ft = -2.0 * g1 * h * s
        fn = 4.0 / 3.0 * e_star * math.sqrt(radius) * d**1.5 if d > 0.0 else 0.0
        vd = vd_h - 0.5 * dt * fn / m
        vx = vx_h + 0.5 * dt * ft / m
        om = om_h + 0.5 * dt * radius * ft / inertia
        started = started or d > 0.0
        if started and d <= 0.0:
            return -vd, vx, om


def exact_sphere(case: SphereCase, vt: float, n_elements: int = 3200) -> dict[str, float]:
    """The exact M-D impact of ``case`` (a ``SphereCase`` with the Hertz law) at tangential
    velocity ``vt`` [m/s]: e, e_t, spin [rad/s] and psi2 = eta v_slip,out / (mu |v_n|);
    ``n_elements`` elements and 40 steps per element."""
    if case.law != "hertz":
        raise ValueError(f"case.law = {case.law!r}: the reference solves the 'hertz' law only")
    if n_elements < 10:
        raise ValueError(f"n_elements = {n_elements}: at least 10 elements are needed")
    body, vn, mu = case.body, case.vn, case.mu
    pair = ContactPair(body.material, case.flat)
    vn_out, vx, om = _mdr(
        case.mass, float(body.inertia), float(body.radius), pair.E_star, pair.G_star, mu, vn,
        vt, n_elements, 40 * n_elements,
    )  # fmt: skip
    vslip = vx + om * body.radius
    eta = 4.0 * pair.G_star / pair.E_star
    return {"e": vn_out / vn, "et": vx / vt, "spin": om, "psi2": eta * vslip / (mu * vn)}


def nu_table(n_elements: int = 3200) -> np.ndarray:
    """The rows of ``NU_EXACT``: nu, psi1, e_t, psi2 at every (nu, psi1) it lists."""
    rows = []
    for nu, psi1, _et, _psi2 in NU_EXACT:
        case = nu_case(float(nu))
        r = exact_sphere(case, psi1 * case.mu * case.vn / case.eta, n_elements)
        rows.append((nu, psi1, r["et"], r["psi2"]))
    return np.array(rows)


if __name__ == "__main__":  # pragma: no cover
    for row in nu_table():
        print(f"[{row[0]:.2f}, {row[1]:g}, {row[2]:.6f}, {row[3]:.6f}]")
