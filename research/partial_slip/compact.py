"""Compact incremental Mindlin-Deresiewicz models (engine candidates), integrated with
scipy's solve_ivp and events. Variants:

- "TY":  Thornton & Yin (1991) incremental scheme in continuous-time form,
         dT = k0 theta dL + sigma mu (1 - theta) dN, Masing turning points that shift by
         sigma_i mu dN; theta = 1 while |k0 dL| < mu dN.
- "TCC": Thornton, Cummins & Cleary (2011/2013) correction: while the normal force decreases,
         the tangential force and the turning points are scaled with the contact radius
         (T <- T a/a_old) instead of the mu dN term.

Sign conventions: T is the tangential force the flat exerts on the sphere (+x); v_slip is the
slip velocity of the sphere's contact point; dL = -v_slip dt is the loading increment (full
stick: dT = k0 dL, k0 = 8 G* a). Everything is for a sphere (normal and tangential motions
decoupled); gravity off.
"""

from __future__ import annotations

import math

import numpy as np
from scipy.integrate import solve_ivp

from impactlab.contact import kernels as K

# state indices
IY, IVX, IVY, IW, IT = 0, 1, 2, 3, 4
NSTACK = 6  # turning-point slots (states 5..)


class NormalLaw:
    """Normal force / contact radius on the loading and the Hertzian unloading branch."""

    def __init__(self, law_id, p):
        self.law = law_id
        self.p = p
        self.Es = p[K.P_ESTAR]
        self.R = p[K.P_R]
        self.unloading = False
        self.dm = self.dr = 0.0
        self.Rr = self.R
        self.af = 1.0

    def set_turning_point(self, dm):
        Fm, dr, Rr = K.turning_point(self.law, self.p, dm)
        am = K.contact_radius(self.law, self.p, dm, dm, 0.0, self.R)
        ah = math.sqrt(Rr * (dm - dr)) if dm > dr else 0.0
        self.af = am / ah if ah > 0 else 1.0
        self.dm, self.dr, self.Rr = dm, dr, Rr
        self.unloading = True

    def eval(self, d):
        """(F, dF/dd, a, da/dd)."""
        if not self.unloading:
            if d <= 0.0:
                return 0.0, 0.0, 0.0, 0.0
            F = K.loading_force(self.law, self.p, d)
            a = K.contact_radius(self.law, self.p, d, d, 0.0, self.R)
            if self.law == K.HERTZ:
                return F, 1.5 * F / d, a, 0.5 * a / d
            h = 1e-6 * d
            Fp = K.loading_force(self.law, self.p, d + h)
            Fm = K.loading_force(self.law, self.p, d - h)
            ap = K.contact_radius(self.law, self.p, d + h, d + h, 0.0, self.R)
            am = K.contact_radius(self.law, self.p, d - h, d - h, 0.0, self.R)
            return F, (Fp - Fm) / (2 * h), a, (ap - am) / (2 * h)
        x = d - self.dr
        if x <= 0.0:
            return 0.0, 0.0, 0.0, 0.0
        F = 4.0 / 3.0 * self.Es * math.sqrt(self.Rr) * x * math.sqrt(x)
        a = self.af * math.sqrt(self.Rr * x)
        return F, 1.5 * F / x, a, 0.5 * a / x

    def stored(self, d, F):
        """Recoverable normal elastic energy 0.4 F (delta - delta_r)."""
        if F <= 0.0:
            return 0.0
        dr = self.dr if self.unloading else K.residual_depth(self.law, self.p, d, F)
        return 0.4 * F * (d - dr)


