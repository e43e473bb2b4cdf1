"""Prototype of the proposed tangential model ("md" = Mindlin-Deresiewicz partial slip with
history), as an ODE with events -- the reference for porting into the compiled engine.

Model (model.md has the derivation and citations): the Method-of-Dimensionality-Reduction (MDR)
representation of the Cattaneo-Mindlin problem -- a line of independent elastic-perfectly-
plastic tangential elements under the Hertzian Coulomb limit -- discretised into N cells of
width dx = a_est/N on 0 <= x <= a(t) (mirrored to -x). Cell i = [i dx, (i+1) dx] carries the
elastic force f_i (both halves), its stiffness is 2 G_1 l_i with l_i its length inside the
contact (G_1 = 4 G*, so the total full-stick stiffness is exactly 8 G* a), and its slip limit
is L_i = mu F_n (3/2a) int_{cell, x<a} (1 - x^2/a^2) dx (sum L_i = mu F_n exactly).

Stick:  df_i/dt = 2 G_1 l_i v_slip                (edge cell growing: new material unstressed)
        df_i/dt = 2 G_1 l_i v_slip + f_i l_i'/l_i (edge cell shrinking: leaving material takes
                                                   its share of the force)
Slip:   f_i = s_i L_i (algebraic).
F_t = -sum f_i. Memory = the vector f (generalises the M-D turning points).

ODE state: [y_C, v_x, v_y, omega, u, f_0 .. f_{M-1}] (u = integral of v_slip, reported only).
Events: cell birth (a = i dx rising), release (a = i dx falling), stick->slip (|f| = L),
slip->stick (L' - s f'_trial = 0 rising), normal turning point (v_n = 0), separation
(delta = delta_r). F_t is continuous at every event.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from compact import NormalLaw

IY, IVX, IVY, IW, IU, IS = 0, 1, 2, 3, 4, 5
OUT, STICK, SLIP = 0, 1, 2


class MDModel:
    """Oblique impact of a sphere with the discrete MDR Mindlin-Deresiewicz tangential model.

    case: cases.Case (law, p, R, m, I, Gs, mu). n_springs: springs over the estimated maximum
    contact radius a_est (default: from a frictionless normal pre-pass, exact for a sphere).
    kt_factor scales G* (rigid/Coulomb limit test)."""

    def __init__(self, case, n_springs=16, a_est=None, rtol=1e-9, kt_factor=1.0, extra=4):
        self.c = case
        self.n = n_springs
        self.a_est = a_est
        self.rtol = rtol
        self.ktf = kt_factor
        self.extra = extra

    # -------------------------------------------------------------------- spring field
    def _setup(self, vn0):
        c = self.c
        if self.a_est is None:
            import mdr
            dmax, amax = mdr.normal_max(c.law_id, c.p, c.m, vn0, c.hertz_time(vn0) / 20000)
            self.a_est = amax * 1.0001
        self.dx = self.a_est / self.n
        self.M = self.n * self.extra  # room if the contact grows beyond the estimate
        self.xl = np.arange(self.M) * self.dx       # cell i = [xl_i, xr_i]; born at a = xl_i
        self.xr = self.xl + self.dx
        self.x = self.xl  # birth / release position
        self.G1 = 4.0 * c.Gs * self.ktf

    def _limits(self, F, Fd, a, ad):
        """(L, dL/dt): slip limit of every cell, L_i = mu F (3/2a) int_{cell_i, |x|<a}
        (1 - x^2/a^2) dx -- the Hertzian line load integrated exactly over the part of the
        cell in contact, so that sum L_i = mu F_n exactly and L_i -> 0 continuously as the
        contact edge crosses the cell's inner edge (birth / release)."""
        L = np.zeros(self.M)
        Ld = np.zeros(self.M)
        if a <= 0.0 or F <= 0.0:
            return L, Ld
        l = self.xl
        r = np.minimum(self.xr, a)
        on = l < a
        l, r = l[on], r[on]
        part = self.xr[on] > a  # the cell the contact edge lies in
        g = 1.5 / a * (r - l) - 0.5 * (r**3 - l**3) / a**3
        dg = np.where(part, 1.5 * l / a**2 - 1.5 * l**3 / a**4,
                      -1.5 * (r - l) / a**2 + 1.5 * (r**3 - l**3) / a**4)
        mu = self.c.mu
        L[on] = mu * F * g
        Ld[on] = mu * (Fd * g + F * dg * ad)
        return L, Ld

    def _state(self, y):
        c = self.c
        d = -y[IY]
        F, dF, a, da = self.nl.eval(d)
        dd = -y[IVY]
        Fd, ad = dF * dd, da * dd
        vs = y[IVX] + y[IW] * c.R
        L, Ld = self._limits(F, Fd, a, ad)
        f = y[IS:].copy()
        sl = self.mode == SLIP
        f[sl] = self.sgn[sl] * L[sl]
        f[self.mode == OUT] = 0.0
        T = -f.sum()
        return d, F, Fd, a, ad, vs, L, Ld, f, T

    def _lengths(self, a, ad):
        """(l_i, l_i') contact length of every cell and its rate."""
        l = np.clip(a - self.xl, 0.0, self.dx)
        edge = (self.xl < a) & (self.xr > a)
        ld = np.where(edge, ad, 0.0)
        return l, ld

    def _ftrial(self, f, vs, a, ad):
        """Stick rate of every cell's force."""
        l, ld = self._lengths(a, ad)
        r = 2.0 * self.G1 * l * vs
        shrink = (ld < 0.0) & (l > 0.0)
        r[shrink] += f[shrink] * ld[shrink] / l[shrink]
        return r

    # -------------------------------------------------------------------- ODE
    def rhs(self, t, y):
        c = self.c
        d, F, Fd, a, ad, vs, L, Ld, f, T = self._state(y)
        dy = np.zeros_like(y)
        dy[IY] = y[IVY]
        dy[IVX] = T / c.m
        dy[IVY] = F / c.m
        dy[IW] = c.R * T / c.I
        dy[IU] = vs
        ft = self._ftrial(f, vs, a, ad)
        st = self.mode == STICK
        dy[IS:][st] = ft[st]
        sl = self.mode == SLIP
        dy[IS:][sl] = self.sgn[sl] * Ld[sl]
        return dy

    def _events(self):
        evs = []
        if not self.nl.unloading:
            def ev_vn(t, y):
                return y[IVY]
            ev_vn.terminal, ev_vn.direction = True, 1
            evs.append(("vn", -1, ev_vn))
        else:
            def ev_sep(t, y):
                return (-y[IY]) - self.nl.dr
            ev_sep.terminal, ev_sep.direction = True, -1
            evs.append(("sep", -1, ev_sep))
        nin = int(np.count_nonzero(self.mode != OUT))
        if nin < self.M:
            j = nin  # next spring to be born

            def ev_birth(t, y, j=j):
                d = -y[IY]
                F, dF, a, da = self.nl.eval(d)
                return a - self.x[j]
            ev_birth.terminal, ev_birth.direction = True, 1
            evs.append(("birth", j, ev_birth))
        if nin > 0:
            j = nin - 1

            def ev_rel(t, y, j=j):
                d = -y[IY]
                F, dF, a, da = self.nl.eval(d)
                return self.x[j] - a
            ev_rel.terminal, ev_rel.direction = True, 1
            evs.append(("release", j, ev_rel))
        for i in range(nin):
            if self.mode[i] == STICK:
                def ev_slip(t, y, i=i):  # small hysteresis: no same-instant ping-pong
                    s = self._state(y)
                    return abs(y[IS + i]) - s[6][i] * (1.0 + 1e-9) - self.ftol
                ev_slip.terminal, ev_slip.direction = True, 1
                evs.append(("slip", i, ev_slip))
            elif self.mode[i] == SLIP:
                def ev_stick(t, y, i=i):
                    s = self._state(y)
                    if s[3] <= self.x[i]:  # outside the contact: only its release may follow
                        return -1.0
                    ft = self._ftrial(s[8], s[5], s[3], s[4])[i]
                    l = min(max(s[3] - self.xl[i], 0.0), self.dx)
                    return s[7][i] - self.sgn[i] * ft - 2.0 * self.G1 * l * self.vtol
                ev_stick.terminal, ev_stick.direction = True, 1
                evs.append(("stick", i, ev_stick))
        return evs

    def _settle(self, y):
        """Apply every switch that is already due at a restart (several cells can change
        mode within one step; only the first event is located, the others are found here, as
        the engine does for a friction state found outside its domain)."""
        for _ in range(4 * self.M + 8):
            d, F, Fd, a, ad, vs, L, Ld, f, T = self._state(y)
            nin = int(np.count_nonzero(self.mode != OUT))
            if nin < self.M and ad > 0.0 and a > self.xl[nin] + 1e-9 * self.dx:
                self._switch("birth", nin, y)
                continue
            if nin > 0 and ad < 0.0 and a < self.xl[nin - 1] - 1e-9 * self.dx:
                self._switch("release", nin - 1, y)
                continue
            ft = self._ftrial(f, vs, a, ad)
            changed = False
            for i in range(nin):
                if self.mode[i] == STICK and abs(y[IS + i]) > L[i] * (1.0 + 1e-9) + self.ftol:
                    self._switch("slip", i, y)
                    changed = True
                elif self.mode[i] == SLIP and self.x[i] < a:
                    l = min(max(a - self.xl[i], 0.0), self.dx)
                    if Ld[i] - self.sgn[i] * ft[i] > 2.0 * self.G1 * l * self.vtol:
                        self._switch("stick", i, y)
                        changed = True
            if not changed:
                return
        raise RuntimeError("mode switches do not settle")

    def _switch(self, name, i, y):
        d, F, Fd, a, ad, vs, L, Ld, w, T = self._state(y)
        if name == "vn":
            self.nl.set_turning_point(-y[IY])
            return
        if name == "birth":
            # born unstressed; near its inner edge L ~ 1.5 mu F l^2/a^2 and the stick trial
            # ~ G_1 |v| l^2 / a': it slips at once iff G_1 |v| a^2 > 1.5 mu F a'
            y[IS + i] = 0.0
            if a <= 0.0:  # first touch: Hertzian limit G_1 |v| a^2 / (1.5 mu F a') -> G_1|v|/(mu E* v_n)
                slip = vs != 0.0 and self.G1 * abs(vs) > self.c.mu * self.c.Es * abs(y[IVY])
            else:
                slip = vs != 0.0 and self.G1 * abs(vs) * a * a > 1.5 * self.c.mu * F * ad
            if slip:
                self.mode[i], self.sgn[i] = SLIP, (1.0 if vs > 0 else -1.0)
            else:
                self.mode[i] = STICK
            return
        if name == "release":
            self.mode[i] = OUT
            y[IS + i] = 0.0
            return
        if name == "slip":
            self.mode[i] = SLIP
            self.sgn[i] = 1.0 if y[IS + i] > 0 else -1.0
            y[IS + i] = self.sgn[i] * L[i]
            return
        if name == "stick":
            y[IS + i] = self.sgn[i] * L[i]
            self.mode[i] = STICK
            return
        raise RuntimeError(name)

    # -------------------------------------------------------------------- driver
    def run(self, vt0, vn0, w0=0.0, history=False, max_events=5000):
        c = self.c
        self.nl = NormalLaw(c.law_id, c.p)
        self._setup(vn0)
        self.mode = np.zeros(self.M, dtype=int)
        self.sgn = np.zeros(self.M)
        y = np.zeros(IS + self.M)
        y[IVX], y[IVY], y[IW] = vt0, -abs(vn0), w0
        Tc = c.hertz_time(vn0)
        self.vtol = 1e-9 * abs(vn0)                    # slip-rate hysteresis [m/s]
        self.ftol = 1e-13 * c.m * abs(vn0) / Tc        # force hysteresis [N]
        E0 = 0.5 * c.m * (vt0**2 + vn0**2) + 0.5 * c.I * w0**2
        atol = np.empty_like(y)
        atol[IY] = 1e-12 * abs(vn0) * Tc
        atol[IVX] = atol[IVY] = 1e-12 * abs(vn0)
        atol[IW] = 1e-12 * abs(vn0) / c.R
        atol[IU] = 1e-12 * abs(vn0) * Tc
        atol[IS:] = 1e-12 * c.m * abs(vn0) / Tc
        t = 0.0
        nev = 0
        self.erise = 0.0
        self.jump = 0.0
        self.coulomb = 0.0
        self.Fmax = 0.0
        H = {"t": [], "T": [], "F": [], "vs": [], "nslip": [], "nin": [], "E": [], "Et": [],
             "a": [], "d": []}
        while True:
            evs = self._events()
            sol = solve_ivp(self.rhs, (t, 40 * Tc), y, method="DOP853", rtol=self.rtol,
                            atol=atol, events=[e for _, _, e in evs], max_step=Tc / 30)
            self._diag(sol.t, sol.y, E0, H, history)
            if sol.status != 1:
                raise RuntimeError("no event before the end: " + sol.message)
            cand = sorted((te[0], j) for j, te in enumerate(sol.t_events) if te.size)
            k = cand[0][1]
            for tj, j in cand:  # ties: geometric/normal events before stick/slip switches
                if tj - cand[0][0] <= 1e-12 * Tc and evs[j][0] in ("vn", "sep", "birth",
                                                                      "release"):
                    k = j
                    break
            t = sol.t_events[k][0]
            y = sol.y_events[k][0].copy()
            name, i, _ = evs[k]
            nev += 1
            if nev > max_events:
                raise RuntimeError("too many events")
            if name == "sep":
                break
            Tb = self._state(y)[-1]
            self._switch(name, i, y)
            self._settle(y)
            Ta = self._state(y)[-1]
            self.jump = max(self.jump, abs(Ta - Tb))
        d, F, Fd, a, ad, vs, L, Ld, w, T = self._state(y)
        res = dict(vx=y[IVX], vy=y[IVY], w=y[IW], e=y[IVY] / abs(vn0),
                   et=y[IVX] / vt0 if vt0 != 0 else math.nan, vslip_out=vs, T=t, nev=nev,
                   erise=self.erise / E0, jump=self.jump / max(self.Fmax, 1e-300),
                   coulomb=self.coulomb / (c.mu * self.Fmax) if c.mu > 0 else 0.0, n_active=int(np.count_nonzero(self.x < self.a_est)),
                   Ediss=(E0 - self._energy(y, F, d)[0]) / E0)
        if history:
            res["hist"] = {k_: np.array(v) for k_, v in H.items()}
        return res

    def _energy(self, y, F, d):
        c = self.c
        Ek = 0.5 * c.m * (y[IVX] ** 2 + y[IVY] ** 2) + 0.5 * c.I * y[IW] ** 2
        En = self.nl.stored(d, F)
        s = self._state(y)
        f = s[8]
        l, _ = self._lengths(s[3], s[4])
        on = l > 0.0
        Et = float(np.sum(f[on] ** 2 / (4.0 * self.G1 * l[on])))
        return Ek + En + Et, Et

    def _diag(self, ts, Y, E0, H, history):
        c = self.c
        for j in range(Y.shape[1]):
            y = Y[:, j]
            d, F, Fd, a, ad, vs, L, Ld, w, T = self._state(y)
            E, Et = self._energy(y, F, d)
            self.erise = max(self.erise, E - E0)
            self.Fmax = max(self.Fmax, F)
            if F > 0:
                self.coulomb = max(self.coulomb, abs(T) - c.mu * F)  # [N], normalised at the end
            if history:
                H["t"].append(ts[j]); H["T"].append(T); H["F"].append(F); H["vs"].append(vs)
                H["nslip"].append(int(np.count_nonzero(self.mode == SLIP)))
                H["nin"].append(int(np.count_nonzero(self.mode != OUT)))
                H["E"].append(E); H["Et"].append(Et); H["a"].append(a); H["d"].append(d)


