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
The run stops at ``t_stop`` (give the modal model's duration plus a margin; a ``t_stop`` that
ends before the sequence does warns, ``SequenceOpenWarning``: ``open_sequence``); the rigid-body
velocities come from the total momentum and the angular momentum about the centre of mass over
the undeformed I_C, and the angle from the best fit of the undeformed rod (``rigid_angle``), so
e is comparable with the modal model's frame velocities and does not depend on ``t_stop``.
Used by the tests and the benchmark; a drop takes about a second at 80 elements.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.bodies.flexible_rod import FlexibleRod
from impactlab.contact import ContactModel
from impactlab.contact.kernels import (
    P_ESTAR,
)
from impactlab.dynamics.drop_body import body_model
from impactlab.dynamics.flex_fe import CorotationalRod
from impactlab.dynamics.flex_fe_drop import FEDrop, FEEnd, switch_interference
from impactlab.dynamics.flexcore.layout import HORIZON_CAP, NEW_IMPACT_CHECKS
from impactlab.dynamics.input_checks import gravity_value
from impactlab.dynamics.models import contact_model, kernel_params
from impactlab.materials import AISI_1010, Material

__all__ = [
    "ReferenceDrop",
    "SequenceOpenWarning",
    "drop_reference",
    "open_sequence",
    "rigid_angle",
]


class SequenceOpenWarning(UserWarning):
    """The reference stopped at ``t_stop`` before its sequence ended (``open_sequence``): its
    e, velocities, duration and contacts are those of a sequence cut short."""


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


def _first_below(clear: Any, vy: float, w: float, g: float, horizon: float) -> float:
    """First tau in [0, horizon] [s] at which the clearance ``clear(tau)`` [m] may reach 0
    (conservative advancement with the speed bound |vy - g tau| + w [m/s], as the engine's
    ``flight.first_below``); horizon + 1 if it stays above."""
    tau = 0.0
    for _ in range(100000):
        h = clear(tau)
        if h <= 0.0:
            return tau
        v0 = abs(vy - g * tau) + w
        rhs = 0.9 * h
        if g > 0.0:
            dt = (-v0 + math.sqrt(v0 * v0 + 4.0 * g * rhs)) / (2.0 * g)
        else:
            dt = rhs / v0 if v0 > 0.0 else horizon + 1.0
        tau += dt
        if tau > horizon:
            return horizon + 1.0
    return tau


def open_sequence(run: FEDrop, y: np.ndarray, body: FlexibleRod) -> str:
    """Why the reference's sequence had not ended in the state ``y`` (at ``t_stop``), by the
    engine's end-of-sequence rule (``flexcore.flight.left_for_good``, stop="sequence"); ""
    when it had. Open: an end still in contact, or the end last in contact may come back to
    the flat, in the rigid ballistic motion lowered by a bound on its elastic displacement,
    sqrt(2 E_vib sum_j (U_j^2 + W_j^2) / omega_j^2) (the body's modes, E_vib the FE's
    vibration energy), before the other end can touch (a new impact), the centre of mass is
    back at its height, or ``HORIZON_CAP``, unless only after a clear flight of 10 periods of
    the basis's first mode (``omega[0]``; a new impact of that end). The engine's third case,
    the rigid path that rose and falls back (``flexcore.flight.falling_back``), is not
    mirrored here: it changes only this warning's wording."""
    fe = run.fe
    for k in range(2):
        if run.ends[k].inn:
            return f"end {k} is still in contact"
    if not run.contacts:
        return ""
    nd = run.nd
    X, V = y[:nd], y[nd : 2 * nd]
    vxc, vyc, w, Ic = fe.rigid_motion(X, V)
    yc = float(np.sum(fe.mass * X[1::3]) / fe.m)
    th = rigid_angle(fe, X)
    ek = 0.5 * fe.m * (vxc**2 + vyc**2) + 0.5 * Ic * w * w
    vg = fe.g * np.sum(fe.mass * (X[1::3] - fe.X0[1::3]))
    evib = max(fe.energy(y) - vg - ek, 0.0)
    bm = body_model(body)
    g, half = fe.g, 0.5 * fe.L
    horizon = min(2.0 * vyc / g if (g > 0.0 and vyc > 0.0) else math.inf, HORIZON_CAP)
    speed = abs(w) * half

    def touch_time(k: int, until: float) -> float:
        band = math.sqrt(2.0 * evib * float(np.sum((bm.U[k] ** 2 + bm.W[k] ** 2) / bm.omega**2)))
        sk = -1.0 if k == 0 else 1.0

        def clear(tau: float) -> float:
            yk = yc + vyc * tau - 0.5 * g * tau * tau + sk * half * math.sin(th + w * tau)
            return yk - fe.R - band

        return _first_below(clear, vyc, speed, g, until)

    last = int(run.contacts[-1]["end"])
    t_other = touch_time(1 - last, horizon)
    if t_other <= horizon:
        horizon = t_other  # the other end's landing: a new impact
    t_back = touch_time(last, horizon)
    flight_min = NEW_IMPACT_CHECKS * 0.1 * 2.0 * math.pi / float(bm.omega[0])
    if t_back <= horizon and t_back < flight_min:
        when = f"within {t_back * 1e3:.3g} ms" if t_back > 0.0 else "now"
        return (
            f"end {last} may touch the flat again {when}, its rigid path lowered by a bound "
            "on its elastic displacement"
        )
    return ""


