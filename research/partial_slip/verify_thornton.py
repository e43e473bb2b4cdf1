"""(b) Thornton's normalised representation: tangential restitution e_t = v_x,out/v_x,in and
normalised rebound spin Omega = 2 omega R / (mu (1 + e) |v_n|) versus
Psi = 2 tan(theta) / (mu (1 + e)), for an elastic (Hertz) and two elastic-plastic normal laws
(Thornton 1997, Ghaednia 2016 from the package). Rigid-body limits for a solid sphere:
e_t = 5/7, Omega = (5/7) Psi for Psi < 7 (rolling); e_t = 1 - 2/Psi, Omega = 5 beyond (sliding).

(Normalisation as used by Thornton and co-workers, e.g. Wu, Thornton & Li, Proc. R. Soc. A 465
(2009) 937, doi:10.1098/rspa.2008.0410; Thornton, Cummins & Cleary, Powder Technol. 233 (2013)
30, doi:10.1016/j.powtec.2012.08.012.)

Writes results/thornton.json and fig_thornton.png."""

from __future__ import annotations

import json
import math
import os

import matplotlib.pyplot as plt
import numpy as np

import impactlab as il
from cases import Case
from runners import rigid_coulomb, run_exact, run_existing, run_new, run_ty

HERE = os.path.dirname(os.path.abspath(__file__))
MU = 0.3
R = 5e-3
CASES = [  # (label, law, law_params, v_n)
    ("Hertz (elastic), |v_n| = 1 m/s", "hertz", None, 1.0),
    ("Thornton (elastic-perfectly plastic), |v_n| = 0.05 m/s", "thornton", None, 0.05),
    ("Thornton (elastic-perfectly plastic), |v_n| = 0.5 m/s", "thornton", None, 0.5),
    ("Ghaednia (Jackson-Green family), |v_n| = 1.41 m/s", "ghaednia", None, 1.41),
]
psi_grid = np.unique(np.concatenate([np.linspace(0.1, 2.0, 11), np.linspace(2.0, 9.0, 22),
                                     np.linspace(9.0, 14.0, 6)]))
res = {}
for label, law, lp, vn in CASES:
    key = "%s@%g" % (law, vn)
    c = Case(il.AISI_201, il.AISI_1010, R, law=law, mu=MU, law_params=lp)
    e = run_exact(c, 0.0, -vn)["e"]  # normal COR (normal and tangential decoupled for a sphere)
    models = {"new": run_new, "exact": run_exact, "existing": run_existing, "TY": run_ty}
    Rr = {m: {"Psi": [], "et": [], "Om": [], "e": []} for m in list(models) + ["rigid"]}
    for P in psi_grid:
        vt = P * MU * (1 + e) * vn / 2.0
        for m, f in models.items():
            r = f(c, vt, -vn)
            ee = r["e"]
            Rr[m]["Psi"].append(float(P)); Rr[m]["et"].append(float(r["et"]))
            Rr[m]["Om"].append(float(-2 * r["w"] * R / (MU * (1 + e) * vn))); Rr[m]["e"].append(float(ee))
        r = rigid_coulomb(c, vt, -vn, e)
        Rr["rigid"]["Psi"].append(float(P)); Rr["rigid"]["et"].append(float(r["et"]))
        Rr["rigid"]["Om"].append(float(-2 * r["w"] * R / (MU * (1 + e) * vn))); Rr["rigid"]["e"].append(e)
        print(key, "%.2f" % P, " ".join("%s %.4f/%.3f" % (m, Rr[m]["et"][-1], Rr[m]["Om"][-1])
                                        for m in Rr), flush=True)
    err = {m: float(np.max(np.abs(np.array(Rr[m]["et"]) - np.array(Rr["exact"]["et"]))))
           for m in Rr}
    res[key] = {"label": label, "law": law, "e": e, "eta": c.eta, "chi": c.chi, "vn": vn, "curves": Rr,
                "max_err_et_vs_exact": err,
                "delta_max_over_delta_y": float(run_exact(c, 0.0, -vn)["dmax"] / c.p[4])
                if math.isfinite(c.p[4]) else None}
    print(key, "e =", e, "max |e_t - exact|:", err)

