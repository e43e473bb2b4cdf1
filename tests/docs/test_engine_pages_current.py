"""The Engine pages of the user navigation describe the engine as it is (its costs, how they
are measured, the targets and where they stand): no dates of work, no commits, no per-change
tallies. The history lives on developer pages under "For developers", whose files stay where
other pages link them."""

from __future__ import annotations

import re
from pathlib import Path

import yaml

ROOT = Path(__file__).resolve().parents[2]
DOCS = ROOT / "docs"
USER_PAGES = ("engine/index.md", "engine/first-run.md", "engine/benchmarks.md")
HISTORY = re.compile(
    r"\b20\d\d-\d\d-\d\d\b|\bcommit|\bmain's\b|\bof main\b|\bTried and left\b|"
    r"\bthen \d+(?:\.\d+)?, \d+(?:\.\d+)? and \d"
)


def _nav() -> list:
    text = (ROOT / "mkdocs.yml").read_text(encoding="utf-8")
    text = re.sub(r"!relative \$config_dir", "'.'", text)
    return yaml.safe_load(text)["nav"]


def _section(name: str) -> list[str]:
    entry = next(e for e in _nav() if isinstance(e, dict) and name in e)
    return [v if isinstance(v, str) else next(iter(v.values())) for v in entry[name]]


def test_the_user_engine_pages_hold_no_history() -> None:
    for page in USER_PAGES:
        text = (DOCS / page).read_text(encoding="utf-8")
        hits = [m.group(0) for m in HISTORY.finditer(text)]
        assert not hits, f"docs/{page}: {hits}"


def test_the_history_pages_are_developer_pages() -> None:
    engine, developers = _section("Engine"), _section("For developers")
    assert set(USER_PAGES) <= set(engine)
    for page in ("engine/partial-slip-steps.md", "engine/performance-history.md"):
        assert page in developers and page not in engine
        assert (DOCS / page).is_file()
    history = (DOCS / "engine" / "performance-history.md").read_text(encoding="utf-8")
    assert "## Compile time" in history and "## Engine benchmarks" in history
