"""The "Public API" block of docs/engine/index.md shows the signatures of ``simulate``,
``simulate_batch`` and ``run_arrays`` as the code has them (every keyword, its default), and
says that a sphere's angle is refused, as the code does."""

from __future__ import annotations

import inspect
import math
import re
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest

import impactlab as il
from impactlab.dynamics import batch

PAGE = Path(__file__).resolve().parents[2] / "docs" / "engine" / "index.md"
FUNCTIONS: dict[str, Callable[..., Any]] = {
    "simulate": il.simulate,
    "simulate_batch": il.simulate_batch,
    "impactlab.dynamics.batch.run_arrays": batch.run_arrays,
}


def _block() -> str:
    text = PAGE.read_text(encoding="utf-8")
    start = text.index("\n## Public API\n")
    section = text[start : text.index("\n## ", start + 3)]
    return section[
        section.index("```text\n") + 8 : section.index("\n```", section.index("```text"))
    ]


def _shown(name: str) -> list[tuple[str, str | None]]:
    """(parameter, default or None) of ``name``'s signature as the block shows it."""
    block = " ".join(_block().split())
    m = re.search(rf"(?:^| ){re.escape(name)}\((.*?)\) ->", block)
    assert m, f"the Public API block does not show {name}(...)"
    shown = []
    for part in (p.strip() for p in m.group(1).split(",")):
        if part == "*":
            continue
        key, _, default = part.partition("=")
        shown.append((key.strip(), default.strip() or None))
    return shown


def _default_text(value: object) -> str:
    if isinstance(value, str):
        return f'"{value}"'
    if isinstance(value, float) and math.isinf(value):
        return "inf"
    return repr(value)


@pytest.mark.parametrize("name", sorted(FUNCTIONS))
def test_the_block_shows_each_keyword_and_default(name: str) -> None:
    params = inspect.signature(FUNCTIONS[name]).parameters
    shown = _shown(name)
    names = [k.lstrip("*") for k, _ in shown]
    assert names == list(params), f"{name}: the page shows {names}, the code has {list(params)}"
    for key, default in shown:
        p = params[key.lstrip("*")]
        if p.default is inspect.Parameter.empty or key == "flat":
            assert default is None or key == "flat", f"{name}: {key} has no default"
            continue
        assert default == _default_text(p.default), f"{name}: {key}={default}, code {p.default!r}"


def test_the_page_says_a_sphere_s_angle_is_refused() -> None:
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    assert "ignored for a sphere" not in text
    assert "a sphere takes none: an angle given for it is refused" in text
    with pytest.raises(ValueError, match="a Sphere has no angle"):
        il.simulate_batch(il.Sphere(radius=0.01), angle=0.5 * math.pi, vy=-1.0)
