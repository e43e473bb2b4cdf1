"""The impact as a plain-Python initial-value problem for the ``solve_ivp`` reference
(``impactlab.dynamics.reference``): equations of motion, normal contact history, the three
friction models, event functions and mode transitions, written independently of the compiled
core. Only the contact-law kernels (``impactlab.contact.kernels``) are shared.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from impactlab.bodies import BP_GSTAR, BP_INERTIA, BP_MASS, Rod, Sphere
from impactlab.contact import history_kernels as hk
from impactlab.contact import kernels as k
from impactlab.contact.base import ContactModel
from impactlab.dynamics.kernels.friction import LEVER_ROUNDOFF
from impactlab.dynamics.kernels.layout import MU_NEGLIGIBLE

_contact_radius: Callable[..., float] = hk.contact_radius


class ReferenceProblem:
    """The impact as an initial-value problem for ``solve_ivp``, with its mode (contact phase,
    friction state) switched between integration segments.

    State: [dx, dy, phi, vx, vy, spin, W, q] (``impactlab.dynamics.kernels.layout``)."""

    def __init__(
        self,
        model: ContactModel,
        friction: str,
        body: Rod | Sphere,
        bp: np.ndarray,
        th0: float,
        mu: float,
        g: float,
        constant_angle: bool,
    ) -> None:
        self.law = model.law_id
        self.p = np.array(model.params)
        self.E = float(self.p[k.P_ESTAR])
        self.dlim = float(self.p[k.P_DLIM])
        dsw = float(self.p[k.P_DSW])
        self.dsw = dsw if dsw > 0.0 else math.inf
        self.fric = "none" if mu < MU_NEGLIGIBLE else friction
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
        return self.af * float(_contact_radius(self.law, self.p, delta, math.inf, self.dr, self.rr))

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
            Ft = -self.fm * self.mu * Fn if self.fm != 0.0 else (y[7] if self.comp else -kt * y[7])
        else:
            Ft = 0.0
        return {
            "delta": delta,
            "a": a,
            "b": b,
            "xs": xs,
            "slide": slide,
            "Fn": Fn,
            "Ft": Ft,
            "vn": vn,
            "vs": vs,
            "kt": kt,
        }

    def rhs(self, t: float, y: np.ndarray) -> np.ndarray:
        f = self.forces(y)
        dq = 0.0
        if self.fric == "mindlin" and self.fm == 0.0:
            dq = -f["kt"] * f["vs"] if self.comp else f["vs"]
        return np.array(
            [
                y[3],
                y[4],
                y[5],
                f["Ft"] / self.m,
                f["Fn"] / self.m - self.g,
                (f["b"] * f["Ft"] - f["a"] * f["Fn"]) / self.I,
                f["Fn"] * f["vn"],
                dq,
            ]
        )

    def energy(self, y: np.ndarray) -> float:
        f = self.forces(y)
        E = (
            0.5 * self.m * (y[3] ** 2 + y[4] ** 2)
            + 0.5 * self.I * y[5] ** 2
            + self.m * self.g * y[1]
        )
        if f["Fn"] > 0.0:
            dr = (
                float(k.residual_depth(self.law, self.p, f["delta"], f["Fn"]))
                if self.loading
                else self.dr
            )
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
        return (
            float(k.loading_force(self.law, self.p, delta + h))
            - float(k.loading_force(self.law, self.p, delta - h))
        ) / (2.0 * h)

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
    def friction_event(self, y: np.ndarray) -> float:
        """The stick/slip event function at ``y``."""
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
            return self.friction_event(y)

        def ev_switch(t: float, y: np.ndarray) -> float:
            return self.geometry(y)[0] - self.dsw if self.loading else -1.0

        evs: list[Callable[[float, np.ndarray], float]] = [
            ev_vn,
            ev_reload,
            ev_sep,
            ev_limit,
            ev_fric,
            ev_switch,
        ]
        for e in evs:
            e.terminal = True  # type: ignore[attr-defined]
            e.direction = 1.0  # type: ignore[attr-defined]
        return evs

    # --- mode transitions ---------------------------------------------------------------------
    def init_friction(self, vn0: float, vt0: float, w0: float) -> None:
        """The friction mode at first touch (contact-point velocities vn0, vt0 [m/s])."""
        a0, b0 = self.a0, self.b0
        if self.fric == "impulse_ratio":
            tol = LEVER_ROUNDOFF * (a0 * a0 + b0 * b0)  # as the compiled engine
            rolling = abs(vt0) <= LEVER_ROUNDOFF * (abs(vn0) + abs(w0) * math.hypot(a0, b0))
            self.sir = (
                -math.copysign(1.0, vt0)
                if not rolling
                else (1.0 if a0 * b0 > tol else (-1.0 if a0 * b0 < -tol else 0.0))
            )
        elif self.fric == "coulomb":
            self.fm = (
                math.copysign(1.0, vt0) if vt0 != 0.0 else self.coulomb_decide(0.0, a0, b0, w0)
            )
        elif (
            self.fric == "mindlin"
            and vt0 != 0.0
            and 4.0 * self.Gs * abs(vt0) > self.mu * self.E * abs(vn0)
        ):
            self.fm = math.copysign(1.0, vt0)

    def turn(self, y: np.ndarray, f: dict[str, float]) -> None:
        """v_n = 0 while compressing: a new unloading branch (from the loading curve)."""
        if self.loading:
            dm = f["delta"]
            Fm = float(k.loading_force(self.law, self.p, dm))
            dr = float(k.residual_depth(self.law, self.p, dm, Fm))
            self.dm, self.dr = dm, dr
            self.rr = float(k.unloading_radius(self.E, dm, Fm, dr))
            self.loading = False
            a_unl = float(_contact_radius(self.law, self.p, dm, math.inf, dr, self.rr))
            a_load = float(_contact_radius(self.law, self.p, dm, dm, 0.0, self.R))
            self.af = a_load / a_unl if a_unl > 0.0 else 1.0
        self.comp = False
        if self.fric == "mindlin" and self.fm == 0.0:
            ktn = 8.0 * self.Gs * self.radius(f["delta"])
            y[7] = -f["Ft"] / ktn if ktn > 0.0 else 0.0

    def switch_friction(self, y: np.ndarray, f: dict[str, float]) -> None:
        """The friction event: stick <-> slip, or a slip reversal."""
        if self.fric == "coulomb":
            if self.fm != 0.0:
                self.fm = self.coulomb_decide(f["Fn"], f["a"], f["b"], y[5])
            else:
                self.fm = -1.0 if f["Ft"] > 0.0 else 1.0
        elif self.fm == 0.0:
            self.fm = (
                -math.copysign(1.0, f["Ft"])
                if f["Ft"] != 0.0
                else (1.0 if f["vs"] >= 0.0 else -1.0)
            )
        else:
            self.fm = 0.0
            y[7] = f["Ft"] if self.comp else (-f["Ft"] / f["kt"] if f["kt"] > 0 else 0.0)