def cells_quasistatic(F_of_t, u_of_t, a_of_t, Gs, mu, n_cells, a_ref):
    """The same discrete model driven quasi-statically by prescribed histories of F_n, the
    tangential displacement u and the contact radius a (fixed-step form of the rate rules with
    the exact clamp). Returns F_t (force on the body, = -sum f) and the stored energy."""
    G1 = 4.0 * Gs
    dx = a_ref / n_cells
    M = 4 * n_cells
    xl = np.arange(M) * dx
    xr = xl + dx
    f = np.zeros(M)
    lold = np.zeros(M)
    n = len(F_of_t)
    T = np.zeros(n)
    E = np.zeros(n)
    for k in range(n):
        du = u_of_t[k] - (u_of_t[k - 1] if k > 0 else 0.0)
        a = a_of_t[k]
        F = F_of_t[k]
        l = np.clip(a - xl, 0.0, dx)
        # shrinking cells carry away their share of the force; growing ones add unstressed material
        shr = (l < lold) & (lold > 0)
        f[shr] *= l[shr] / lold[shr]
        f += 2.0 * G1 * 0.5 * (l + lold) * du
        f[l <= 0] = 0.0
        if a > 0 and F > 0:
            r = np.minimum(xr, a)
            on = xl < a
            g = np.where(on, 1.5 / a * (r - xl) - 0.5 * (r**3 - xl**3) / a**3, 0.0)
            L = mu * F * g
            f = np.clip(f, -L, L)
        lold = l
        T[k] = -f.sum()
        on = l > 0
        E[k] = np.sum(f[on] ** 2 / (4.0 * G1 * l[on]))
    return T, E
