"""The independent reference of the flexible drop: a corotational Timoshenko finite-element rod
(``impactlab.dynamics.flex_fe``) integrated by scipy's ``solve_ivp`` (SI units).

Contact, friction, gravity and the plastic history are the same physics as the modal model
(docs/flexible.md): the sphere centre is the end node, v_t = x' + R theta', the friction moment
is R F_t; the forces come from the same contact-law kernels (``impactlab.contact.kernels``);
but every switch (touch, turning point, reload, separation, elastic-plastic switch, stick/slip)
is a terminal event of ``solve_ivp`` (DOP853: Hairer, Norsett & Wanner, Solving Ordinary
Differential Equations I, Springer (1993), doi:10.1007/978-3-540-78862-1) and the integration
restarts after each. Stick: with lumped masses the stick force of an end node is
F_t = -(f_x / m_0 + R f_th / J_0) / (1 / m_0 + R^2 / J_0) (f: the other forces on the node).
The run stops at ``t_stop`` (give the modal model's duration plus a margin); the rigid-body
velocities come from the total momentum and the angular momentum about the centre of mass, so
e is comparable with the modal model's frame velocities. Used by the tests and the benchmark;
a drop takes about a second at 80 elements.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.contact.kernels import (
    P_ESTAR,
)
from impactlab.dynamics.flex_fe import CorotationalRod
from impactlab.dynamics.flex_fe_drop import FEDrop, FEEnd, switch_interference
from impactlab.dynamics.input_checks import gravity_value
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010, Material

__all__ = ["ReferenceDrop", "drop_reference"]


@dataclass(frozen=True)
class ReferenceDrop:
    """The reference's result (SI units): ``contacts`` (dicts named as ``ContactRecord``'s fields:
    end, start, duration, delta_max, x_start, x_end, delta_r, reload, dent), ``dents`` (dicts
    named as ``DentRecord``'s: end, x_min, x_max, contact_radius, delta_max, delta_p,
    unloading_radius, n_contacts), e, the rigid-body velocities and spin at
    ``t_stop``, the duration (first touch to last separation), delta_p, the scar length, the
    largest relative energy error, the vibration energy, the number of right-hand sides and the
    wall time [s]."""

    contacts: list[dict[str, Any]]
    dents: list[dict[str, Any]]
    e: float
    velocity_out: tuple[float, float]
    spin_out: float
    duration: float
    delta_p: float
    scar_length: float
    energy_error: float
    vibration_energy: float
    n_rhs: int
    wall_time: float


def _initial_state(fe: CorotationalRod, vx0: float, vy0: float, w0: float) -> np.ndarray:
    """Nodal positions and the rigid velocity field about C, plus the two work quadratures."""
    X = fe.X0.copy()
    xc = np.sum(fe.mass * X[0::3]) / fe.m
    yc = np.sum(fe.mass * X[1::3]) / fe.m
    V = np.zeros(X.size)
    V[0::3] = vx0 - w0 * (X[1::3] - yc)
    V[1::3] = vy0 + w0 * (X[0::3] - xc)
    V[2::3] = w0
    return np.concatenate([X, V, [0.0, 0.0]])


def _atol(fe: CorotationalRod, p: np.ndarray, vn0: float, rtol: float) -> np.ndarray:
    """Absolute tolerances from the rigid engine's Hertzian scales."""
    nd = 3 * fe.nn
    a0 = 0.5 * fe.L * math.cos(fe.th0)
    X = fe.X0
    xc = np.sum(fe.mass * X[0::3]) / fe.m
    yc = np.sum(fe.mass * X[1::3]) / fe.m
    I_c = np.sum(fe.mass * ((X[0::3] - xc) ** 2 + (X[1::3] - yc) ** 2)) + np.sum(fe.J)
    meff = 1.0 / (1.0 / fe.m + a0 * a0 / I_c)
    dstar = (15.0 * meff * vn0 * vn0 / (16.0 * p[P_ESTAR] * math.sqrt(fe.R))) ** 0.4
    atol = np.empty(2 * nd + 2)
    atol[0:nd:3] = dstar
    atol[1:nd:3] = dstar
    atol[2:nd:3] = dstar / fe.h
    atol[nd::3] = abs(vn0)
    atol[nd + 1 :: 3] = abs(vn0)
    atol[nd + 2 :: 3] = abs(vn0) / fe.h
    atol[-2:] = 0.5 * fe.m * vn0 * vn0
    return atol * rtol


