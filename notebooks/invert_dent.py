# ---
# jupyter:
#   jupytext:
#     formats: py:percent
#     text_representation:
#       extension: .py
#       format_name: percent
#   kernelspec:
#     display_name: Python 3
#     language: python
#     name: python3
# ---

# %% [markdown]
# # Invert a dent
#
# The paper's method (Sec. 5.2, Eqs. 12 and 29 of doi:10.1007/s00419-015-1108-2): from the
# measured angle, tip velocity, restitution, friction and the dent's depth and length, the
# impact's duration T and mean normal force F. Uncertainties are propagated to first order and by
# Monte Carlo; the standard uncertainties below are assumed (the paper gives none).

# %%
import json
import math

import matplotlib.pyplot as plt

from impactlab.analytic import critical_friction, invert
from impactlab.paper.data import EXPERIMENTS

x = EXPERIMENTS[20]  # the paper's 20 deg drop
inputs = {
    "angle": (x.angle, math.radians(0.5)),
    "v_i": (x.v_i, 0.02),
    "e": (x.e, 0.02),
    "mu": (x.mu, 0.01),
    "delta_p": (abs(x.delta_p), 1e-6),  # the paper prints depths negative
    "sliding_length": (abs(x.L_s), 50e-6),
}
print(f"mu / mu_c = {x.mu / float(critical_friction(x.angle)):.3f} (gross sliding: < 1)")

# %%
res = invert(**inputs, n_samples=5000, seed=0)
print(f"T = {res.duration * 1e3:.3f} ms, F = {res.mean_force:.1f} N")
res  # noqa: B018 (shown as a table in Jupyter)

# %% [markdown]
# ## All the paper's drops

# %%
rows = {}
for angle_deg, xi in sorted(EXPERIMENTS.items()):
    ri = invert(
        angle=xi.angle,
        v_i=xi.v_i,
        e=xi.e,
        mu=xi.mu,
        delta_p=abs(xi.delta_p),
        sliding_length=abs(xi.L_s),
    )
    rows[angle_deg] = (ri.duration, ri.mean_force)
    print(f"{angle_deg:4.0f} deg: T = {ri.duration * 1e3:.3f} ms, F = {ri.mean_force:6.1f} N")

# %%
fig, ax = plt.subplots(figsize=(5.6, 3.4), constrained_layout=True)
ax.plot(list(rows), [t * 1e3 for t, _ in rows.values()], "o-")
ax.set_xlabel("angle [deg]")
ax.set_ylabel("T [ms]")
fig.savefig("duration.png", dpi=100)
with open("inversion.json", "w") as f:
    json.dump(res.to_dict(), f, indent=2, default=str)
