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
# # Sweep a study
#
# A grid over the impact angle, the friction coefficient and the drop velocity, computed chunk
# by chunk into a resumable Zarr store. The study and the result show a summary of each
# dimension (name, size, range, unit); the maps of a 3-D study are drawn as facets, one panel
# per velocity, each titled with the slice it shows.

# %%
import matplotlib.pyplot as plt
import numpy as np

from impactlab.sweep import Study, plot_output_map, plot_regime_map, run_sweep

study = Study(
    name="regime-map",
    grid={
        "angle": np.radians(np.linspace(5.0, 85.0, 17)),  # SI in Python: radians
        "mu": np.linspace(0.0, 0.8, 17),
        "vy": [-1.0, -1.41, -2.0],
    },
    fixed={"law": "ghaednia", "friction": "coulomb"},
    outputs=["e", "delta_p", "duration", "regime"],
    chunk_size=289,
)
print(repr(study))
study  # noqa: B018 (shown as a table in Jupyter)

# %%
result = run_sweep(study, "regime-map-notebook.zarr", quiet=True)
ds = result.dataset
print(f"{result.stats.cases_computed} cases in {result.stats.chunks_computed} chunks")
result  # noqa: B018

# %% [markdown]
# Running the same study again finds every chunk stored and computes nothing.

# %%
again = run_sweep(study, "regime-map-notebook.zarr", quiet=True)
print(f"resume: {again.stats.chunks_before} chunks stored, {again.stats.chunks_computed} computed")

# %%
axes = plot_regime_map(ds)  # one panel per vy, with the rigid-body mu_c(theta)
fig = np.ravel(axes)[0].figure
fig.savefig("regime_map.png", dpi=90)
print([a.get_title().replace("\n", ": ") for a in np.ravel(axes) if a.get_visible()])

# %%
fig, ax = plt.subplots(figsize=(6.0, 4.0), constrained_layout=True)
plot_output_map(ds, "e", x="angle", y="mu", sel={"vy": -1.41}, ax=ax)
fig.savefig("e_angle_mu.png", dpi=90)
e20 = float(ds["e"].sel(angle=np.radians(20.0), mu=0.2, vy=-1.41, method="nearest"))
print(f"e at 20 deg, mu = 0.2, vy = -1.41 m/s: {e20:.4f}")
