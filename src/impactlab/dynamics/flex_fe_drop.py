"""The contact bookkeeping of the finite-element reference drop (``flex_reference``): the
right-hand side with the contact forces, the event functions, the event actions and the dents
(the same physics as the modal model, docs/flexible.md; SI units)."""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from impactlab.contact.history_kernels import loading_contact_radius
from impactlab.contact.kernels import (
    P_DLIM,
    P_DSW,
    P_ESTAR,
    loading_force,
    residual_depth,
    unloading_force,
    unloading_radius,
)
from impactlab.dynamics.flex_fe import CorotationalRod

__all__ = ["FEDrop", "FEEnd", "switch_interference"]


@dataclass
class FEEnd:
    """Contact state of one end (as the compiled ``layout.MD_*``)."""

    inn: bool = False
    ph: int = 0
    dm: float = 0.0
    dr: float = 0.0
    rr: float = 0.0
    fm: float = 0.0
    comp: bool = True
    dsw: float = math.inf
    dent: int = -1
    thr: float = 0.0


@dataclass
class FEDrop:
    """One reference drop: the mesh, the contact model and the mutable contact bookkeeping."""

    fe: CorotationalRod
    law: int
    p: np.ndarray
    mu: float
    ends: list[FEEnd] = field(default_factory=list)
    dents: list[dict[str, Any]] = field(default_factory=list)
    contacts: list[dict[str, Any]] = field(default_factory=list)
    cur: list[dict[str, Any] | None] = field(default_factory=lambda: [None, None])
    n_rhs: int = 0

    @property
    def nd(self) -> int:
        return 3 * self.fe.nn

    def kin(self, yy: np.ndarray, k: int) -> tuple[float, float, float, float]:
        """(delta, x, v_n, v_t) of end k."""
        n = 0 if k == 0 else self.fe.nn - 1
        Xn = yy[3 * n : 3 * n + 3]
        Vn = yy[self.nd + 3 * n : self.nd + 3 * n + 3]
        return self.fe.R - Xn[1], Xn[0], Vn[1], Vn[0] + self.fe.R * Vn[2]

    def _contact_force(self, yy: np.ndarray, k: int, F: np.ndarray) -> tuple[float, float]:
        s = self.ends[k]
        delta = self.kin(yy, k)[0]
        if s.ph == 0:
            Fn = loading_force(self.law, self.p, delta)
        else:
            Fn = unloading_force(self.p[P_ESTAR], s.rr, s.dr, delta)
        n = 0 if k == 0 else self.fe.nn - 1
        R = self.fe.R
        if self.mu > 0.0 and s.fm != 0.0:
            Ft = -s.fm * self.mu * Fn
        elif self.mu > 0.0:
            mk, Jk = self.fe.mass[n], self.fe.J[n]
            Ft = -(F[3 * n] / mk + R * F[3 * n + 2] / Jk) / (1.0 / mk + R * R / Jk)
        else:
            Ft = 0.0
        F[3 * n] += Ft
        F[3 * n + 1] += Fn
        F[3 * n + 2] += R * Ft
        return Fn, Ft

    def forces(self, yy: np.ndarray) -> tuple[np.ndarray, list[tuple[float, float]]]:
        """(accelerations, per-end (F_n, F_t))."""
        self.n_rhs += 1
        f, _U = self.fe.internal(yy[: self.nd])
        F = -f
        F[1::3] -= self.fe.mass * self.fe.g
        out = [self._contact_force(yy, k, F) if self.ends[k].inn else (0.0, 0.0) for k in range(2)]
        return F * self.fe.minv, out

    def rhs(self, _t: float, yy: np.ndarray) -> np.ndarray:
        acc, fo = self.forces(yy)
        wn = wt = 0.0
        for k in range(2):
            if self.ends[k].inn:
                _d, _x, vn, vt = self.kin(yy, k)
                wn += fo[k][0] * vn
                wt += fo[k][1] * vt
        return np.concatenate([yy[self.nd : 2 * self.nd], acc, [wn, wt]])

    def _end_events(self, k: int, dlim: float) -> list[tuple[Callable[..., float], int, str]]:
        s = self.ends[k]
        kin = self.kin
        if not s.inn:
            return [(lambda t, yy, thr=s.thr: kin(yy, k)[0] - thr, k, "touch")]
        sgn = 1.0 if s.comp else -1.0
        evs: list[tuple[Callable[..., float], int, str]] = [
            (lambda t, yy: sgn * kin(yy, k)[2], k, "vn")
        ]
        if s.ph == 0:
            evs.append((lambda t, yy: kin(yy, k)[0] - dlim, k, "limit"))
            if math.isfinite(s.dsw):
                evs.append((lambda t, yy, dsw=s.dsw: kin(yy, k)[0] - dsw, k, "switch"))
        elif s.comp:
            evs.append((lambda t, yy, dm=s.dm: kin(yy, k)[0] - dm, k, "reload"))
        else:
            evs.append((lambda t, yy, dr=s.dr: dr - kin(yy, k)[0], k, "sep"))
        if self.mu > 0.0 and s.fm != 0.0:
            evs.append((lambda t, yy, fm=s.fm: -fm * kin(yy, k)[3], k, "fric"))
        elif self.mu > 0.0:
            mu = self.mu

            def stick_end(t: float, yy: np.ndarray) -> float:
                fo = self.forces(yy)[1][k]
                return abs(fo[1]) - mu * fo[0]

            evs.append((stick_end, k, "fric"))
        return evs

    def events(self) -> list[tuple[Callable[..., float], int, str]]:
        evs = self._end_events(0, self.p[P_DLIM]) + self._end_events(1, self.p[P_DLIM])
        for fn, _k, _n in evs:
            fn.terminal = True  # type: ignore[attr-defined]
            fn.direction = 1.0  # type: ignore[attr-defined]
        return evs

    def in_dent(self, k: int, x: float) -> int:
        best, bd = -1, -1.0
        for i, dd in enumerate(self.dents):
            inside = dd["x_min"] - dd["contact_radius"] <= x <= dd["x_max"] + dd["contact_radius"]
            if dd["end"] == k and inside and dd["delta_p"] > bd:
                bd, best = dd["delta_p"], i
        return best

    def stick_decide(self, yy: np.ndarray, k: int) -> float:
        """Friction mode at v_t = 0 (on a lumped node the F_n -> 0+ ratio is 0: stick)."""
        self.ends[k].fm = 0.0
        Fn, Fs = self.forces(yy)[1][k]
        if Fn > 0.0 and abs(Fs) > self.mu * Fn:
            return -1.0 if Fs > 0 else 1.0
        return 0.0

    def touch(self, yy: np.ndarray, t: float, k: int) -> None:
        s = self.ends[k]
        d, x, _vn, vt = self.kin(yy, k)
        di = s.dent
        reload = di >= 0
        dsw0 = switch_interference(self.p)
        if reload:
            dd = self.dents[di]
            s.ph, s.dm, s.dr = (1 if dd["delta_max"] > 0 else 0), dd["delta_max"], dd["delta_p"]
            s.rr = dd["unloading_radius"]
            s.dsw = dsw0 if dd["delta_max"] < dsw0 else math.inf
            dd["n_contacts"] += 1
        else:
            self.dents.append(
                dict(
                    end=k,
                    x_min=x,
                    x_max=x,
                    contact_radius=0.0,
                    delta_max=0.0,
                    delta_p=0.0,
                    unloading_radius=self.fe.R,
                    n_contacts=1,
                )
            )
            di = len(self.dents) - 1
            s.ph, s.dm, s.dr, s.rr, s.dsw = 0, 0.0, 0.0, self.fe.R, dsw0
        s.inn, s.comp, s.dent = True, True, di
        if self.mu > 0.0:
            s.fm = (1.0 if vt > 0 else -1.0) if vt != 0.0 else self.stick_decide(yy, k)
        rec = dict(end=k, start=t, x_start=x, delta_max=d, reload=int(reload), dent=di)
        self.cur[k] = rec
        self.contacts.append(rec)

    def turn(self, yy: np.ndarray, k: int) -> None:
        s = self.ends[k]
        d = self.kin(yy, k)[0]
        if s.comp and s.ph == 0:
            Fm = loading_force(self.law, self.p, d)
            dri = residual_depth(self.law, self.p, d, Fm)
            s.dm, s.dr, s.rr, s.ph = d, dri, unloading_radius(self.p[P_ESTAR], d, Fm, dri), 1
            dd = self.dents[s.dent]
            dd.update(delta_max=d, delta_p=dri, unloading_radius=s.rr)
            dd["contact_radius"] = max(
                dd["contact_radius"], loading_contact_radius(self.law, self.p, d)
            )
        s.comp = not s.comp

    def separate(self, yy: np.ndarray, t: float, k: int) -> None:
        s = self.ends[k]
        _d, x, _vn, _vt = self.kin(yy, k)
        c = self.cur[k]
        if c is not None:
            c.update(duration=t - c["start"], x_end=x, delta_r=s.dr)
        self.cur[k] = None
        s.inn, s.fm, s.comp = False, 0.0, False
        s.dent = self.in_dent(k, x)
        s.thr = self.dents[s.dent]["delta_p"] if s.dent >= 0 else 0.0

    def apply(self, yy: np.ndarray, t: float, k: int, kind: str) -> None:
        """The action of event ``kind`` of end k at (t, yy)."""
        s = self.ends[k]
        if kind == "limit":
            raise ValueError("the reference left the contact law's validity range")
        if kind == "touch":
            self.touch(yy, t, k)
        elif kind == "vn":
            self.turn(yy, k)
        elif kind == "reload":
            s.ph = 0
        elif kind == "switch":
            s.dsw = math.inf
        elif kind == "sep":
            self.separate(yy, t, k)
        elif s.fm != 0.0:
            s.fm = self.stick_decide(yy, k)
        else:
            s.fm = -1.0 if self.forces(yy)[1][k][1] > 0 else 1.0

    def track(self, ys: np.ndarray) -> None:
        """Largest interference and dent extents over the accepted points ``ys`` (columns)."""
        for j in range(ys.shape[1]):
            for k in range(2):
                if self.ends[k].inn:
                    d, x, _vn, _vt = self.kin(ys[:, j], k)
                    c = self.cur[k]
                    if c is not None:
                        c["delta_max"] = max(c["delta_max"], d)
                    dd = self.dents[self.ends[k].dent]
                    dd["x_min"], dd["x_max"] = min(dd["x_min"], x), max(dd["x_max"], x)

    def refresh_thresholds(self, yy: np.ndarray) -> None:
        for k in range(2):
            s = self.ends[k]
            if not s.inn:
                d, x, _vn, _vt = self.kin(yy, k)
                i = self.in_dent(k, x)
                thr = self.dents[i]["delta_p"] if i >= 0 else 0.0
                if d < thr or i == s.dent:
                    s.dent, s.thr = i, thr


def switch_interference(p: np.ndarray) -> float:
    """The law's elastic -> plastic switch interference [m] (inf: none)."""
    return float(p[P_DSW]) if (math.isfinite(p[P_DSW]) and p[P_DSW] > 0) else math.inf
