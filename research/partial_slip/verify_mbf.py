"""(a) Maw, Barber & Fawcett (1976, 1981): elastic sphere, local angle of reflection psi2 versus
local angle of incidence psi1 over the whole range, for the solid sphere (chi = 1.441,
nu = 0.3) and MBF's thin diametral slice (chi = 1.2558, nu = 0.28).

MBF's theory is computed independently: their problem (Hertz normal contact, Cattaneo-Mindlin
tangential compliance with full loading history, local Coulomb friction, no normal-tangential
coupling, e = 1) is solved exactly by the MDR reference (mdr.py, N = 600 springs); no
digitised MBF curve was available.

psi1 = eta v_slip,in / (mu |v_n|),  psi2 = eta v_slip,out / (mu |v_n|) (MBF / Thornton sign
convention: psi2 < 0 = the contact point rebounds backwards),  eta = 4 G*/E*
(= 2(1-nu)/(2-nu) for equal materials); chi = (eta/2)(1 + m R^2 / I). Rigid-body Coulomb:
psi2 = 0 (rolling) for psi1 < 4 chi, psi2 = psi1 - 4 chi (sliding) beyond.

Writes results/mbf.json and fig_mbf.png."""

from __future__ import annotations

import json
import os

import impactlab as il
import matplotlib.pyplot as plt
import numpy as np

from cases import Case
from runners import rigid_coulomb, run_exact, run_existing, run_new, run_tcc, run_ty

HERE = os.path.dirname(os.path.abspath(__file__))
os.makedirs(os.path.join(HERE, "results"), exist_ok=True)

STEEL3 = il.Material("steel nu=0.30", E=200e9, nu=0.30, yield_strength=1e9, density=7800.0)
STEEL28 = il.Material("steel nu=0.28", E=200e9, nu=0.28, yield_strength=1e9, density=7800.0)
VN = 1.0
MU = 0.3


def make(kind, mu=MU):
    if kind == "sphere":
        c = Case(STEEL3, STEEL3, 5e-3, law="hertz", mu=mu)
    else:  # thin diametral slice: I = m R^2 / 2 (MBF 1976, Fig. 1)
        c = Case(STEEL28, STEEL28, 5e-3, law="hertz", mu=mu)
        c.I = 0.5 * c.m * c.R**2
    return c


def psi2_of(c, r, vn=VN):
    return c.eta * r["vslip_out"] / (c.mu * vn)


psi_grid = np.unique(np.concatenate([np.linspace(0.05, 1.0, 12), np.linspace(1.0, 8.0, 57),
                                     np.linspace(8.0, 12.0, 9)]))
res = {}
for kind in ("sphere", "slice"):
    c = make(kind)
    models = {"exact": run_exact, "new": run_new, "TY": run_ty, "TCC": run_tcc}
    if kind == "sphere":
        models["existing"] = run_existing
    R = {m: {"psi1": [], "psi2": [], "et": [], "spin": []} for m in list(models) + ["rigid"]}
    for p1 in psi_grid:
        vt = p1 * c.mu * VN / c.eta
        for m, f in models.items():
            r = f(c, vt, -VN)
            R[m]["psi1"].append(float(p1)); R[m]["psi2"].append(float(psi2_of(c, r)))
            R[m]["et"].append(float(r["et"])); R[m]["spin"].append(float(-r["w"] * c.R / (c.mu * VN)))
        r = rigid_coulomb(c, vt, -VN, 1.0)
        R["rigid"]["psi1"].append(float(p1)); R["rigid"]["psi2"].append(float(psi2_of(c, r)))
        R["rigid"]["et"].append(float(r["et"])); R["rigid"]["spin"].append(float(-r["w"] * c.R / (c.mu * VN)))
        print(kind, "%.3f" % p1, " ".join("%s %+.4f" % (m, R[m]["psi2"][-1]) for m in R), flush=True)
    res[kind] = {"chi": c.chi, "eta": c.eta, "curves": R}

# scale invariance: psi2(psi1) must not depend on mu (nor on V, E) -- MBF's single parameter chi
inv = []
for p1 in (0.5, 2.0, 3.5, 5.0):
    vals = []
    for mu in (0.1, 0.3, 0.6):
        c = make("sphere", mu)
        for vn in (0.3, 3.0):
            vt = p1 * mu * vn / c.eta
            r = run_exact(c, vt, -vn)
            vals.append(float(c.eta * r["vslip_out"] / (mu * vn)))
    inv.append((p1, max(vals) - min(vals)))
    print("psi1 %.2f: spread of psi2 over mu in {0.1,0.3,0.6}, V in {0.3,3}: %.2e" % inv[-1])