with open(os.path.join(HERE, "results", "thornton.json"), "w") as fh:
    json.dump(res, fh, indent=1)

cols = {"hertz@1": "C3", "thornton@0.05": "C1", "thornton@0.5": "C0", "ghaednia@1.41": "C2"}
fig, ax = plt.subplots(1, 3, figsize=(17, 5.4))
Ps = np.linspace(0.01, 14, 300)
for a in ax[:2]:
    pass
ax[0].plot(Ps, np.where(Ps < 7, 5 / 7, 1 - 2 / Ps), color="0.6", lw=1, label="rigid-body Coulomb")
ax[1].plot(Ps, np.where(Ps < 7, 5 / 7 * Ps, 5.0), color="0.6", lw=1, label="rigid-body Coulomb")
for law, d in res.items():
    C = d["curves"]
    lab = "%s: e = %.3f" % (law, d["e"])
    ax[0].plot(C["new"]["Psi"], C["new"]["et"], color=cols[law], lw=2.2, label=lab + " new")
    ax[0].plot(C["exact"]["Psi"], C["exact"]["et"], color="k", lw=0.8, ls="--")
    ax[0].plot(C["existing"]["Psi"], C["existing"]["et"], color=cols[law], lw=1.0, ls=":",
               label=lab + " existing 'mindlin'")
    ax[1].plot(C["new"]["Psi"], C["new"]["Om"], color=cols[law], lw=2.2, label=lab + " new")
    ax[1].plot(C["exact"]["Psi"], C["exact"]["Om"], color="k", lw=0.8, ls="--")
    ax[1].plot(C["existing"]["Psi"], C["existing"]["Om"], color=cols[law], lw=1.0, ls=":")
    ax[2].plot(C["new"]["Psi"], np.array(C["new"]["et"]) - np.array(C["exact"]["et"]),
               color=cols[law], lw=2.0, label=law + " new - exact")
    ax[2].plot(C["existing"]["Psi"], np.array(C["existing"]["et"]) - np.array(C["exact"]["et"]),
               color=cols[law], lw=1.0, ls=":", label=law + " existing - exact")
    ax[2].plot(C["TY"]["Psi"], np.array(C["TY"]["et"]) - np.array(C["exact"]["et"]),
               color=cols[law], lw=1.0, ls="-.", label=law + " Thornton-Yin - exact")
ax[0].set_xlabel("Psi = 2 tan(theta) / (mu (1+e))"); ax[0].set_ylabel("e_t = v_x,out / v_x,in")
ax[0].set_title("tangential restitution (dashed black: exact M-D reference)")
ax[0].set_ylim(0.4, 1.0); ax[0].grid(alpha=.3); ax[0].legend(fontsize=7, loc="lower right")
ax[1].set_xlabel("Psi"); ax[1].set_ylabel("Omega = 2 omega R / (mu (1+e) |v_n|)")
ax[1].set_title("normalised rebound spin"); ax[1].grid(alpha=.3); ax[1].legend(fontsize=7)
ax[2].set_xlabel("Psi"); ax[2].set_ylabel("e_t - e_t(exact M-D)"); ax[2].grid(alpha=.3)
ax[2].set_title("deviation from the exact M-D solution of the same model"); ax[2].legend(fontsize=7)
for a in ax:
    a.set_xlim(0, 14)
fig.suptitle("Thornton's normalised representation, AISI 201 sphere (R = 5 mm) on AISI 1010, "
             "mu = %.1f: elastic and elastic-plastic normal laws" % MU, fontsize=11)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "fig_thornton.png"), dpi=120)
print("wrote fig_thornton.png")
