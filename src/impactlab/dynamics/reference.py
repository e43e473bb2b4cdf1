"""Reference implementation of the impact with scipy's ``solve_ivp`` (test oracle and benchmark
baseline).

The same physics as the compiled engine (docs/engine/index.md), written independently in plain
Python (``impactlab.dynamics.reference_problem``): the equations of motion, the normal contact
history and the rigid engine's three point-contact friction models (partial slip has its
own reference, ``impactlab.verification.partial_slip``), with every phase switch located by
``solve_ivp``'s terminal events and the integration restarted in the new mode. Only the
contact-law kernels (``impactlab.contact.kernels``) are shared. Slow (milliseconds per impact);
use it to check the engine, not for production.
"""

from __future__ import annotations

import inspect
import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.bodies import Rod, Sphere
from impactlab.dynamics.checks import check_impact
from impactlab.dynamics.input_checks import velocity_from
from impactlab.dynamics.kernels.status import REGIME_NAMES
from impactlab.dynamics.models import body_params
from impactlab.dynamics.reference_problem import ReferenceProblem
from impactlab.dynamics.simulate import simulate
from impactlab.friction import FRICTION_IDS
from impactlab.materials import AISI_1010, Material


class _Stats:
    """Running extremes, stick time and normal work over the integration (SI)."""

    def __init__(self) -> None:
        self.fmax = self.dmax = self.tmax = 0.0  # largest force, interference and its time
        self.vs_pos = self.vs_neg = 0.0  # extreme slip velocities
        self.stick_time = 0.0
        self.w_mark = self.w_comp = self.w_rest = 0.0  # normal work: mark, compression, rest.

    def track(self, f: dict[str, float], t: float) -> None:
        self.fmax = max(self.fmax, f["Fn"])
        if f["delta"] > self.dmax:
            self.dmax, self.tmax = f["delta"], t
        self.vs_pos = max(self.vs_pos, f["vs"])
        self.vs_neg = min(self.vs_neg, f["vs"])


@dataclass
class _Scales:
    """Error-control scales of the state (as in the engine) and the time scale t* [s]."""

    sc: np.ndarray
    tstar: float
    dstar: float
    fscale: float


def _scales(P: ReferenceProblem, vn0: float) -> _Scales:
    lever = P.d + P.R
    vstar = abs(vn0)
    meff = 1.0 / (1.0 / P.m + P.a0 * P.a0 / P.I)
    dstar = (15.0 * meff * vn0**2 / (16.0 * P.E * math.sqrt(P.R))) ** 0.4
    tstar = dstar / abs(vn0)
    fscale = meff * vstar / tstar
    sc = np.array(
        [
            dstar,
            dstar,
            dstar / lever,
            vstar,
            vstar,
            vstar / lever,
            meff * vn0**2,
            fscale if P.fric == "mindlin" else 1e300,
        ]
    )
    return _Scales(sc, tstar, dstar, fscale)


def _on_event(P: ReferenceProblem, ev: int, y: np.ndarray, f: dict[str, float], st: _Stats) -> None:
    """Mode transition at the event ``ev`` (not separation or the law limit)."""
    if ev == 5:  # the loading curve left the elastic curve: passed once
        P.dsw = math.inf
    if ev == 0:
        if P.comp:
            st.w_comp += y[6] - st.w_mark
            st.w_mark = y[6]
            P.turn(y, f)
        else:
            st.w_rest += y[6] - st.w_mark
            st.w_mark = y[6]
            P.comp = True
            if P.fric == "mindlin" and P.fm == 0.0:
                y[7] = f["Ft"]
    elif ev == 1:
        P.loading = True
        if P.fric == "mindlin" and P.fm == 0.0:
            y[7] = f["Ft"]
    elif ev == 4:
        P.switch_friction(y, f)


def _integrate(
    P: ReferenceProblem,
    y: np.ndarray,
    r: float,
    s: _Scales,
    st: _Stats,
    method: str,
    max_segments: int,
) -> tuple[float, np.ndarray, int, int]:
    """Integrate segment by segment until separation. Returns (t, y, segments, nfev)."""
    t = 0.0
    nfev = 0
    evs = P.events()
    for seg in range(max_segments):
        if P.fric == "mindlin":
            s.sc[7] = s.fscale if P.comp else s.dstar
        sol = solve_ivp(
            P.rhs,
            (t, t + 1e4 * s.tstar),
            y,
            method=method,
            rtol=r,
            atol=r * s.sc,
            events=evs,
            max_step=s.tstar,
            first_step=0.02 * s.tstar * r**0.2 if seg == 0 else None,
            dense_output=False,
        )
        nfev += int(sol.nfev)
        if sol.status == -1:
            raise RuntimeError(f"solve_ivp failed: {sol.message}")
        fired = [i for i, te in enumerate(sol.t_events) if len(te)]
        # statistics over the segment's steps
        sticking = P.fric in ("coulomb", "mindlin") and P.fm == 0.0
        for j in range(sol.y.shape[1]):
            st.track(P.forces(sol.y[:, j]), sol.t[j])
        if not fired:
            raise RuntimeError("solve_ivp ended without separation")
        ev = fired[0]
        t_ev = float(sol.t_events[ev][0])
        y = np.array(sol.y_events[ev][0])
        if sticking:
            st.stick_time += t_ev - t
        t = t_ev
        f = P.forces(y)
        st.track(f, t)
        if ev == 2:  # separation
            st.w_rest += y[6] - st.w_mark
            return t, y, seg + 1, nfev
        if ev == 3:
            raise ValueError("the interference exceeded the contact law's validity range")
        _on_event(P, ev, y, f, st)
    raise RuntimeError("too many segments")


