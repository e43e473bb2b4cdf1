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
# # Analyze an experiment
#
# Raw files to measured impact quantities: a motion-capture recording of the markers on the rod
# (C3D) and a profilometer scan of the dent (X3P). Here both are synthetic, made by
# `impactlab.testing` from a known impact, so the analysis can be compared with the truth.

# %%
import math
from pathlib import Path

from impactlab import testing as S
from impactlab.bodies import PAPER_ROD
from impactlab.experiment import MarkerGeometry, analyze

truth = S.rigid_impulse_impact(PAPER_ROD, math.radians(20.0), (0.0, -1.41), e=0.5, mu=0.2)
tracks, info = S.marker_tracks(PAPER_ROD, truth, noise=0.15e-3, seed=2)
c3d = S.write_c3d(tracks, Path("drop.c3d"))  # millimetres, 500 fps, with occlusions
z, dx, dy, scan_truth = S.synthetic_scan(delta_p=22e-6, sliding_length=1400e-6, seed=1)
scan = S.write_scan(z, dx, dy, Path("dent.x3p"))  # ISO 5436-2 X3P
print(f"{tracks.n_frames} frames at {tracks.rate:g} Hz; scan {z.shape[1]} x {z.shape[0]} px")

# %% [markdown]
# ## The analysis
#
# `analyze` fits the rigid-body motion before and after the impact, measures the dent, and
# inverts it (the paper's method) to the impact's duration and mean force, with uncertainties.

# %%
geometry = MarkerGeometry(S.DEFAULT_MARKERS, info["labels"])
res = analyze(c3d, scan, PAPER_ROD, geometry=geometry, out_dir=Path("results"))
assert not res.errors, res.errors
summary = res.summary()
true = {"e": truth.e, "mu": truth.mu, "delta_p": scan_truth.groove.depth}
for name, est in summary.items():
    t = f"truth {true[name]:.5g}" if name in true else ""
    print(f"{name:14s} {est!s:>28s}  {t}".rstrip())
res  # noqa: B018 (shown as a table in Jupyter)

# %%
T, F = summary["duration"], summary["mean_force"]
print(f"T = {T.value * 1e3:.3f} ms ± {T.sigma * 1e3:.3f}, F = {F.value:.2f} N ± {F.sigma:.2f}")
print("results:", ", ".join(sorted(p.name for p in Path("results").iterdir())))
