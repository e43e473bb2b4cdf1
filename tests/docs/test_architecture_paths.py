"""The recipes of docs/architecture.md ("Where to add things") name files that exist; a file
named with one of its functions or constants (`path.py`, `name`; `name` in `path.py`) holds
that name; each grep a recipe gives finds exactly the files the paragraph after it lists; and
each Python line it gives imports what exists."""

from __future__ import annotations

import importlib
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
    tokens = set(re.findall(r"`([\w./-]+\.(?:py|md|toml|json|yml))`", _recipes()))
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


def _blocks(start: str) -> list[tuple[str, str]]:
    """(command, the paragraph after it) of every bash block of the recipes starting with
    ``start``."""
    found = re.findall(r"```bash\n(.*?)```\n\n(.*?)(?:\n\n|$)", _recipes(), flags=re.S)
    commands = [(" ".join(cmd.replace("\\\n", " ").split()), after) for cmd, after in found]
    return [(cmd, after) for cmd, after in commands if cmd.startswith(start)]


def _hits(pattern: str) -> set[str]:
    """The files under src/impactlab (relative to it) with a line that ``grep -E`` matches."""
    rule = re.compile(pattern)
    src = ROOT / "src" / "impactlab"
    return {
        p.relative_to(src).as_posix()
        for p in src.rglob("*.py")
        if any(rule.search(line) for line in p.read_text(encoding="utf-8").splitlines())
    }


def test_every_grep_of_a_recipe_finds_the_files_it_lists() -> None:
    greps = _blocks("grep")
    assert len(greps) >= 2  # a friction model, a body
    for command, listing in greps:
        m = re.fullmatch(r"grep -rnE '([^']+)'\s+src/impactlab --include=\*\.py\s*", command)
        assert m, f"a recipe's grep is not of the form this test reads: {command}"
        hits = _hits(m.group(1))
        files = set(re.findall(r"`([\w./-]+\.py)`", listing))
        folders = set(re.findall(r"`([\w./-]+/)`", listing))
        assert len(hits) > 10 and files, command
        listed_not_found = sorted(f for f in files if f not in hits)
        found_not_listed = sorted(
            h for h in hits - files if not any(h.startswith(d) for d in folders)
        )
        assert not listed_not_found and not found_not_listed, (
            f"{command}\nlisted but not found: {listed_not_found}\n"
            f"found but not listed: {found_not_listed}"
        )


def test_the_python_line_of_a_recipe_imports_what_exists() -> None:
    lines = _blocks(".venv/bin/python -c")
    assert lines
    for command, _after in lines:
        imports = re.findall(r"from ([\w.]+) import (\w+)", command)
        assert imports, command
        for module, name in imports:
            assert hasattr(importlib.import_module(module), name), (module, name)