def summary(kind):
    c = res[kind]["curves"]["exact"]
    p1 = np.array(c["psi1"]); p2 = np.array(c["psi2"])
    chi = res[kind]["chi"]
    slope = p2[0] / p1[0]
    pos = p1[p2 < 0]  # reversed contact-point velocity
    slide = p1[np.abs(p2 - (p1 - 4 * chi)) < 1e-3]
    return {"slope_small_psi": float(slope), "reversal_from": float(pos.min()) if pos.size else None,
            "reversal_to": float(pos.max()) if pos.size else None,
            "psi2_min": float(p2.min()), "psi1_at_min": float(p1[np.argmin(p2)]),
            "gross_slip_throughout_from": float(slide.min()) if slide.size else None,
            "four_chi": 4 * chi}


S = {k: summary(k) for k in res}
for k, v in S.items():
    print(k, v)
# model errors vs exact
err = {}
for kind in res:
    ex = np.array(res[kind]["curves"]["exact"]["psi2"])
    err[kind] = {m: float(np.max(np.abs(np.array(res[kind]["curves"][m]["psi2"]) - ex)))
                 for m in res[kind]["curves"]}
    print(kind, "max |psi2 - exact|:", err[kind])
with open(os.path.join(HERE, "results", "mbf.json"), "w") as fh:
    json.dump({"res": res, "summary": S, "max_err_psi2": err, "scale_invariance": inv}, fh, indent=1)

sty = {"new": dict(color="C3", lw=2.2, label="new: M-D (discrete MDR, N=16)"),
       "exact": dict(color="k", lw=1.0, ls="--", label="exact M-D = MBF theory (MDR, N=600)"),
       "existing": dict(color="C0", lw=1.4, label="existing 'mindlin'"),
       "TY": dict(color="C2", lw=1.0, ls="-.", label="Thornton-Yin"),
       "TCC": dict(color="C4", lw=1.0, ls=":", label="TY + TCC"),
       "rigid": dict(color="0.6", lw=1.0, label="rigid-body Coulomb")}
fig, ax = plt.subplots(1, 3, figsize=(16, 5.2))
for a, kind in zip(ax[:2], ("sphere", "slice")):
    R = res[kind]["curves"]
    for m in ["rigid", "existing", "TY", "TCC", "exact", "new"]:
        if m in R:
            a.plot(R[m]["psi1"], R[m]["psi2"], **sty[m])
    a.axhline(0, color="0.8", lw=0.8)
    a.set_xlabel("psi1 = eta v_slip,in / (mu |v_n|)"); a.set_ylabel("psi2 = eta v_slip,out / (mu |v_n|)")
    a.set_title("%s, chi = %.4f" % ("solid sphere (nu = 0.3)" if kind == "sphere" else
                                    "thin diametral slice (nu = 0.28)", res[kind]["chi"]))
    a.grid(alpha=.3); a.set_xlim(0, 12); a.set_ylim(-2.0, 2.5)
ax[0].legend(fontsize=8, loc="upper left")
a = ax[2]
R = res["sphere"]["curves"]
for m in ["rigid", "existing", "TY", "TCC", "exact", "new"]:
    a.plot(R[m]["psi1"], R[m]["et"], **sty[m])
a2 = a.twinx()
for m in ["rigid", "existing", "exact", "new"]:
    a2.plot(R[m]["psi1"], R[m]["spin"], color=sty[m]["color"], lw=0.9, alpha=0.6, ls=(0, (4, 2)))
a2.set_ylabel("rebound spin  -omega R / (mu |v_n|)  (thin dashed)")
a.set_xlabel("psi1"); a.set_ylabel("tangential restitution e_t (solid lines)")
a.set_title("solid sphere: e_t and rebound spin vs psi1"); a.grid(alpha=.3); a.set_xlim(0, 12)
fig.suptitle("Maw, Barber & Fawcett elastic oblique impact: theory computed independently as the "
             "exact Mindlin-Deresiewicz solution (MDR)", fontsize=11)
fig.tight_layout()
fig.savefig(os.path.join(HERE, "fig_mbf.png"), dpi=120)
print("wrote fig_mbf.png")
