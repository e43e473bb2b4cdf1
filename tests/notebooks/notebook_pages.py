"""The notebook gallery: read the jupytext percent-format notebooks of ``notebooks/`` and write
their documentation pages ``docs/notebooks/NAME.md`` (text and code of each cell, the output the
cell printed when it ran, and the figures it saved).

Regenerate the pages after changing a notebook (it runs each notebook, cell by cell, in a
temporary folder)::

    MPLBACKEND=Agg .venv/bin/python tests/notebooks/notebook_pages.py

``tests/notebooks/test_notebooks.py`` runs every notebook as a script and checks that each page
still shows its notebook's code.
"""

from __future__ import annotations

import contextlib
import io
import os
import re
import shutil
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOKS = ROOT / "notebooks"
PAGES = ROOT / "docs" / "notebooks"
#: the notebooks of the gallery, in order, with their page titles
GALLERY = {
    "simulate_impact": "Simulate an impact",
    "invert_dent": "Invert a dent",
    "analyze_experiment": "Analyze an experiment",
    "sweep_study": "Sweep a study",
}

_CELL = re.compile(r"^# %%(?P<kind> \[markdown\])?.*$", flags=re.MULTILINE)
_IMAGE = re.compile(r"savefig\(\s*\"([\w.-]+\.png)\"")


@dataclass(frozen=True)
class Cell:
    """One cell: ``kind`` "markdown" or "code", and its source (markdown without ``# ``)."""

    kind: str
    source: str


def cells(text: str) -> list[Cell]:
    """The cells of a percent-format notebook (the jupytext header is not a cell)."""
    marks = list(_CELL.finditer(text))
    out = []
    for i, m in enumerate(marks):
        end = marks[i + 1].start() if i + 1 < len(marks) else len(text)
        body = text[m.end() : end].strip("\n")
        if m.group("kind"):
            lines = [ln[2:] if ln.startswith("# ") else ln.lstrip("#") for ln in body.splitlines()]
            out.append(Cell("markdown", "\n".join(lines).strip()))
        else:
            out.append(Cell("code", body.rstrip()))
    return out


def run_cells(path: Path, workdir: Path) -> list[str]:
    """Run the code cells of ``path`` in ``workdir`` in one namespace; what each printed."""
    namespace: dict[str, object] = {"__name__": "__main__", "__file__": str(path)}
    printed = []
    here = Path.cwd()
    os.chdir(workdir)
    try:
        for cell in cells(path.read_text()):
            buf = io.StringIO()
            if cell.kind == "code":
                with contextlib.redirect_stdout(buf):
                    exec(compile(cell.source, str(path), "exec"), namespace)
            printed.append(buf.getvalue())
    finally:
        os.chdir(here)
    return printed


def render(name: str, printed: list[str]) -> str:
    """The documentation page of notebook ``name`` (its cells and what each printed)."""
    source = f"notebooks/{name}.py"
    note = [
        f"<!-- generated from {source} by tests/notebooks/notebook_pages.py: do not edit -->",
        f"_This page is the notebook `{source}` of the repository, with the output it printed "
        "when it ran. The notebook is a Python script in jupytext's percent format: run it with "
        "`python`, or open it in Jupyter with jupytext (`jupytext --to ipynb`)._",
    ]
    parts: list[str] = []
    for cell, out in zip(cells((NOTEBOOKS / f"{name}.py").read_text()), printed, strict=True):
        if cell.kind == "markdown":
            parts.append(cell.source)
            parts.extend(note)  # after the title (the first cell), once
            note = []
            continue
        parts.append(f"```python\n{cell.source}\n```")
        if out.strip():
            parts.append(f"```text\n{out.rstrip()}\n```")
        parts.extend(f"![{img}](img/{name}-{img})" for img in _IMAGE.findall(cell.source))
    return "\n\n".join(parts) + "\n"


def main() -> None:
    (PAGES / "img").mkdir(parents=True, exist_ok=True)
    for name in GALLERY:
        with tempfile.TemporaryDirectory() as tmp:
            printed = run_cells(NOTEBOOKS / f"{name}.py", Path(tmp))
            for img in Path(tmp).glob("*.png"):
                shutil.copy2(img, PAGES / "img" / f"{name}-{img.name}")
        (PAGES / f"{name}.md").write_text(render(name, printed))
        print(f"wrote docs/notebooks/{name}.md", file=sys.stderr)


if __name__ == "__main__":
    main()
