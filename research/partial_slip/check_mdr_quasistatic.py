"""MDR reference against the closed forms of Cattaneo-Mindlin and Mindlin-Deresiewicz."""
import numpy as np
import mdr

Gs, mu, R, Es = 1.0e10, 0.3, 1e-3, 1e11
a0 = 1e-4
N0 = 4.0 / 3.0 * Es * a0**3 / R
k0 = 8 * Gs * a0
ustar = 3 * mu * N0 / (16 * Gs * a0)   # displacement of full slip (Mindlin)
nspr, xmax = 4000, 1.0001 * a0

def cm_load(u):   # Cattaneo-Mindlin, constant N, from zero
    return mu * N0 * (1 - (1 - np.minimum(u, ustar) / ustar) ** 1.5)

n = 4001
# 1) constant N: load to 0.8 u*, unload to -0.8 u*, reload to +0.8 u*
u1 = np.linspace(0, 0.8 * ustar, n)
u2 = np.linspace(0.8 * ustar, -0.8 * ustar, 2 * n)
u3 = np.linspace(-0.8 * ustar, 0.8 * ustar, 2 * n)
u = np.concatenate([u1, u2, u3])
N = np.full(u.size, N0); a = np.full(u.size, a0)
F, E = mdr.quasistatic(N, u, a, Gs, mu, nspr, xmax)
T = -F
Ts = cm_load(0.8 * ustar)
exact = np.concatenate([cm_load(u1),
                        Ts - 2 * mu * N0 * (1 - (1 - (0.8 * ustar - u2) / (2 * ustar)) ** 1.5),
                        -Ts + 2 * mu * N0 * (1 - (1 - (u3 + 0.8 * ustar) / (2 * ustar)) ** 1.5)])
print("Cattaneo-Mindlin load/unload/reload: max |T - exact| / (mu N) =",
      np.abs(T - exact).max() / (mu * N0))
# dissipated energy per cycle: Mindlin-Deresiewicz closed form
# W = (9 mu^2 N^2/(10 a G* 8...)) use numerical loop area of the exact curves instead
loopT = np.concatenate([T[n:], ]); loopu = np.concatenate([u[n:]])
area = -np.trapezoid(T[n:], u[n:])
area_ex = -np.trapezoid(exact[n:], u[n:])
print("hysteresis loop area: MDR %.6e exact %.6e rel %.2e" % (area, area_ex, abs(area / area_ex - 1)))

# 2) M-D: N and T increased together from zero with dT/dN = c < mu -> no slip, T = c N
for c in (0.5 * mu, 0.99 * mu, 1.5 * mu):
    s = np.linspace(0, 1, n)
    Nt = N0 * s
    at = a0 * s ** (1 / 3)
    # choose u so that k0(a) du = c dN  (full-stick increments)
    dN = np.diff(Nt, prepend=0.0)
    du = np.where(at > 0, c * dN / (8 * Gs * np.maximum(at, 1e-30)), 0.0)
    ut = np.cumsum(du)
    F, E = mdr.quasistatic(Nt, ut, at, Gs, mu, nspr, xmax)
    T = -F
    print("M-D oblique loading dT/dN = %.2f mu: T/N at end = %.5f (expected %.5f)"
          % (c / mu, T[-1] / N0, min(c, mu)))

# 3) M-D: N constant, then N decreased at constant u (after loading to T = 0.5 mu N)
u1 = np.linspace(0, ustar * (1 - 0.5 ** (2 / 3)), n)   # T = 0.5 mu N0
Nn = np.concatenate([np.full(n, N0), np.linspace(N0, 0.3 * N0, n)])
an = a0 * (Nn / N0) ** (1 / 3)
un = np.concatenate([u1, np.full(n, u1[-1])])
F, E = mdr.quasistatic(Nn, un, an, Gs, mu, nspr, xmax)
T = -F
print("after loading to T=0.5 mu N0, T/N0 =", T[n - 1] / N0)
# exact (MDR analysis): uniform stick displacement field clipped by the shrinking limit
print("N decreased to 0.3 N0 at fixed u: T/(mu N) =", T[-1] / (mu * Nn[-1]),
      "(<= 1 required; T*a/a0 rule gives", 0.5 * N0 * mu * an[-1] / a0 / (mu * Nn[-1]), ")")

