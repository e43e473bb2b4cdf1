"""The recipes of docs/architecture.md ("Where to add things") name files that exist, and a
file named with one of its functions or constants (`path.py`, `name`; `name` in `path.py`)
holds that name."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PAGE = ROOT / "docs" / "architecture.md"


def _recipes() -> str:
    text = PAGE.read_text(encoding="utf-8")
    start = text.index("## Where to add things")
    return text[start : text.index("\n## ", start + 3)]


def _file(token: str) -> Path | None:
    for base in (ROOT, ROOT / "src" / "impactlab"):
        if (base / token).is_file():
            return base / token
    return None


def test_every_file_a_recipe_names_exists() -> None:
    tokens = set(re.findall(r"`([\w./-]+\.(?:py|md|toml))`", _recipes()))
    assert len(tokens) > 40
    missing = sorted(t for t in tokens if _file(t) is None)
    assert not missing, f"docs/architecture.md names files that do not exist: {missing}"


def test_a_file_named_with_a_name_holds_it() -> None:
    text = _recipes()
    pairs = re.findall(r"`([\w./-]+\.py)`,\s+`(\w+)`", text)  # `path.py`, `name`
    pairs += [(p, n) for n, p in re.findall(r"`(\w+)`\s+(?:in|of)\s+`([\w./-]+\.py)`", text)]
    assert len(pairs) >= 10
    for token, name in pairs:
        path = _file(token)
        assert path is not None, token
        assert re.search(rf"\b{name}\b", path.read_text(encoding="utf-8")), (token, name)
