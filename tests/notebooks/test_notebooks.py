"""The notebook gallery: each notebook of ``notebooks/`` (jupytext percent format,
kept as text) runs as a script in a fresh subprocess, in a temporary folder, with
``MPLBACKEND=Agg``, prints its key numbers and writes its outputs; each has a documentation page
``docs/notebooks/NAME.md`` that shows its current code and the value each cell displays
(``notebook_pages.py`` writes them)."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
if str(HERE) not in sys.path:
    sys.path.insert(0, str(HERE))

from notebook_pages import GALLERY, NOTEBOOKS, OUT, PAGES, cells  # noqa: E402

ROOT = HERE.parents[1]

# notebook -> (regular expressions its output must contain, files it must write)
CASES: dict[str, tuple[tuple[str, ...], tuple[str, ...]]] = {
    "simulate_impact": (
        (
            r"<contact law 'ghaednia': .*doi:10\.1016/j\.triboint\.2015\.09\.005",
            r"e = 0\.42\d\d, delta_p = 6\d\.\d\d um",
            r"13 cases; regimes: frictionless slip stick reversal",
        ),
        ("force_time.png", "force_penetration.png", "batch.nc"),
    ),
    "invert_dent": (
        (r"T = 4\.106 ms, F = 69\.\d N", r"45 deg: T = 1\.382 ms"),
        ("duration.png", "inversion.json"),
    ),
    "analyze_experiment": (
        (r"T = 4\.\d\d\d ms ± 0\.\d+, F = \d\d\.\d\d N", r"results: .*results\.json"),
        ("drop.c3d", "dent.x3p", "results/results.json"),
    ),
    "sweep_study": (
        (
            r"Study\('regime-map', grid, 867 cases in \d+ chunks; angle\[17\] 5 \.\. 85 deg",
            r"resume: \d+ chunks stored, 0 computed",
            r"'friction regime( \(\d+ flagged cases blank, marked x\))?: vy = -1\.41 m/s'",
            r"e at 20 deg, mu = 0\.2, vy = -1\.41 m/s: 0\.42\d\d",
        ),
        ("regime-map-notebook.zarr", "regime_map.png", "e_angle_mu.png"),
    ),
}

# notebook -> how each value its cells display starts on its page, in order (after OUT)
SHOWN: dict[str, tuple[str, ...]] = {
    "simulate_impact": (
        "```text\nRod(",
        "```text\nget_material('aisi-1010')",
        "```text\n<contact law 'ghaednia'",
        "```text\nImpactResult(",
        "|  | t | penetration | normal\\_force |",  # df.head() as a Markdown table
        "```text\nBatchResult(",
    ),
    "invert_dent": ("```text\nInversionResult(",),
    "analyze_experiment": ("```text\nExperimentResult(",),
    "sweep_study": ("```text\nStudy('regime-map', grid, 867 cases", "```text\nSweepResult("),
}


def test_the_gallery_is_complete() -> None:
    assert set(CASES) == set(GALLERY) == set(SHOWN)
    assert {p.stem for p in NOTEBOOKS.glob("*.py")} == set(GALLERY)


@pytest.mark.parametrize("name", sorted(CASES))
def test_notebook_runs(name: str, tmp_path: Path) -> None:
    patterns, files = CASES[name]
    env = dict(os.environ, MPLBACKEND="Agg")
    res = subprocess.run(
        [sys.executable, str(NOTEBOOKS / f"{name}.py")],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
        check=False,
    )
    assert res.returncode == 0, res.stdout + res.stderr
    for pattern in patterns:
        assert re.search(pattern, res.stdout), f"{pattern!r} not in:\n{res.stdout}"
    for f in files:
        assert (tmp_path / f).exists(), f"{name} did not write {f}"


@pytest.mark.parametrize("name", sorted(GALLERY))
def test_notebook_format_and_page(name: str) -> None:
    text = (NOTEBOOKS / f"{name}.py").read_text()
    assert text.startswith("# ---\n# jupyter:\n#   jupytext:\n#     formats: py:percent\n")
    nb = cells(text)
    assert nb[0].kind == "markdown" and nb[0].source.startswith(f"# {GALLERY[name]}\n")
    assert sum(c.kind == "code" for c in nb) >= 2
    page = (PAGES / f"{name}.md").read_text()
    assert page.startswith(f"# {GALLERY[name]}\n")
    stale = [c.source for c in nb if c.kind == "code" and f"```python\n{c.source}\n```" not in page]
    assert not stale, (
        f"docs/notebooks/{name}.md does not show the notebook's current code: run "
        "tests/notebooks/notebook_pages.py"
    )
    for img in re.findall(r"\]\((img/[\w.-]+\.png)\)", page):
        assert (PAGES / img).is_file(), img


@pytest.mark.parametrize("name", sorted(GALLERY))
def test_each_page_shows_the_values_its_cells_display(name: str) -> None:
    page = (PAGES / f"{name}.md").read_text()
    blocks = page.split(f"\n\n{OUT}\n\n")[1:]
    assert len(blocks) == len(SHOWN[name]), (
        f"docs/notebooks/{name}.md shows {len(blocks)} displayed values, the notebook "
        f"displays {len(SHOWN[name])}: run tests/notebooks/notebook_pages.py"
    )
    for block, start in zip(blocks, SHOWN[name], strict=True):
        assert block.startswith(start), f"{start!r} is not the start of {block[:200]!r}"
    assert not re.search(r"\b0x[0-9a-fA-F]{6,}\b", page), "a memory address on the page"


def test_the_inversion_page_shows_its_uncertainties() -> None:
    """The gallery promises the inversion "with uncertainties": the displayed result has them."""
    page = (PAGES / "invert_dent.md").read_text()
    shown = page.split(f"\n\n{OUT}\n\n")[1].split("\n```")[0]
    assert re.search(r"±|sigma", shown), shown
