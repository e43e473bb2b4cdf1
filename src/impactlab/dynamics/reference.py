"""Reference implementation of the impact with scipy's ``solve_ivp`` (test oracle and benchmark
baseline).

The same physics as the compiled engine (docs/engine/index.md), written independently in plain
Python: the equations of motion, the normal contact history and the three friction models, with
every phase switch located by ``solve_ivp``'s terminal events and the integration restarted in
the new mode. Only the contact-law kernels (``impactlab.contact.kernels``) are shared.
Slow (milliseconds per impact); use it to check the engine, not for production.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.bodies import BP_GSTAR, BP_INERTIA, BP_MASS, Rod, Sphere
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.dynamics.engine import DEFAULT_RTOL, REGIME_NAMES
from impactlab.dynamics.simulate import (
    _body_params,
    _check_body,
    _check_flat,
    _check_rtol,
    _check_velocity,
    check_angle,
    contact_model,
    gravity_value,
)
from impactlab.friction import get_friction
from impactlab.materials import AISI_1010, Material

_contact_radius: Callable[..., float] = k.contact_radius


class _Problem:
    """State: [dx, dy, phi, vx, vy, omega, W, q] (see the engine's module docstring)."""

    def __init__(self, model: ContactModel, friction: str, body: Rod | Sphere, bp: np.ndarray,
                 th0: float, mu: float, g: float, constant_angle: bool) -> None:
        self.law = model.law_id
        self.p = np.array(model.params)
        self.E = float(self.p[k.P_ESTAR])
        self.dlim = float(self.p[k.P_DLIM])
        dsw = float(self.p[k.P_DSW])
        self.dsw = dsw if dsw > 0.0 else math.inf
        self.fric = "none" if mu == 0.0 else friction
        self.d = body.half_length
        self.R = body.tip_radius
        self.m = float(bp[BP_MASS])
        self.I = float(bp[BP_INERTIA])
        self.Gs = float(bp[BP_GSTAR])
        self.g = g
        self.mu = mu
        self.th0 = th0
        self.const = constant_angle
        self.a0 = self.d * math.cos(th0)
        self.b0 = self.d * math.sin(th0) + self.R
        # mode
        self.loading = True
        self.dm = 0.0
        self.dr = 0.0
        self.rr = self.R
        self.comp = True
        self.fm = 0.0  # 0: stick / elastic; +-1: slip direction
        self.sir = 0.0  # impulse ratio sign
        self.af = 1.0  # unloading contact-radius factor (continuity at the turning point)

    # --- kinematics and forces ---------------------------------------------------------------
    def geometry(self, y: np.ndarray) -> tuple[float, float, float, float, float]:
        d, R, phi = self.d, self.R, y[2]
        if self.const:
            a, b = self.a0, self.b0
            delta = a * phi - y[1]
            xs = y[0] + d * math.sin(self.th0) * phi
            return delta, a, b, xs, y[0] + b * phi
        th = self.th0 + phi
        a = d * math.cos(th)
        b = d * math.sin(th) + R
        delta = d * (math.sin(th) - math.sin(self.th0)) - y[1]
        xs = y[0] - d * (math.cos(th) - math.cos(self.th0))
        return delta, a, b, xs, xs + R * phi

    def normal_force(self, delta: float) -> float:
        if self.loading:
            return float(k.loading_force(self.law, self.p, delta))
        return float(k.unloading_force(self.E, self.rr, self.dr, delta))

    def radius(self, delta: float) -> float:
        if self.loading:
            return float(_contact_radius(self.law, self.p, delta, delta, 0.0, self.R))
        return self.af * float(_contact_radius(self.law, self.p, delta, math.inf, self.dr,
                                               self.rr))

    def stick_force(self, Fn: float, a: float, b: float, w: float) -> float:
        cent = 0.0 if self.const else a * w * w
        return (Fn * a * b / self.I - cent) / (1.0 / self.m + b * b / self.I)

    def forces(self, y: np.ndarray) -> dict[str, float]:
        delta, a, b, xs, slide = self.geometry(y)
        Fn = self.normal_force(delta)
        vn = y[4] - y[5] * a
        vs = y[3] + y[5] * b
        kt = 0.0
        if self.fric == "impulse_ratio":
            Ft = self.sir * self.mu * Fn
        elif self.fric == "coulomb":
            Ft = self.stick_force(Fn, a, b, y[5]) if self.fm == 0.0 else -self.fm * self.mu * Fn
        elif self.fric == "mindlin":
            kt = 8.0 * self.Gs * self.radius(delta)
            if self.fm != 0.0:
                Ft = -self.fm * self.mu * Fn
            else:
                Ft = y[7] if self.comp else -kt * y[7]
        else:
            Ft = 0.0
        return {"delta": delta, "a": a, "b": b, "xs": xs, "slide": slide, "Fn": Fn, "Ft": Ft,
                "vn": vn, "vs": vs, "kt": kt}

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        f = self.forces(y)
        dq = 0.0
        if self.fric == "mindlin" and self.fm == 0.0:
            dq = -f["kt"] * f["vs"] if self.comp else f["vs"]
        return np.array([
            y[3], y[4], y[5], f["Ft"] / self.m, f["Fn"] / self.m - self.g,
            (f["b"] * f["Ft"] - f["a"] * f["Fn"]) / self.I, f["Fn"] * f["vn"], dq,
        ])

    def energy(self, y: np.ndarray) -> float:
        f = self.forces(y)
        E = (0.5 * self.m * (y[3] ** 2 + y[4] ** 2) + 0.5 * self.I * y[5] ** 2
             + self.m * self.g * y[1])
        if f["Fn"] > 0.0:
            dr = (float(k.residual_depth(self.law, self.p, f["delta"], f["Fn"])) if self.loading
                  else self.dr)
            E += 0.4 * f["Fn"] * (f["delta"] - dr)
        if self.fric == "mindlin" and f["kt"] > 0.0:
            E += 0.5 * f["Ft"] ** 2 / f["kt"]
        return E

    # --- Mindlin rates -------------------------------------------------------------------------
    def _dF(self, delta: float, Fn: float) -> float:
        if not self.loading:
            d = delta - self.dr
            return 1.5 * Fn / d if d > 0.0 else 0.0
        if delta <= 0.0:
            return 0.0
        h = 1e-6 * delta
        return (float(k.loading_force(self.law, self.p, delta + h))
                - float(k.loading_force(self.law, self.p, delta - h))) / (2.0 * h)

    def _da(self, delta: float) -> float:
        base = 0.0 if self.loading else self.dr
        d = delta - base
        if d <= 0.0:
            return 0.0
        h = 1e-6 * d
        return (self.radius(delta + h) - self.radius(delta - h)) / (2.0 * h)

    def mindlin_slip_exit(self, f: dict[str, float]) -> float:
        """> 0 when the elastic trial force points back inside the friction cone."""
        ddelta = -f["vn"]
        dFn = self._dF(f["delta"], f["Fn"]) * ddelta
        if self.comp:
            dFt = -f["kt"] * f["vs"]
        elif f["kt"] > 0.0:
            dkt = 8.0 * self.Gs * self._da(f["delta"]) * ddelta
            dFt = dkt * f["Ft"] / f["kt"] - f["kt"] * f["vs"]
        else:
            dFt = 0.0
        return self.fm * dFt + self.mu * dFn

    def coulomb_decide(self, Fn: float, a: float, b: float, w: float) -> float:
        Fs = self.stick_force(Fn, a, b, w)
        if Fn > 0.0 or Fs != 0.0:
            if abs(Fs) <= self.mu * Fn:
                return 0.0
            return -1.0 if Fs > 0.0 else 1.0
        ratio = a * b / self.I / (1.0 / self.m + b * b / self.I)
        if abs(ratio) <= self.mu:
            return 0.0
        return -1.0 if ratio > 0.0 else 1.0

    # --- events (fire when g crosses upwards) -------------------------------------------------
    def events(self) -> list[Callable[[float, np.ndarray], float]]:
        def ev_vn(t: float, y: np.ndarray) -> float:
            f = self.forces(y)
            return f["vn"] if self.comp else -f["vn"]

        def ev_reload(t: float, y: np.ndarray) -> float:
            if self.loading or not self.comp:
                return -1.0
            return self.geometry(y)[0] - self.dm

        def ev_sep(t: float, y: np.ndarray) -> float:
            if self.loading or self.comp:
                return -1.0
            return self.dr - self.geometry(y)[0]

        def ev_limit(t: float, y: np.ndarray) -> float:
            return self.geometry(y)[0] - self.dlim if self.loading else -1.0

        def ev_fric(t: float, y: np.ndarray) -> float:
            if self.fric not in ("coulomb", "mindlin"):
                return -1.0
            f = self.forces(y)
            if self.fric == "coulomb":
                if self.fm != 0.0:
                    return -self.fm * f["vs"]
                return abs(f["Ft"]) - self.mu * f["Fn"]
            if self.fm == 0.0:
                if self.comp:
                    return abs(f["Ft"]) - self.mu * f["Fn"]
                return abs(y[7]) - (self.mu * f["Fn"] / f["kt"] if f["kt"] > 0.0 else 0.0)
            return self.mindlin_slip_exit(f)

        def ev_switch(t: float, y: np.ndarray) -> float:
            return self.geometry(y)[0] - self.dsw if self.loading else -1.0

        evs: list[Callable[[float, np.ndarray], float]] = [
            ev_vn, ev_reload, ev_sep, ev_limit, ev_fric, ev_switch]
        for e in evs:
            e.terminal = True  # type: ignore[attr-defined]
            e.direction = 1.0  # type: ignore[attr-defined]
        return evs


def simulate_reference(
    body: Rod | Sphere,
    flat: Material = AISI_1010,
    *,
    law: str | ContactModel = "ghaednia",
    friction: str = "coulomb",
    mu: float = 0.0,
    angle: float | None = None,
    velocity: tuple[float, float],
    spin: float = 0.0,
    law_params: Mapping[str, float] | None = None,
    gravity: bool | float = True,
    constant_angle: bool = False,
    rtol: float | None = None,
    method: str = "RK45",
    max_segments: int = 10_000,
) -> dict[str, Any]:
    """The impact integrated with ``scipy.integrate.solve_ivp`` (same arguments as
    ``simulate``). Returns a dict with the engine's output names (``OUTPUT_FIELDS`` except the
    diagnostics), ``regime`` as a name, plus ``n_segments`` and ``nfev``.

    Error control: ``rtol`` and the per-component ``atol = rtol * scale`` of the engine (scale:
    Hertz estimate of the penetration, the impact speed, and their rotational counterparts).
    """
    body = _check_body(body)
    flat = _check_flat(flat)
    fr = get_friction(friction).name
    mu_v = float(mu)
    if not (math.isfinite(mu_v) and mu_v >= 0.0):
        raise ValueError(f"mu must be finite and >= 0, got {mu!r}")
    th0 = check_angle(angle, body)
    vx0, vy0 = _check_velocity(velocity)
    w0 = float(spin)
    g = gravity_value(gravity)
    r = _check_rtol(rtol if rtol is not None else DEFAULT_RTOL)
    model = contact_model(body, flat, law, law_params)
    bp = _body_params(body, flat)
    P = _Problem(model, fr, body, bp, th0, mu_v, g, constant_angle)

    a0, b0 = P.a0, P.b0
    vn0 = vy0 - w0 * a0
    vt0 = vx0 + w0 * b0
    if not vn0 < 0.0:
        raise ValueError(f"velocity: the contact point does not approach the flat (v_n = {vn0!r})")
    # initial friction mode
    if P.fric == "impulse_ratio":
        P.sir = (-math.copysign(1.0, vt0) if vt0 != 0.0
                 else (1.0 if a0 * b0 > 0.0 else (-1.0 if a0 * b0 < 0.0 else 0.0)))
    elif P.fric == "coulomb":
        P.fm = math.copysign(1.0, vt0) if vt0 != 0.0 else P.coulomb_decide(0.0, a0, b0, w0)
    elif P.fric == "mindlin":
        if vt0 != 0.0 and 4.0 * P.Gs * abs(vt0) > mu_v * P.E * abs(vn0):
            P.fm = math.copysign(1.0, vt0)

    # scales (as in the engine)
    lever = P.d + P.R
    vstar = abs(vn0)
    meff = 1.0 / (1.0 / P.m + a0 * a0 / P.I)
    dstar = (15.0 * meff * vn0 ** 2 / (16.0 * P.E * math.sqrt(P.R))) ** 0.4
    tstar = dstar / abs(vn0)
    fscale = meff * vstar / tstar
    sc = np.array([dstar, dstar, dstar / lever, vstar, vstar, vstar / lever, meff * vn0 ** 2,
                   fscale if P.fric == "mindlin" else 1e300])

    y = np.array([0.0, 0.0, 0.0, vx0, vy0, w0, 0.0, 0.0])
    t = 0.0
    e0 = 0.5 * P.m * (vx0 ** 2 + vy0 ** 2) + 0.5 * P.I * w0 ** 2
    w_mark = w_comp = w_rest = 0.0
    stick_time = 0.0
    fmax = dmax = tmax = 0.0
    vs_pos = vs_neg = 0.0
    nfev = 0
    finished = False
    evs = P.events()
    for seg in range(max_segments):
        if P.fric == "mindlin":
            sc[7] = fscale if P.comp else dstar
        sol = solve_ivp(P.rhs, (t, t + 1e4 * tstar), y, method=method, rtol=r, atol=r * sc,
                        events=evs, max_step=tstar, first_step=0.02 * tstar * r ** 0.2
                        if seg == 0 else None, dense_output=False)
        nfev += int(sol.nfev)
        if sol.status == -1:
            raise RuntimeError(f"solve_ivp failed: {sol.message}")
        fired = [i for i, te in enumerate(sol.t_events) if len(te)]
        # statistics over the segment's steps
        sticking = P.fric in ("coulomb", "mindlin") and P.fm == 0.0
        for j in range(sol.y.shape[1]):
            f = P.forces(sol.y[:, j])
            fmax = max(fmax, f["Fn"])
            if f["delta"] > dmax:
                dmax, tmax = f["delta"], sol.t[j]
            vs_pos = max(vs_pos, f["vs"])
            vs_neg = min(vs_neg, f["vs"])
        if not fired:
            raise RuntimeError("solve_ivp ended without separation")
        ev = fired[0]
        t_ev = float(sol.t_events[ev][0])
        y = np.array(sol.y_events[ev][0])
        if sticking:
            stick_time += t_ev - t
        t = t_ev
        f = P.forces(y)
        fmax = max(fmax, f["Fn"])
        if f["delta"] > dmax:
            dmax, tmax = f["delta"], t
        vs_pos = max(vs_pos, f["vs"])
        vs_neg = min(vs_neg, f["vs"])
        if ev == 2:  # separation
            w_rest += y[6] - w_mark
            finished = True
            break
        if ev == 3:
            raise ValueError("the interference exceeded the contact law's validity range")
        if ev == 5:  # the loading curve left the elastic curve: passed once
            P.dsw = math.inf
        if ev == 0:
            if P.comp:
                w_comp += y[6] - w_mark
                w_mark = y[6]
                if P.loading:
                    dm = f["delta"]
                    Fm = float(k.loading_force(P.law, P.p, dm))
                    dr = float(k.residual_depth(P.law, P.p, dm, Fm))
                    P.dm, P.dr = dm, dr
                    P.rr = float(k.unloading_radius(P.E, dm, Fm, dr))
                    P.loading = False
                    a_unl = float(_contact_radius(P.law, P.p, dm, math.inf, dr, P.rr))
                    a_load = float(_contact_radius(P.law, P.p, dm, dm, 0.0, P.R))
                    P.af = a_load / a_unl if a_unl > 0.0 else 1.0
                P.comp = False
                if P.fric == "mindlin" and P.fm == 0.0:
                    ktn = 8.0 * P.Gs * P.radius(f["delta"])
                    y[7] = -f["Ft"] / ktn if ktn > 0.0 else 0.0
            else:
                w_rest += y[6] - w_mark
                w_mark = y[6]
                P.comp = True
                if P.fric == "mindlin" and P.fm == 0.0:
                    y[7] = f["Ft"]
        elif ev == 1:
            P.loading = True
            if P.fric == "mindlin" and P.fm == 0.0:
                y[7] = f["Ft"]
        elif ev == 4:
            if P.fric == "coulomb":
                if P.fm != 0.0:
                    P.fm = P.coulomb_decide(f["Fn"], f["a"], f["b"], y[5])
                else:
                    P.fm = -1.0 if f["Ft"] > 0.0 else 1.0
            else:
                if P.fm == 0.0:
                    P.fm = (-math.copysign(1.0, f["Ft"]) if f["Ft"] != 0.0
                            else (1.0 if f["vs"] >= 0.0 else -1.0))
                else:
                    P.fm = 0.0
                    y[7] = f["Ft"] if P.comp else (-f["Ft"] / f["kt"] if f["kt"] > 0 else 0.0)
    if not finished:
        raise RuntimeError("too many segments")

    delta, a, b, xs, slide = P.geometry(y)
    vx, vy, w = y[3], y[4], y[5]
    vn = vy - w * a
    vt = vx + w * b
    pn = P.m * (vy - vy0) + P.m * g * t
    e_end = 0.5 * P.m * (vx ** 2 + vy ** 2) + 0.5 * P.I * w ** 2 + P.m * g * y[1]
    if P.fric == "none":
        reg = 0
    elif vs_pos > 1e-6 * vstar and vs_neg < -1e-6 * vstar:
        reg = 3
    elif P.fric == "impulse_ratio" and ((P.sir > 0 and vs_pos > 1e-6 * vstar)
                                        or (P.sir < 0 and vs_neg < -1e-6 * vstar)):
        reg = 3
    elif stick_time > 1e-9 * t:
        reg = 2
    else:
        reg = 1
    return {
        "e": -vn / vn0,
        "e_energy": math.sqrt(max(0.0, -w_rest / w_comp)) if w_comp < 0.0 else math.nan,
        "vx_out": vx,
        "vy_out": vy,
        "spin_out": w,
        "delta_max": dmax,
        "delta_p": P.dr,
        "sliding_length": slide,
        "contact_travel": xs,
        "duration": t,
        "mean_force": pn / t,
        "max_force": fmax,
        "normal_impulse": pn,
        "tangential_impulse": P.m * (vx - vx0),
        "energy_dissipated": e0 - e_end,
        "stick_time": stick_time,
        "regime": REGIME_NAMES[reg],
        "vn_in": vn0,
        "vt_in": vt0,
        "vn_out": vn,
        "vt_out": vt,
        "angle_out": th0 + y[2] if isinstance(body, Rod) else math.nan,
        "t_max": tmax,
        "n_segments": seg + 1,
        "nfev": nfev,
    }
