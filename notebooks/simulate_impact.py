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
# # Simulate an impact
#
# The paper's rod (Table 1 of doi:10.1007/s00419-015-1108-2) dropped at 20 deg and 1.41 m/s on
# an AISI 1010 flat, with the Ghaednia contact law and exact Coulomb friction (mu = 0.2). In
# Jupyter, the bodies, materials, laws and results below show themselves as tables.

# %%
import math

import matplotlib.pyplot as plt
import numpy as np

import impactlab as il
from impactlab.contact import get_law
from impactlab.dynamics.plotting import plot_force_penetration

rod = il.Rod.paper()
rod  # noqa: B018 (a notebook cell's result: shown as a table in Jupyter)

# %%
il.AISI_1010  # noqa: B018

# %%
law = get_law("ghaednia")
print(repr(law))
law  # noqa: B018

# %% [markdown]
# ## One impact
#
# Inputs are SI (angles in radians); strings with units such as `"20 deg"` work too.

# %%
r = il.simulate(
    rod,
    il.AISI_1010,
    law="ghaednia",
    friction="coulomb",
    mu=0.2,
    angle="20 deg",
    velocity=(0.0, -1.41),
)
print(f"e = {r.e:.4f}, delta_p = {r.delta_p * 1e6:.2f} um, T = {r.duration * 1e3:.4f} ms")
r  # noqa: B018

# %% [markdown]
# The history has its units in `df.attrs["units"]`, and `phase` (loading / unloading) and
# `stick` (slip / stick) are categorical columns.

# %%
h = r.history
df = h.to_dataframe()
print(df.attrs["units"]["normal_force"], df["phase"].value_counts().to_dict())
df.head()

# %%
fig, ax = plt.subplots(figsize=(6.4, 3.6), constrained_layout=True)
for phase, part in df.groupby("phase", observed=True):
    ax.plot(part["t"] * 1e3, part["normal_force"], ".", ms=3, label=f"{phase}")
ax.set_xlabel("time [ms]")
ax.set_ylabel("normal force [N]")
ax.legend()
fig.savefig("force_time.png", dpi=100)

# %% [markdown]
# The figures of one impact come ready-made from `impactlab.dynamics.plotting`:
# `plot_force_time`, `plot_force_penetration`, `plot_contact_path` and `plot_dent` (each takes
# `ax=` to draw into your own axes; `save_figures(r, folder)` writes all four). Each returns
# its Figure, which the notebook shows once.

# %%
fig = plot_force_penetration(r)
fig.savefig("force_penetration.png", dpi=100)
fig  # noqa: B018 (the cell's value: the notebook shows the figure)

# %% [markdown]
# ## Many impacts at once
#
# `simulate_batch` runs arrays of inputs through the compiled engine; `to_xarray()` gives a
# Dataset with a `case` dimension, units in the attributes and the regime as coded integers.

# %%
b = il.simulate_batch(
    rod,
    law="ghaednia",
    friction="coulomb",
    mu=np.linspace(0.0, 0.6, 13),
    angle=math.radians(20),
    vy=-1.41,
)
ds = b.to_xarray()
print(f"{len(b)} cases; regimes: {ds['regime'].attrs['flag_meanings']}")
ds.to_netcdf("batch.nc")
b  # noqa: B018
