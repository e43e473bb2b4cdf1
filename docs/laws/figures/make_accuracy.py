"""Regenerate docs/laws/figures/accuracy_errors.png and accuracy_curves.png: every contact law
against the shipped FE reference curves (impactlab.fe.accuracy), and print the page's tables.

Run from the repository root: .venv/bin/python docs/laws/figures/make_accuracy.py
"""

from pathlib import Path

from impactlab.fe.accuracy import accuracy
from impactlab.fe.accuracy_views import markdown, plot_curves, plot_errors

results = accuracy()
here = Path(__file__).parent
for name, fig in (
    ("accuracy_errors.png", plot_errors(results)),
    ("accuracy_curves.png", plot_curves(results)),
):
    fig.savefig(here / name, dpi=90)
    print(here / name)
print(markdown(results))
