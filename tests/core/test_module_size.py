"""Small modules: no source module of the package is longer than 400 lines (the house rule
that keeps each one readable in one sitting; split by subject when one grows past it)."""

from __future__ import annotations

from pathlib import Path

import impactlab

MAX_LINES = 400


def test_no_module_is_longer_than_400_lines() -> None:
    root = Path(impactlab.__file__).resolve().parent
    long = {
        str(p.relative_to(root)): n
        for p in sorted(root.rglob("*.py"))
        if (n := len(p.read_text(encoding="utf-8").splitlines())) > MAX_LINES
    }
    assert not long, f"modules over {MAX_LINES} lines: {long}"
