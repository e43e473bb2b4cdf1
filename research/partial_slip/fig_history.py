"""Force histories of a 4 deg Kharaz impact: F_t/(mu F_n), slip velocity and the slipping
fraction of the contact for the exact M-D reference, the new model, Thornton-Yin and the
existing 'mindlin' model. Writes fig_history.png."""

from __future__ import annotations

import os

import impactlab as il
import matplotlib.pyplot as plt
import numpy as np

from cases import kharaz_case, velocities
from compact import IT, Compact
from model import MDModel
from run_mdr import mdr_impact

HERE = os.path.dirname(os.path.abspath(__file__))
c = kharaz_case()
fig, ax = plt.subplots(1, 3, figsize=(16, 4.6))
for th, ls in ((4.0, "-"), (20.0, "--")):
    vt, vn = velocities(3.9, th)
    x = mdr_impact(c, vt, vn, nspr=600, nsteps=20000, nhist=400)
    H = x["hist"]
    ok = H[:, 2] > 0
    ax[0].plot(H[ok, 0] * 1e6, H[ok, 3] / (c.mu * H[ok, 2]), "k", ls=ls, lw=1, label="exact M-D, %g deg" % th)
    ax[1].plot(H[:, 0] * 1e6, H[:, 4], "k", ls=ls, lw=1)
    ax[2].plot(H[ok, 0] * 1e6, H[ok, 6], "k", ls=ls, lw=1, label="exact M-D (slipping length / a), %g deg" % th)
    r = MDModel(c, 16).run(vt, vn, history=True)
    h = r["hist"]
    ok = h["F"] > 0
    ax[0].plot(h["t"][ok] * 1e6, h["T"][ok] / (c.mu * h["F"][ok]), color="C3", ls=ls, lw=2, alpha=.7,
               label="new (N=16), %g deg" % th)
    ax[1].plot(h["t"] * 1e6, h["vs"], color="C3", ls=ls, lw=2, alpha=.7)
    ax[2].plot(h["t"][ok] * 1e6, h["nslip"][ok] / np.maximum(h["nin"][ok], 1), color="C3", ls=ls,
               lw=2, alpha=.7, label="new: slipping cells / cells in contact, %g deg" % th)
    q = Compact(c, "TY").run(vt, vn, history=True)
    Y = q["y"]
    nl = Compact(c, "TY")
    d = -Y[0]
    F = np.array([4 / 3 * c.Es * np.sqrt(c.R) * max(di, 0) ** 1.5 for di in d])
    okq = F > 0
    ax[0].plot(q["t"][okq] * 1e6, Y[IT][okq] / (c.mu * F[okq]), color="C2", ls=ls, lw=1, label="Thornton-Yin, %g deg" % th)
    ax[1].plot(q["t"] * 1e6, Y[1] + Y[3] * c.R, color="C2", ls=ls, lw=1)
    e = il.simulate(c.body, c.flat, law="hertz", friction="mindlin", mu=c.mu, velocity=(vt, vn),
                    gravity=False, history=True).history
    oke = e.normal_force > 0
    ax[0].plot(e.t[oke] * 1e6, e.tangential_force[oke] / (c.mu * e.normal_force[oke]), color="C0",
               ls=ls, lw=1, label="existing 'mindlin', %g deg" % th)
    ax[1].plot(e.t * 1e6, e.slip_velocity, color="C0", ls=ls, lw=1)
ax[0].set_ylabel("F_t / (mu F_n)"); ax[1].set_ylabel("slip velocity of the contact point [m/s]")
ax[2].set_ylabel("slipping fraction")
for a in ax:
    a.set_xlabel("t [us]"); a.grid(alpha=.3)
ax[0].legend(fontsize=7); ax[2].legend(fontsize=7)
ax[0].set_ylim(-1.05, 1.05)
fig.suptitle("Kharaz case: histories at 4 deg (solid) and 20 deg (dashed)")
fig.tight_layout()
fig.savefig(os.path.join(HERE, "fig_history.png"), dpi=110)
print("wrote fig_history.png")
