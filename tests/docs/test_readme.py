"""The README as a new user reads it: every Python block runs, every ``il.NAME`` and
``impactlab.NAME`` it mentions exists."""

from __future__ import annotations

import re
from pathlib import Path

import impactlab

README = Path(__file__).resolve().parents[2] / "README.md"


def _python_blocks(text: str) -> list[str]:
    return re.findall(r"```python\n(.*?)```", text, flags=re.S)


def test_every_python_block_runs() -> None:
    blocks = _python_blocks(README.read_text())
    assert blocks, "the README shows no Python"
    namespace: dict[str, object] = {}
    for block in blocks:  # the blocks build on one another, as in one interpreter
        exec(compile(block, str(README), "exec"), namespace)


def test_every_named_attribute_exists() -> None:
    text = README.read_text()
    names = set(re.findall(r"\b(?:il|impactlab)\.([A-Za-z_][A-Za-z0-9_.]*)", text))
    missing = []
    for dotted in sorted(names):
        obj: object = impactlab
        for part in dotted.rstrip(".").split("."):
            if not hasattr(obj, part):
                # a submodule named in prose (impactlab.sweep) is imported on demand
                try:
                    obj = __import__(f"{obj.__name__}.{part}", fromlist=[part])  # type: ignore[attr-defined]
                except (ImportError, AttributeError):
                    missing.append(dotted)
                    break
            else:
                obj = getattr(obj, part)
    assert not missing, f"README names what impactlab does not have: {missing}"