def rigid_angle(fe: CorotationalRod, X: np.ndarray) -> float:
    """The rigid-body angle [rad] of the pose ``X`` (nodal x, y, theta): the rotation of the
    undeformed rod that fits the nodes best in the least squares of their masses and rotary
    inertias, sum m_i |r_i - R(th) s_i|^2 + sum J_i (th0 + theta_i - th)^2 (r_i, s_i: the
    deformed and undeformed positions about the centre of mass). Its linearisation is the
    modal model's floating frame (the elastic modes carry no angular momentum about it); the
    chord between the end nodes turns with every bending mode."""
    ms, m = fe.mass, fe.m
    rx = X[0::3] - np.sum(ms * X[0::3]) / m
    ry = X[1::3] - np.sum(ms * X[1::3]) / m
    s = np.arange(fe.nn) * fe.h
    s -= np.sum(ms * s) / m
    a, b = float(np.sum(ms * s * rx)), float(np.sum(ms * s * ry))
    fit, theta = math.hypot(a, b), fe.th0 + X[2::3]
    th_a = fe.th0 + (math.atan2(b, a) - fe.th0 + math.pi) % (2.0 * math.pi) - math.pi
    th, jsum = th_a, float(np.sum(fe.J))
    for _ in range(4):  # Newton on fit sin(th_a - th) + sum J (theta - th) = 0
        f = fit * math.sin(th_a - th) + float(np.sum(fe.J * (theta - th)))
        th += f / (fit * math.cos(th_a - th) + jsum)
    return th


def _summary(run: FEDrop, y: np.ndarray, t: float, vn0: float) -> dict[str, Any]:
    fe = run.fe
    nd = run.nd
    X, V = y[:nd], y[nd : 2 * nd]
    vxc, vyc, w, Ic = fe.rigid_motion(X, V)
    ended = [c["start"] + c["duration"] for c in run.contacts if "duration" in c]
    T = max(ended) if ended else math.nan
    # the rigid-body angle, rotated back to the last separation (free spin w after it)
    th = rigid_angle(fe, X) - w * (t - T)
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
    ``simulate_drop``. Warns (``SequenceOpenWarning``) when the sequence has not ended at
    ``t_stop`` (``open_sequence``)."""
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
    why = open_sequence(run, y, body)
    if why:
        warnings.warn(
            f"drop_reference: t_stop = {t_stop:g} s ends before the sequence does: {why}; "
            "e, the velocities, the duration and the contacts are those of a sequence cut "
            "short; raise t_stop",
            SequenceOpenWarning,
            stacklevel=2,
        )
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
