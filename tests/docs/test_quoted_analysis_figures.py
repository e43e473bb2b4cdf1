"""The figures that the documentation quotes from the worked analysis
(``examples/analyze_experiment.py``: a synthetic 20 deg drop, its marker file and dent scan)
are the ones the example prints now: the summary table of docs/tutorials/analyze.md,
docs/experiment.md and the notebook page, the notebook page's ``T = ..., F = ...`` line and
result repr, and experiment.md's rounded T and F and their distance from the inversion of the
true inputs. The example runs once, so that a change to the marker fits, the scan analysis or
the inversion cannot leave a page's numbers stale."""

from __future__ import annotations

import json
import math
import os
import re
import subprocess
import sys
from pathlib import Path
from typing import Any

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXAMPLE = ROOT / "examples" / "analyze_experiment.py"
#: the pages that quote the example's summary table
PAGES = ("docs/tutorials/analyze.md", "docs/experiment.md", "docs/notebooks/analyze_experiment.md")
#: the figures each of these pages must quote (so that a page that stops matching the pattern
#: below fails instead of passing with nothing checked)
QUOTED = ("e", "mu", "delta_p", "sliding_length", "duration", "mean_force")

# one estimate as ``str(Estimate)`` prints it: value, optional "± sigma", optional unit
_ESTIMATE = r"(-?\d[\d.e+-]*(?: ± \d[\d.e+-]*)?(?: [a-zA-Z/]+\b)?)"
_TF = re.compile(r"T = (\d[\d.]*) ms ± (\d[\d.]*), F = (\d[\d.]*) N ± (\d[\d.]*)")

pytest.importorskip("SurfaceTopography", reason="the example reads an X3P scan")


@pytest.fixture(scope="module")
def example(tmp_path_factory: pytest.TempPathFactory) -> tuple[str, dict[str, Any]]:
    """The example's printed output and its ``results.json``, from one run."""
    out = tmp_path_factory.mktemp("analyze-example")
    env = dict(os.environ, MPLBACKEND="Agg")
    env.pop("IMPACTLAB_EXAMPLE_OUT", None)
    proc = subprocess.run(
        [sys.executable, str(EXAMPLE), str(out)],
        cwd=out,
        env=env,
        capture_output=True,
        text=True,
        timeout=900,
    )
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-3000:]
    results = json.loads((out / "results" / "results.json").read_text())
    return proc.stdout, results


def _table(text: str, names: list[str]) -> dict[str, str]:
    """name -> the estimate quoted on a line that starts with the name (a summary table)."""
    found: dict[str, str] = {}
    for name in names:
        m = re.search(rf"^{re.escape(name)}\s+{_ESTIMATE}", text, flags=re.MULTILINE)
        if m is not None:
            found[name] = m.group(1)
    return found


def _code(page: str) -> str:
    """The text of a page's fenced code blocks (where the example's output is quoted)."""
    text = (ROOT / page).read_text(encoding="utf-8")
    return "\n".join(re.findall(r"^```[a-z]*\n(.*?)^```", text, flags=re.MULTILINE | re.DOTALL))


@pytest.mark.parametrize("page", PAGES)
def test_summary_tables_quote_the_examples_output(
    page: str, example: tuple[str, dict[str, Any]]
) -> None:
    printed, results = example
    names = list(results["summary"])
    now = _table(printed, names)
    assert set(now) == set(names), (sorted(set(names) - set(now)), printed)
    quoted = _table(_code(page), names)
    lost = sorted(set(QUOTED) - set(quoted))
    assert not lost, f"{page} no longer quotes {lost}"
    stale = {name: (text, now[name]) for name, text in quoted.items() if text != now[name]}
    assert not stale, f"{page}: quoted -> printed now: {stale}"


def test_notebook_page_quotes_the_examples_t_and_f(example: tuple[str, dict[str, Any]]) -> None:
    printed, results = example
    now = _TF.search(printed)
    assert now is not None, printed
    page = (ROOT / "docs/notebooks/analyze_experiment.md").read_text(encoding="utf-8")
    quoted = _TF.findall(page)
    assert quoted and all(q == now.groups() for q in quoted), (quoted, now.groups())
    # the result's repr: each value with 6 significant digits
    shown = re.search(r"^ExperimentResult\(.*$", page, flags=re.MULTILINE)
    assert shown is not None, "the page no longer shows the result's repr"
    for name in ("sliding_length", "duration", "mean_force"):
        m = re.search(rf"\b{name}=(-?\d[\d.e+-]*)", shown.group(0))
        assert m is not None, name
        assert m.group(1) == f"{results['summary'][name]['value']:.6g}", name


@pytest.mark.filterwarnings("ignore::impactlab.ImplausibleInputWarning")  # mu against mu_c
def test_experiment_page_rounds_and_compares_as_printed(
    example: tuple[str, dict[str, Any]],
) -> None:
    """experiment.md: "T = 4.15 ms and F = 69 N", the true inputs' T and F and the distance
    of the measured ones from them in sigma."""
    from impactlab.analytic import invert

    summary = example[1]["summary"]
    T, F = summary["duration"], summary["mean_force"]
    true = invert(
        angle=math.radians(20.0),
        v_i=-1.41,
        e=0.5,
        mu=0.2,
        delta_p=22e-6,
        sliding_length=1400e-6,
    )
    text = " ".join((ROOT / "docs/experiment.md").read_text(encoding="utf-8").split())
    sigma = "\N{GREEK SMALL LETTER SIGMA}"
    claim = (
        f"T = {T['value'] * 1e3:.2f} ms and F = {F['value']:.0f} N are of the order of the "
        f"paper's Table 2 (4.30 ms, 79 N) for its 20° drop; with the true inputs the inversion "
        f"gives T = {true.duration * 1e3:.2f} ms and F = {true.mean_force:.1f} N (the measured "
        f"values differ by {abs(T['value'] - true.duration) / T['sigma']:.1f}{sigma} and "
        f"{abs(F['value'] - true.mean_force) / F['sigma']:.1f}{sigma}"
    )
    assert claim in text, claim
