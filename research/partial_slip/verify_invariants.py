"""(d) Invariants of the new model: no energy gain, continuity of F_t at every switch, the
Coulomb bound |F_t| <= mu F_n, the rigid (Coulomb) limit as the tangential stiffness -> inf,
convergence with the number of cells N, and mu = 0.

Writes results/invariants.json and fig_invariants.png."""

from __future__ import annotations

import copy
import json
import os

import matplotlib.pyplot as plt
import numpy as np

import impactlab as il
from cases import Case, kharaz_case, velocities
from runners import rigid_coulomb, run_exact, run_new

HERE = os.path.dirname(os.path.abspath(__file__))
out = {}

# ---- energy, continuity, Coulomb bound over laws and angles
rows = []
cases = [("hertz (Kharaz)", kharaz_case(), 3.9),
         ("thornton", Case(il.AISI_201, il.AISI_1010, 5e-3, law="thornton", mu=0.3), 0.5),
         ("ghaednia", Case(il.AISI_201, il.AISI_1010, 5e-3, law="ghaednia", mu=0.3), 1.41),
         ("kogut-komvopoulos", Case(il.AISI_201, il.AISI_1010, 5e-3, law="kogut-komvopoulos",
                                    mu=0.3), 1.0),
         ("brake", Case(il.AISI_201, il.AISI_1010, 5e-3, law="brake", mu=0.3), 1.0)]
for name, c, V in cases:
    for th in (2, 5, 10, 20, 30, 45, 70):
        vt, vn = velocities(V, th)
        r = run_new(c, vt, vn)
        x = run_exact(c, vt, vn)
        E0 = 0.5 * c.m * V**2
        Ek = 0.5 * c.m * (r["vx"] ** 2 + r["vy"] ** 2) + 0.5 * c.I * r["w"] ** 2
        rows.append(dict(law=name, theta=th, erise=r["erise"], jump=r["jump"],
                         coulomb=r["coulomb"], diss=(E0 - Ek) / E0, nev=r["nev"],
                         et=r["et"], et_exact=x["et"], exact_erise=x["erise"]))
        print("%-18s %4.1f erise %.1e jump %.1e coulomb %+.1e diss %.4f ev %3d et %.5f exact %.5f"
              % (name, th, r["erise"], r["jump"], r["coulomb"], (E0 - Ek) / E0, r["nev"],
                 r["et"], x["et"]), flush=True)
out["energy_continuity"] = rows
print("max energy rise / E0: new %.2e, exact %.2e; max force jump / (mu F_max) %.2e; "
      "max (|F_t| - mu F_n)/(mu F_max) %.2e; min dissipation %.3e" % (
          max(r["erise"] for r in rows), max(r["exact_erise"] for r in rows),
          max(r["jump"] for r in rows), max(r["coulomb"] for r in rows),
          min(r["diss"] for r in rows)))

# ---- Coulomb limit: k_t -> infinity
c0 = kharaz_case()
lim = []
for th in (5, 10, 20, 30, 40):
    vt, vn = velocities(3.9, th)
    rig = rigid_coulomb(c0, vt, vn, 1.0)["et"]
    row = {"theta": th, "rigid": rig, "new": {}, "exact": {}}
    for k in (1, 10, 100, 1000, 10000):
        ck = copy.copy(c0)
        ck.Gs = c0.Gs * k
        x = run_exact(ck, vt, vn, nsteps=int(20000 * max(1, np.sqrt(k))))
        row["exact"][k] = x["et"]
        if k <= 100:
            r = run_new(c0, vt, vn, kt_factor=k)
            row["new"][k] = r["et"]
    lim.append(row)
    print("theta %d rigid %.5f | " % (th, rig) + " ".join(
        "k%g: exact %.5f new %s" % (k, row["exact"][k], ("%.5f" % row["new"][k]) if k in row["new"] else "-")
        for k in row["exact"]), flush=True)
out["coulomb_limit"] = lim

# ---- convergence with N
conv = {}
for N in (2, 4, 8, 16, 32, 64):
    errs = []
    for th in (1, 2, 4, 7, 10, 15, 20, 25, 30):
        vt, vn = velocities(3.9, th)
        errs.append(run_new(c0, vt, vn, n_springs=N)["et"] - run_exact(c0, vt, vn, nspr=1200, nsteps=40000)["et"])
    conv[N] = errs
    print("N = %2d: max |e_t - exact| = %.2e  (%s)" % (N, max(abs(e) for e in errs),
                                                      " ".join("%+.4f" % e for e in errs)), flush=True)
out["convergence"] = {str(k): v for k, v in conv.items()}

# ---- mu = 0
cz = kharaz_case(mu=0.0)
r = run_new(cz, *velocities(3.9, 20))
out["mu0"] = {"et": r["et"], "w": r["w"]}
print("mu = 0: e_t = %.12f, spin = %.3e" % (r["et"], r["w"]))

with open(os.path.join(HERE, "results", "invariants.json"), "w") as fh:
    json.dump(out, fh, indent=1, default=float)

fig, ax = plt.subplots(1, 3, figsize=(16, 4.8))
a = ax[0]
for row in lim:
    ks = sorted(row["exact"])
    a.loglog(ks, [abs(row["exact"][k] - row["rigid"]) + 1e-16 for k in ks], "o-",
             label="theta = %d deg" % row["theta"])
    kn = sorted(row["new"])
    a.loglog(kn, [abs(row["new"][k] - row["rigid"]) + 1e-16 for k in kn], "k+", ms=9)
a.set_ylim(1e-7, 0.3)
a.set_xlabel("tangential stiffness factor (G* multiplied)"); a.set_ylabel("|e_t - e_t(rigid Coulomb)|")
a.set_title("Coulomb limit (lines: exact M-D, +: new model)"); a.grid(alpha=.3, which="both")
a.legend(fontsize=8)
a = ax[1]
Ns = sorted(conv)
a.loglog(Ns, [max(abs(e) for e in conv[N]) for N in Ns], "o-", color="C3")
a.set_xticks(Ns); a.set_xticklabels([str(N) for N in Ns]); a.minorticks_off()
a.set_xlabel("number of cells N"); a.set_ylabel("max |e_t - e_t(exact)|, 1-30 deg")
a.set_title("convergence of the discrete model (Kharaz case)"); a.grid(alpha=.3, which="both")
a = ax[2]
c = kharaz_case()
vt, vn = velocities(3.9, 4)
from model import MDModel
r = MDModel(c, 16).run(vt, vn, history=True)
H = r["hist"]
E0 = 0.5 * c.m * 3.9**2
a.plot(H["t"] * 1e6, (H["E"] - E0) / E0, color="C3", label="(E_kin + E_n + E_t - E0)/E0")
a.plot(H["t"] * 1e6, H["Et"] / E0, color="C0", label="stored tangential E_t / E0")
a.plot(H["t"] * 1e6, H["T"] / (c.mu * np.maximum(H["F"], 1e-30)) * 1e-3, color="C2",
       label="F_t/(mu F_n) x 1e-3")
a.set_xlabel("t [us]"); a.set_title("energy balance, 4 deg Kharaz impact"); a.grid(alpha=.3)
a.legend(fontsize=8)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "fig_invariants.png"), dpi=120)
print("wrote fig_invariants.png")
