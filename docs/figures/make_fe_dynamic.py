"""Regenerate docs/figures/fe_dynamic_<case>.png and print the tables of docs/fe-dynamic.md
from the shipped impact tables (impactlab.verification.fe_impact; no CalculiX run).

Run from the repository root: .venv/bin/python docs/figures/make_fe_dynamic.py
"""

import textwrap
from pathlib import Path

from impactlab.fe.impact_reference import IMPACT_CASES
from impactlab.verification.fe_impact import (
    compare_impacts,
    comparison_markdown,
    plot_force_histories,
)

here = Path(__file__).parent
for case, spec in IMPACT_CASES.items():
    if spec.dynamic:
        fig = plot_force_histories(case)
        width = 60 * len(spec.speeds)  # the title wrapped to the figure's width
        fig.suptitle(textwrap.fill(spec.description, width), fontsize=9)
        fig.tight_layout()
        path = here / f"fe_dynamic_{case}.png"
        fig.savefig(path, dpi=90)
        print(path)
    print(comparison_markdown(compare_impacts(case)))