def _integrate(
    run: FEDrop, y: np.ndarray, t_stop: float, rtol: float, atol: np.ndarray
) -> tuple[float, float, np.ndarray]:
    """Integrate from the first touch to ``t_stop``: (largest energy error [J], final time,
    final state)."""
    e0 = run.fe.energy(y)
    t, eerr, nev = 0.0, 0.0, 0
    while t < t_stop and nev < 20000:
        evs = run.events()
        sol = solve_ivp(
            run.rhs,
            (t, min(t_stop, t + 5e-5)),
            y,
            method="DOP853",
            rtol=rtol,
            atol=atol,
            events=[e[0] for e in evs],
        )
        run.track(sol.y)
        fired = [(i, te[0]) for i, te in enumerate(sol.t_events) if te.size]
        if not fired:
            t, y = sol.t[-1], sol.y[:, -1].copy()
            run.refresh_thresholds(y)
        else:
            i, t = min(fired, key=lambda a: a[1])
            y = sol.y_events[i][0].copy()
            nev += 1
            run.apply(y, t, evs[i][1], evs[i][2])
        eerr = max(eerr, abs(run.fe.energy(y) - e0 - y[-2] - y[-1]))
    return eerr, t, y


def _summary(run: FEDrop, y: np.ndarray, t: float, vn0: float) -> dict[str, Any]:
    fe = run.fe
    nd = run.nd
    X, V = y[:nd], y[nd : 2 * nd]
    vxc, vyc, w, Ic = fe.rigid_motion(X, V)
    ended = [c["start"] + c["duration"] for c in run.contacts if "duration" in c]
    T = max(ended) if ended else math.nan
    # chord angle, rotated back to the last separation (free spin w after it)
    th = math.atan2(X[3 * (fe.nn - 1) + 1] - X[1], X[3 * (fe.nn - 1)] - X[0]) - w * (t - T)
    e = -(vyc + fe.g * t - w * 0.5 * fe.L * math.cos(th)) / vn0  # gravity over [0, t] removed
    xs = [c[key] for c in run.contacts if c["end"] == 0 for key in ("x_start", "x_end") if key in c]
    xs += [dd[key] for dd in run.dents if dd["end"] == 0 for key in ("x_min", "x_max")]
    Vg = fe.g * np.sum(fe.mass * (X[1::3] - fe.X0[1::3]))
    ek = 0.5 * fe.m * (vxc**2 + vyc**2) + 0.5 * Ic * w * w
    return dict(
        e=e,
        velocity_out=(vxc, vyc),
        spin_out=w,
        duration=T,
        delta_p=max((dd["delta_p"] for dd in run.dents), default=0.0),
        scar_length=max(xs) - min(xs),
        vibration_energy=fe.energy(y) - Vg - ek,
    )


def drop_reference(
    body: FlexibleRod,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    mu: float = 0.0,
    angle: float,
    velocity: tuple[float, float],
    spin: float = 0.0,
    gravity: bool | float = True,
    t_stop: float,
    n_elements: int = 80,
    rtol: float = 1e-8,
) -> ReferenceDrop:
    """The drop of ``body`` (its length, mass, material, diameter; the modes are not used) by
    the corotational finite-element reference, from the first touch of the tip to ``t_stop``
    [s], with Coulomb friction mu; angle [rad], velocity [m/s], spin [rad/s] as in
    ``simulate_drop``."""
    wall = time.perf_counter()
    g = gravity_value(gravity)
    fe = CorotationalRod.from_body(body, n_elements, angle, g)
    model = contact_model(body.rigid(), flat, law)
    p = kernel_params(model)
    vx0, vy0 = velocity
    vn0 = vy0 - spin * 0.5 * fe.L * math.cos(angle)
    run = FEDrop(
        fe, model.law_id, p, mu, [FEEnd(rr=fe.R, dsw=switch_interference(p)) for _ in range(2)]
    )
    y = _initial_state(fe, vx0, vy0, spin)
    run.touch(y, 0.0, 0)
    eerr, t, y = _integrate(run, y, t_stop, rtol, _atol(fe, p, vn0, rtol))
    s = _summary(run, y, t, vn0)
    ke0 = 0.5 * fe.m * (vx0**2 + vy0**2)
    return ReferenceDrop(
        run.contacts,
        run.dents,
        energy_error=eerr / ke0,
        n_rhs=run.n_rhs,
        wall_time=time.perf_counter() - wall,
        **s,
    )
