"""Regenerate docs/laws/figures/all_laws.png (the paper's pair, R = 8.8 mm, up to 200 um).

Run from the repository root: .venv/bin/python docs/laws/figures/make_all_laws.py
"""

from pathlib import Path

from impactlab.contact.plotting import plot_laws
from impactlab.materials import AISI_201, AISI_1010, ContactPair

fig = plot_laws(ContactPair(AISI_201, AISI_1010), radius=8.8e-3, delta_max=200e-6)
out = Path(__file__).with_name("all_laws.png")
fig.savefig(out, dpi=130)
print(out)