class Compact:
    """One impact of a sphere with a compact M-D tangential model."""

    def __init__(self, case, variant="TY", rtol=1e-10, kt_factor=1.0):
        self.c = case
        self.variant = variant
        self.rtol = rtol
        self.ktf = kt_factor  # multiplies k0 (Coulomb-limit test: kt_factor -> inf)

    # ------------------------------------------------------------------ kinematics
    def _kin(self, y):
        c = self.c
        d = -y[IY]
        F, dF, a, da = self.nl.eval(d)
        vn = y[IVY]
        dd = -vn  # d delta / dt
        vs = y[IVX] + y[IW] * c.R
        return d, F, dF * dd, a, da * dd, vs

    def _theta(self, T, N, refs):
        """theta of the current branch (1 at its start, 0 at its slip limit)."""
        sg, Tref, cc = self.sigma, self._ref(refs), self.cfac
        if N <= 0.0:
            return 0.0
        chi = sg * (T - Tref) / (cc * self.c.mu * N)
        chi = min(max(chi, 0.0), 1.0)
        return (1.0 - chi) ** (1.0 / 3.0)

    def _ref(self, refs):
        return 0.0 if self.depth == 0 else refs[self.depth - 1]

    def rhs(self, t, y):
        c = self.c
        d, N, Nd, a, ad, vs = self._kin(y)
        T = y[IT]
        mu = c.mu
        k0 = self.ktf * 8.0 * c.Gs * a
        Ld = -vs
        dy = np.zeros_like(y)
        dy[IY] = y[IVY]
        dy[IVX] = T / c.m
        dy[IVY] = N / c.m
        dy[IW] = c.R * T / c.I
        refs = y[5:]
        if self.mode == "slip":
            dy[IT] = self.sigma * mu * Nd
            return dy
        if self.mode == "free":
            return dy
        scale = (self.variant == "TCC" and Nd < 0.0)
        if abs(k0 * Ld) < mu * Nd:  # normal growth dominates: no slip anywhere
            dT = k0 * Ld
        else:
            th = self._theta(T, N, refs)
            if scale:
                dT = k0 * th * Ld + (T * ad / a if a > 0 else 0.0)
            else:
                dT = k0 * th * Ld + self.sigma * mu * (1.0 - th) * Nd
        dy[IT] = dT
        # turning points: shift (TY) or scale (TCC, unloading)
        for i in range(self.depth):
            if scale:
                dy[5 + i] = refs[i] * ad / a if a > 0 else 0.0
            else:
                dy[5 + i] = self.tp_sigma[i] * mu * Nd
        return dy

    # ------------------------------------------------------------------ events
    def _events(self):
        c = self.c
        evs = []

        def ev_vn(t, y):  # normal turning point (vn from - to +)
            return y[IVY]
        ev_vn.terminal = True
        ev_vn.direction = 1

        def ev_sep(t, y):  # separation: delta reaches delta_r while unloading
            return (-y[IY]) - self.nl.dr
        ev_sep.terminal = True
        ev_sep.direction = -1
        if not self.nl.unloading:
            evs.append(("vn", ev_vn))
        else:
            evs.append(("sep", ev_sep))
        if self.mode == "slip":
            def ev_stick(t, y):  # trial rate points back inside: sigma k0 L' - mu N' < 0
                d, N, Nd, a, ad, vs = self._kin(y)
                k0 = self.ktf * 8.0 * c.Gs * a
                return self.sigma * k0 * (-vs) - c.mu * Nd
            ev_stick.terminal = True
            ev_stick.direction = -1
            evs.append(("stick", ev_stick))
        elif self.mode == "branch":
            def ev_rev(t, y):  # reversal of the loading direction
                d, N, Nd, a, ad, vs = self._kin(y)
                k0 = self.ktf * 8.0 * c.Gs * a
                return self.sigma * k0 * (-vs) + c.mu * max(Nd, 0.0)
            ev_rev.terminal = True
            ev_rev.direction = -1
            evs.append(("rev", ev_rev))

            def ev_gross(t, y):  # slip limit of the branch or Coulomb limit
                d, N, Nd, a, ad, vs = self._kin(y)
                T = y[IT]
                refs = y[5:]
                chi = self.sigma * (T - self._ref(refs)) / (self.cfac * c.mu * N) if N > 0 else 1.0
                # Coulomb guard in both directions (the incremental schemes can overshoot it)
                return max(chi - 1.0, abs(T) / (c.mu * N) - 1.0 if N > 0 else 0.0)
            ev_gross.terminal = True
            ev_gross.direction = 1
            evs.append(("gross", ev_gross))
            if self.depth >= 1:
                def ev_mem(t, y):  # Masing memory: reached the previous turning point
                    refs = y[5:]
                    if self.depth >= 2:
                        target = refs[self.depth - 2]
                    else:  # first reversal from the skeleton: mirror point -T_1
                        target = -refs[0]
                    return self.sigma * (y[IT] - target)
                ev_mem.terminal = True
                ev_mem.direction = 1
                evs.append(("mem", ev_mem))
        return evs

    # ------------------------------------------------------------------ driver
    def run(self, vt0, vn0, w0=0.0, history=False):
        c = self.c
        self.nl = NormalLaw(c.law_id, c.p)
        y = np.zeros(5 + NSTACK)
        y[IVX], y[IVY], y[IW] = vt0, -abs(vn0), w0
        # first touch: Hertzian start, |T|/(mu N) -> 4 G* |vt_c| / (mu E* |vn|)
        vs0 = vt0 + w0 * c.R
        ratio = self.ktf * 4.0 * c.Gs * abs(vs0) / (c.mu * c.Es * abs(vn0))
        self.sigma = -1.0 if vs0 > 0 else 1.0
        self.depth = 0
        self.cfac = 1.0
        self.tp_sigma = [0.0] * NSTACK
        self.mode = "slip" if ratio > 1.0 and vs0 != 0.0 else "branch"
        if self.mu_zero():
            self.mode = "free"
        t = 0.0
        Tc = c.hertz_time(vn0)
        hist_t, hist_y, modes = [], [], []
        nev = 0
        E0 = 0.5 * c.m * (vt0**2 + vn0**2) + 0.5 * c.I * w0**2
        self.erise = 0.0
        self.coul = 0.0
        # start slightly inside contact to avoid the 0/0 at delta = 0
        t_end = 20 * Tc
        while True:
            evs = self._events()
            names = [n for n, _ in evs]
            sol = solve_ivp(self.rhs, (t, t_end), y, method="DOP853", rtol=self.rtol,
                            atol=self._atol(vn0, Tc), events=[e for _, e in evs],
                            dense_output=False, first_step=Tc * 1e-4 if t == 0 else None,
                            max_step=Tc / 20)
            if history:
                hist_t.append(sol.t)
                hist_y.append(sol.y)
                modes += [self.mode] * sol.t.size
            self._diag(sol.y, E0)
            if sol.status != 1:
                raise RuntimeError("integration ended without event: " + str(sol.message))
            k = next(i for i, te in enumerate(sol.t_events) if te.size)
            t = sol.t_events[k][0]
            y = sol.y_events[k][0].copy()
            name = names[k]
            nev += 1
            if nev > 200:
                raise RuntimeError("too many events")
            if name == "sep":
                break
            self._switch(name, t, y)
        self.nev = nev
        res = dict(vx=y[IVX], vy=y[IVY], w=y[IW], e=-y[IVY] / (-abs(vn0)),
                   et=y[IVX] / vt0 if vt0 != 0 else math.nan, T=t, nev=nev,
                   erise=self.erise / E0, coulomb_excess=self.coul)
        if history:
            res["t"] = np.concatenate(hist_t)
            res["y"] = np.concatenate(hist_y, axis=1)
            res["modes"] = modes
        return res

    def mu_zero(self):
        return self.c.mu == 0.0

    def _atol(self, vn0, Tc):
        c = self.c
        dstar = abs(vn0) * Tc / 3.0
        Fs = c.m * abs(vn0) / Tc
        a = np.full(5 + NSTACK, 1e-12 * Fs)
        a[IY] = 1e-12 * dstar
        a[IVX] = a[IVY] = 1e-12 * abs(vn0)
        a[IW] = 1e-12 * abs(vn0) / c.R
        return a

    def _diag(self, Y, E0):
        c = self.c
        for j in range(Y.shape[1]):
            y = Y[:, j]
            d, N, Nd, a, ad, vs = self._kin(y)
            T = y[IT]
            Ek = 0.5 * c.m * (y[IVX] ** 2 + y[IVY] ** 2) + 0.5 * c.I * y[IW] ** 2
            En = self.nl.stored(d, N)
            k0 = self.ktf * 8.0 * c.Gs * a
            Et = 0.5 * T * T / k0 if k0 > 0 else 0.0  # lower bound of the stored energy
            self.erise = max(self.erise, Ek + En + Et - E0)
            self.Nmax = max(getattr(self, "Nmax", 0.0), N)
            if N > 0:
                self.coul = max(self.coul, (abs(T) - c.mu * N) / (c.mu * self.Nmax))

    def _switch(self, name, t, y):
        c = self.c
        d, N, Nd, a, ad, vs = self._kin(y)
        k0 = self.ktf * 8.0 * c.Gs * a
        if name == "vn":
            self.nl.set_turning_point(-y[IY])
            return
        if name == "gross":
            self.mode = "slip"
            if y[IT] != 0.0:
                self.sigma = 1.0 if y[IT] > 0 else -1.0
            y[IT] = self.sigma * c.mu * N
            self.depth = 0
            return
        if name == "stick":
            # whole contact at the limit in direction sigma: skeleton branch, T = sigma mu N
            self.mode = "branch"
            self.depth = 0
            self.cfac = 1.0
            if self.sigma * k0 * (-vs) + c.mu * max(Nd, 0.0) < 0.0:
                self._reverse(y)
            return
        if name == "rev":
            self._reverse(y)
            return
        if name == "mem":
            if self.depth >= 2:
                self.depth -= 2
                self.cfac = 2.0 if self.depth >= 1 else 1.0
                # direction unchanged (branch i-2 has the same direction as branch i)
            else:
                self.depth = 0
                self.cfac = 1.0
            return
        raise RuntimeError(name)

    def _reverse(self, y):
        if self.depth >= NSTACK:
            raise RuntimeError("turning-point stack full")
        y[5 + self.depth] = y[IT]
        self.tp_sigma[self.depth] = self.sigma
        self.depth += 1
        self.sigma = -self.sigma
        self.cfac = 2.0