def _regime(P: ReferenceProblem, st: _Stats, t: float, vstar: float) -> int:
    if P.fric == "none" or (P.fric == "impulse_ratio" and P.sir == 0.0):
        return 0
    if st.vs_pos > 1e-6 * vstar and st.vs_neg < -1e-6 * vstar:
        return 3
    if P.fric == "impulse_ratio" and (
        (P.sir > 0 and st.vs_pos > 1e-6 * vstar) or (P.sir < 0 and st.vs_neg < -1e-6 * vstar)
    ):
        return 3
    if st.stick_time > 1e-9 * t:
        return 2
    return 1


def _result(
    P: ReferenceProblem,
    y: np.ndarray,
    t: float,
    st: _Stats,
    initial: tuple[float, float, float, float, float, float],
    rod: bool,
) -> dict[str, Any]:
    """The output dict at separation; ``initial`` = (angle, vx0, vy0, w0, vn0, vt0)."""
    th0, vx0, vy0, w0, vn0, vt0 = initial
    _delta, a, b, xs, slide = P.geometry(y)
    vx, vy, w = y[3], y[4], y[5]
    vn = vy - w * a
    vt = vx + w * b
    g = P.g
    pn = P.m * (vy - vy0) + P.m * g * t
    e0 = 0.5 * P.m * (vx0**2 + vy0**2) + 0.5 * P.I * w0**2
    e_end = 0.5 * P.m * (vx**2 + vy**2) + 0.5 * P.I * w**2 + P.m * g * y[1]
    return {
        "e": -vn / vn0,
        "e_energy": math.sqrt(max(0.0, -st.w_rest / st.w_comp)) if st.w_comp < 0.0 else math.nan,
        "vx_out": vx,
        "vy_out": vy,
        "spin_out": w,
        "delta_max": st.dmax,
        "delta_p": P.dr,
        "sliding_length": slide,
        "contact_travel": xs,
        "duration": t,
        "mean_force": pn / t,
        "max_force": st.fmax,
        "normal_impulse": pn,
        "tangential_impulse": P.m * (vx - vx0),
        "energy_dissipated": e0 - e_end,
        "stick_time": st.stick_time,
        "regime": REGIME_NAMES[_regime(P, st, t, abs(vn0))],
        "vn_in": vn0,
        "vt_in": vt0,
        "vn_out": vn,
        "vt_out": vt,
        "angle_out": th0 + y[2] if rod else math.nan,
        "t_max": st.tmax,
    }


def _simulate_defaults() -> dict[str, Any]:
    """``simulate``'s keyword defaults (the reference takes the same arguments)."""
    skip = ("body", "flat", "history", "partial_slip_cells")  # partial slip: no reference
    return {
        n: p.default
        for n, p in inspect.signature(simulate).parameters.items()
        if p.default is not p.empty and n not in skip
    }


def simulate_reference(
    body: Rod | Sphere,
    flat: Material = AISI_1010,
    *,
    method: str = "RK45",
    max_segments: int = 10_000,
    **impact: Any,
) -> dict[str, Any]:
    """The impact integrated with ``scipy.integrate.solve_ivp``; ``impact`` holds ``simulate``'s
    keyword arguments (law, friction, mu, angle, velocity, ...; same defaults, same checks).
    Returns a dict with the engine's output names (``OUTPUT_FIELDS`` except the diagnostics),
    ``regime`` as a name, plus ``n_segments`` and ``nfev``.

    Error control: ``rtol`` and the per-component ``atol = rtol * scale`` of the engine (scale:
    Hertz estimate of the penetration, the impact speed, and their rotational counterparts).
    """
    args = {**_simulate_defaults(), **impact}
    speed, incidence = args.pop("speed", None), args.pop("incidence", None)
    if args["velocity"] is None or speed is not None or incidence is not None:
        args["velocity"] = velocity_from(args["velocity"], speed, incidence)
    x = check_impact(body, flat, **args)
    if x.friction.name not in FRICTION_IDS:  # its reference: verification.partial_slip
        raise ValueError(f"simulate_reference: no solve_ivp reference for {x.friction.name!r}")
    P = ReferenceProblem(
        x.model,
        x.friction.name,
        x.body,
        body_params(x.body, x.flat),
        x.angle,
        x.mu,
        x.gravity,
        x.constant_angle,
    )
    (vx0, vy0), w0 = x.velocity, x.spin
    vn0 = vy0 - w0 * P.a0
    vt0 = vx0 + w0 * P.b0
    P.init_friction(vn0, vt0, w0)
    st = _Stats()
    y0 = np.array([0.0, 0.0, 0.0, vx0, vy0, w0, 0.0, 0.0])
    t, y, nseg, nfev = _integrate(P, y0, x.rtol, _scales(P, vn0), st, method, max_segments)
    out = _result(P, y, t, st, (x.angle, vx0, vy0, w0, vn0, vt0), isinstance(x.body, Rod))
    out["n_segments"] = nseg
    out["nfev"] = nfev
    return out
