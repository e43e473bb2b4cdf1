"""Every ``python`` code block of the README and the docs is valid Python (a signature listing
is fenced as ``text``), and every block of a tutorial page names only what the page's blocks
before it define, imports or the builtins give: the tutorials say their code works."""

from __future__ import annotations

import ast
import builtins
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PAGES = sorted([ROOT / "README.md", *(ROOT / "docs").rglob("*.md")])
TUTORIALS = sorted((ROOT / "docs" / "tutorials").glob("*.md"))
BLOCK = re.compile(r"^```python\n(.*?)^```", re.S | re.M)


def _blocks(page: Path) -> list[str]:
    return BLOCK.findall(page.read_text(encoding="utf-8"))


@pytest.mark.parametrize("page", PAGES, ids=lambda p: str(p.relative_to(ROOT)))
def test_python_blocks_parse(page: Path) -> None:
    for block in _blocks(page):
        try:
            ast.parse(block)
        except SyntaxError as exc:
            pytest.fail(f"{page.relative_to(ROOT)}: a python block is no Python ({exc}):\n{block}")


def _defined(tree: ast.AST) -> set[str]:
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name) and isinstance(node.ctx, ast.Store):
            names.add(node.id)
        elif isinstance(node, ast.alias):
            names.add((node.asname or node.name).split(".")[0])
        elif isinstance(node, (ast.FunctionDef, ast.ClassDef)):
            names.add(node.name)
        elif isinstance(node, ast.arg):
            names.add(node.arg)
    return names


@pytest.mark.parametrize("page", TUTORIALS, ids=lambda p: p.name)
def test_tutorial_blocks_name_what_is_defined(page: Path) -> None:
    known = set(dir(builtins))
    for block in _blocks(page):
        tree = ast.parse(block)
        known |= _defined(tree)
        used = {n.id for n in ast.walk(tree) if isinstance(n, ast.Name)}
        assert used <= known, f"{page.name}: {sorted(used - known)} undefined in:\n{block}"