# 4) proportional preload (T/N = 0.6 mu, no slip: traction proportional to pressure), then T at
#    constant N: exact M-D (MDR) versus the Cattaneo-Masing closure used by the incremental
#    schemes (theta^3 = 1 - T/(mu N)), which assumes the traction field of a T-after-N history.
s = np.linspace(0, 1, n)
Nt = N0 * s
at = a0 * s ** (1 / 3)
dN = np.diff(Nt, prepend=0.0)
du = np.where(at > 0, 0.6 * mu * dN / (8 * Gs * np.maximum(at, 1e-30)), 0.0)
up = np.cumsum(du)
uext = up[-1] + np.linspace(0, 0.7 * ustar, n)[1:]
Nall = np.concatenate([Nt, np.full(n - 1, N0)])
aall = np.concatenate([at, np.full(n - 1, a0)])
uall = np.concatenate([up, uext])
F, E = mdr.quasistatic(Nall, uall, aall, Gs, mu, nspr, xmax)
T = -F[n - 1:] / (mu * N0)
dU = uall[n - 1:] - up[-1]
j = np.argmax(T > 0.9999)
# Cattaneo closure from T0 = 0.6 mu N: T = mu N [1 - (1 - (u + u0)/u*)^1.5], u0 from T0
u0 = ustar * (1 - 0.4 ** (2 / 3))
Tcl = 1 - (1 - np.minimum(dU + u0, ustar) / ustar) ** 1.5
jc = np.argmax(Tcl > 0.9999)
print("proportional preload 0.6 mu N, then T at constant N: extra displacement to gross slip "
      "exact M-D = %.3f u*, Cattaneo/Masing closure = %.3f u* (u* = 3 mu N/(16 G* a))"
      % (dU[j] / ustar, dU[jc] / ustar))
k = np.argmin(abs(dU - 0.2 * ustar))
print("   at du = 0.2 u*: T/(mu N) exact %.4f, closure %.4f; tangent stiffness / 8G*a: exact %.3f,"
      " closure %.3f" % (T[k], Tcl[k], np.gradient(T, dU)[k] * mu * N0 / k0,
                         np.gradient(Tcl, dU)[k] * mu * N0 / k0))

# 5) the discrete cell model (model.py, N cells) against Cattaneo-Mindlin
from model import cells_quasistatic
u1 = np.linspace(0, 0.8 * ustar, n)
u2 = np.linspace(0.8 * ustar, -0.8 * ustar, 2 * n)
u3 = np.linspace(-0.8 * ustar, 0.8 * ustar, 2 * n)
u = np.concatenate([u1, u2, u3])
Nc = np.full(u.size, N0); ac = np.full(u.size, a0)
Ts = cm_load(0.8 * ustar)
exact = np.concatenate([cm_load(u1),
                        Ts - 2 * mu * N0 * (1 - (1 - (0.8 * ustar - u2) / (2 * ustar)) ** 1.5),
                        -Ts + 2 * mu * N0 * (1 - (1 - (u3 + 0.8 * ustar) / (2 * ustar)) ** 1.5)])
for Ncell in (4, 8, 16, 32, 64):
    # contact established first (a grows 0 -> a0 at N growing with u = 0), then the loop
    m0 = 400
    grow = np.linspace(0, 1, m0)
    Tq, Eq = cells_quasistatic(np.concatenate([N0 * grow, Nc]), np.concatenate([np.zeros(m0), u]),
                               np.concatenate([a0 * grow ** (1 / 3), ac]), Gs, mu, Ncell, a0)
    err = np.abs(-Tq[m0:] - exact).max() / (mu * N0)
    print("discrete model N = %2d: Cattaneo-Mindlin load/unload/reload max |T - exact|/(mu N) = %.4f"
          % (Ncell, err))
