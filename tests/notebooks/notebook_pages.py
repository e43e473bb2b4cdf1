"""The notebook gallery: read the jupytext percent-format notebooks of ``notebooks/`` and write
their documentation pages ``docs/notebooks/NAME.md``: the text and code of each cell, what the
cell printed, the value it displayed (its last expression, as Jupyter shows it: the text repr,
a DataFrame as a Markdown table, a figure as the image the cell saved) and the figures it saved.

Regenerate the pages after changing a notebook, or a repr that a notebook displays::

    MPLBACKEND=Agg .venv/bin/python tests/notebooks/notebook_pages.py

Each notebook runs twice, each time in a fresh process and a temporary folder, cell by cell.
The pages stay the same from run to run: numbers that differ between the two runs (timings,
process ids) are shown as ``…``, and a value that shows a memory address, or output that
differs otherwise, stops the build. ``tests/notebooks/test_notebooks.py`` runs every notebook
as a script and checks that each page still shows its notebook's code and displayed values.
"""

from __future__ import annotations

import ast
import contextlib
import html
import io
import json
import os
import pprint
import re
import shutil
import subprocess
import sys
import tempfile
import tokenize
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

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
#: the line above a cell's displayed value on a page (Jupyter's ``Out[n]:``)
OUT = "**Out:**"
#: how many rows and columns of a DataFrame Jupyter shows (pandas' notebook defaults)
MAX_ROWS, MIN_ROWS, MAX_COLUMNS = 60, 10, 20

_CELL = re.compile(r"^# %%(?P<kind> \[markdown\])?.*$", flags=re.MULTILINE)
_IMAGE = re.compile(r"savefig\(\s*\"([\w.-]+\.png)\"")
_ADDRESS = re.compile(r"\b0x[0-9a-fA-F]{6,}\b")
_NUMBER = re.compile(r"(\d+(?:\.\d*)?(?:[eE][+-]?\d+)?)")
_MD_SPECIAL = re.compile(r"([\\`*_\[\]|$])")


@dataclass(frozen=True)
class Cell:
    """One cell: ``kind`` "markdown" or "code", and its source (markdown without ``# ``)."""

    kind: str
    source: str


@dataclass(frozen=True)
class Output:
    """What a cell showed: the text it ``printed`` and the Markdown of the value it displayed
    (``shown``; empty when it displayed nothing)."""

    printed: str = ""
    shown: str = ""


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


def _silenced(source: str) -> bool:
    """Whether the cell's last statement ends with ``;`` (Jupyter then displays nothing)."""
    skip = {tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.ENDMARKER}
    skip |= {tokenize.INDENT, tokenize.DEDENT}
    toks = [t for t in tokenize.generate_tokens(io.StringIO(source).readline) if t.type not in skip]
    return bool(toks) and toks[-1].string == ";"


def _cell_text(text: str) -> str:
    """A table cell's text, escaped for Markdown (no HTML, no emphasis, no math, no ``|``)."""
    return _MD_SPECIAL.sub(r"\\\1", html.escape(text, quote=False))


def _table_row(cells: list[str]) -> str:
    return "| " + " | ".join(_cell_text(c) for c in cells) + " |"


def markdown_table(df: Any) -> str:
    """A pandas DataFrame as a Markdown table, as Jupyter shows it: pandas' number format per
    column, numbers right-aligned, the middle rows and columns of a large frame left out."""
    n_rows, n_cols = df.shape
    rows = list(range(n_rows))
    if n_rows > MAX_ROWS:
        rows = [*range(MIN_ROWS // 2), -1, *range(n_rows - MIN_ROWS // 2, n_rows)]
    cols = list(range(n_cols))
    if n_cols > MAX_COLUMNS:
        cols = [*range(MAX_COLUMNS // 2), -1, *range(n_cols - MAX_COLUMNS // 2, n_cols)]
    sub = df.iloc[[r for r in rows if r >= 0], [c for c in cols if c >= 0]]
    index = [str(i) for i in sub.index]
    columns: list[tuple[str, bool, list[str]]] = []
    for j, name in enumerate(sub.columns):
        col = sub.iloc[:, j]
        lines = col.to_string(index=False, header=False).splitlines()[: len(sub)]
        columns.append((str(name), col.dtype.kind in "iufc", [s.strip() for s in lines]))
    if -1 in cols:
        columns.insert(MAX_COLUMNS // 2, ("…", False, ["…"] * len(sub)))
    if -1 in rows:
        half = MIN_ROWS // 2
        index.insert(half, "…")
        columns = [(h, num, [*v[:half], "…", *v[half:]]) for h, num, v in columns]
    header = [df.index.name or "", *(h for h, _, _ in columns)]
    rule = ["---", *("---:" if num else "---" for _, num, _ in columns)]
    body = [[i, *(v[k] for _, _, v in columns)] for k, i in enumerate(index)]
    lines = [_table_row(header), "| " + " | ".join(rule) + " |", *map(_table_row, body)]
    if len(rows) < n_rows or len(cols) < n_cols:
        lines += ["", f"{n_rows} rows x {n_cols} columns"]
    return "\n".join(lines)


def show(value: Any, source: str, where: str) -> str:
    """The Markdown of the value a cell displays (``source``: the cell's code, ``where``: the
    cell, for errors): nothing for None, a DataFrame as a table, a saved figure by its image
    (under the cell already), anything else as its text repr."""
    if value is None:
        return ""
    pandas = sys.modules.get("pandas")
    if pandas is not None and isinstance(value, pandas.DataFrame):
        return markdown_table(value)
    if hasattr(value, "savefig") and hasattr(value, "axes"):
        if not _IMAGE.findall(source):
            raise ValueError(f"{where} displays a figure: save it (savefig) so the page shows it")
        return ""
    builtin = type(value) in (dict, list, tuple, set, frozenset)  # laid out as IPython does
    text = pprint.pformat(value, width=79, sort_dicts=False) if builtin else repr(value)
    if m := _ADDRESS.search(text):
        raise ValueError(
            f"{where} displays a value whose repr holds a memory address ({m.group()}), which "
            f"would change the page at every run: {text[:200]!r}; give it a repr or end the cell "
            "with another expression"
        )
    return f"```text\n{text}\n```"


def run_cells(path: Path, workdir: Path) -> list[Output]:
    """Run the cells of ``path`` in ``workdir`` in one namespace, as Jupyter does: what each
    printed and what it displayed (the value of its last statement if that is an expression
    not ended by ``;``). Markdown cells give an empty Output."""
    namespace: dict[str, object] = {"__name__": "__main__", "__file__": str(path)}
    outputs = []
    here = Path.cwd()
    os.chdir(workdir)
    try:
        for i, cell in enumerate(cells(path.read_text())):
            if cell.kind != "code":
                outputs.append(Output())
                continue
            tree = ast.parse(cell.source)
            last = tree.body[-1] if tree.body and isinstance(tree.body[-1], ast.Expr) else None
            shown = last is not None and not _silenced(cell.source)
            body = tree.body[:-1] if shown else tree.body
            buf, value = io.StringIO(), None
            with contextlib.redirect_stdout(buf):
                exec(compile(ast.Module(body, []), str(path), "exec"), namespace)
                if shown and last is not None:
                    expr = ast.Expression(last.value)
                    value = eval(compile(expr, str(path), "eval"), namespace)
            where = f"{path.name}, cell {i + 1}"
            outputs.append(Output(buf.getvalue(), show(value, cell.source, where)))
    finally:
        os.chdir(here)
    return outputs


def steady(first: str, second: str, where: str) -> str:
    """The text of two runs with the numbers that differ between them (timings, process ids)
    as ``…``; ValueError if they differ otherwise."""
    if first == second:
        return first
    a, b = _NUMBER.split(first), _NUMBER.split(second)
    if len(a) != len(b) or a[::2] != b[::2]:
        pairs = zip(first.splitlines(), second.splitlines(), strict=False)
        diff = next(((x, y) for x, y in pairs if x != y), (first, second))
        raise ValueError(f"{where} differs from one run to the next: {diff[0]!r} vs {diff[1]!r}")
    print(f"{where}: numbers that differ between runs are shown as …", file=sys.stderr)
    kept = (x if k % 2 == 0 or x == y else "…" for k, (x, y) in enumerate(zip(a, b, strict=True)))
    return "".join(kept)


def render(name: str, text: str, outputs: list[Output]) -> str:
    """The documentation page of notebook ``name`` (source ``text``): its cells, what each
    printed and the value each displayed."""
    source = f"notebooks/{name}.py"
    note = [
        f"<!-- generated from {source} by tests/notebooks/notebook_pages.py: do not edit -->",
        f"_This page is the notebook `{source}` of the repository, run: under each cell what "
        f"it printed and, after {OUT}, the value it displayed, as text (Jupyter shows "
        "impactlab's objects as tables). The notebook is a Python script in jupytext's percent "
        "format: run it with `python`, or open it in Jupyter with jupytext "
        "(`jupytext --to ipynb`)._",
    ]
    parts: list[str] = []
    for cell, out in zip(cells(text), outputs, strict=True):
        if cell.kind == "markdown":
            parts.append(cell.source)
            parts.extend(note)  # after the title (the first cell), once
            note = []
            continue
        parts.append(f"```python\n{cell.source}\n```")
        if out.printed.strip():
            parts.append(f"```text\n{out.printed.rstrip()}\n```")
        if out.shown:
            parts.extend((OUT, out.shown))
        parts.extend(f"![{img}](img/{name}-{img})" for img in _IMAGE.findall(cell.source))
    return "\n\n".join(parts) + "\n"


def _run_apart(name: str, workdir: Path) -> list[Output]:
    """Run notebook ``name`` in a fresh process in ``workdir`` (``run_cells``)."""
    out = workdir / ".outputs.json"
    env = dict(os.environ)
    env.setdefault("MPLBACKEND", "Agg")
    cmd = [sys.executable, __file__, "--run", name, str(workdir), str(out)]
    if subprocess.run(cmd, env=env, check=False).returncode != 0:
        raise SystemExit(f"notebooks/{name}.py failed (see above)")
    outputs = [Output(**o) for o in json.loads(out.read_text())]
    out.unlink()
    return outputs


def main(argv: list[str]) -> None:
    if argv[:1] == ["--run"]:  # one run of one notebook, in this process
        name, workdir, out = argv[1:4]
        outputs = run_cells(NOTEBOOKS / f"{name}.py", Path(workdir))
        Path(out).write_text(json.dumps([asdict(o) for o in outputs]))
        return
    (PAGES / "img").mkdir(parents=True, exist_ok=True)
    for name in GALLERY:
        with tempfile.TemporaryDirectory() as tmp, tempfile.TemporaryDirectory() as tmp2:
            first, second = _run_apart(name, Path(tmp)), _run_apart(name, Path(tmp2))
            for img in Path(tmp).glob("*.png"):
                shutil.copy2(img, PAGES / "img" / f"{name}-{img.name}")
        outputs = []
        for i, (a, b) in enumerate(zip(first, second, strict=True)):
            where = f"notebooks/{name}.py, cell {i + 1}"
            printed = steady(a.printed, b.printed, f"{where} (printed)")
            outputs.append(Output(printed, steady(a.shown, b.shown, f"{where} (displayed)")))
        text = (NOTEBOOKS / f"{name}.py").read_text()
        (PAGES / f"{name}.md").write_text(render(name, text, outputs))
        print(f"wrote docs/notebooks/{name}.md", file=sys.stderr)


if __name__ == "__main__":
    main(sys.argv[1:])
