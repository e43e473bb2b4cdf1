"""The product speaks of the product: no development history (numbered sessions, waves, issues,
contracts; a session or an issue at all) in the code, the tests, the benchmarks and tools, the
task runner, the contributors' page or the user documentation. That history belongs to
CHANGELOG.md (with its performance history) and git; a comment or a page states the fact or
the reason instead, and cites a page by its subject. A bare "wave" is not checked: the
physics has wave speeds and waves in the flat."""

from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]

#: the folders and files read: the package, the tests, the user docs, the examples and
#: notebooks, the benchmarks and tools, the test set-up, the task runner, the contributors' page
#: and the site's configuration (CHANGELOG.md is not read)
SCANNED = (
    "src",
    "tests",
    "docs",
    "examples",
    "notebooks",
    "benchmarks",
    "tools",
    "README.md",
    "CONTRIBUTING.md",
    "conftest.py",
    "tasks.py",
    "mkdocs.yml",
)
#: left out: the changelog page (it includes CHANGELOG.md)
EXCLUDED = ("docs/changelog.md",)
SUFFIXES = {".py", ".md", ".toml", ".yml", ".yaml", ".txt", ".cfg", ".ini", ".rst"}

# built from pieces, so that this file does not match its own pattern
_SESSION, _WAVE, _ISSUE, _CONTRACT = "sess" + "ion", "wa" + "ve", "iss" + "ue", "con" + "tract"
HISTORY = re.compile(
    rf"\b({_SESSION}|{_WAVE}) ?[0-9]+|\b{_ISSUE} #?[0-9]+\b|{_WAVE}4|{_CONTRACT} C[12]",
    re.IGNORECASE,
)
#: The words themselves, numbered or not ("this session", "the issue"); a word inside an
#: identifier (``session_id``) is no word.
BARE = re.compile(rf"\b({_SESSION}|{_ISSUE})s?\b", re.IGNORECASE)
#: What ``BARE`` lets pass: pytest's session scope (``scope="session"``, a session fixture,
#: once per session) and the verb (issue a warning, as Python issues it).
ALLOWED = re.compile(
    rf"""scope=["']{_SESSION}["']|\b{_SESSION} fixtures?\b|\bper {_SESSION}\b"""
    rf"|\b{_ISSUE}s? (?:a|an|it|them)\b",
    re.IGNORECASE,
)


def _files() -> list[Path]:
    out: list[Path] = []
    for name in SCANNED:
        top = ROOT / name
        paths = [top] if top.is_file() else sorted(top.rglob("*"))
        for p in paths:
            rel = p.relative_to(ROOT).as_posix()
            if (
                p.is_file()
                and p.suffix in SUFFIXES
                and "__pycache__" not in p.parts
                and not rel.startswith(EXCLUDED)
                and p.resolve() != Path(__file__).resolve()
            ):
                out.append(p)
    return out


def _bare(line: str) -> re.Match[str] | None:
    """The first bare history word of ``line`` that ``ALLOWED`` does not let pass."""
    return BARE.search(ALLOWED.sub(" ", line))


def _hits() -> list[tuple[str, int, str]]:
    hits = []
    for p in _files():
        text = p.read_text(encoding="utf-8", errors="replace")
        for no, line in enumerate(text.splitlines(), 1):
            m = HISTORY.search(line) or _bare(line)
            if m:
                hits.append((p.relative_to(ROOT).as_posix(), no, m.group(0)))
    return hits


def test_pattern_finds_history_words() -> None:
    for text in (
        f"{_SESSION.title()} 8",
        f"({_ISSUE} 12)",
        f"{_ISSUE} #14",
        f"{_WAVE} 4",
        f"test_{_WAVE}4_str",
        f"{_CONTRACT} C2",
    ):
        assert HISTORY.search(text), text
    for text in ("the session's store", "an issue of the journal", "wave speed c0 = 5 km/s"):
        assert not HISTORY.search(text), text


def test_bare_words_are_found_and_pytest_and_the_verb_pass() -> None:
    for text in (
        f"the {_SESSION}'s store",
        f"as in one {_SESSION}",
        f"{_SESSION.title()}s of work",
        f"an {_ISSUE} of the journal",
        f"see the {_ISSUE}s",
        f'scope="{_SESSION}" for this {_SESSION}',
    ):
        assert _bare(text), text
    for text in (
        f'@pytest.fixture(scope="{_SESSION}")',
        f"the {_SESSION} fixture ``site``",
        f"compiled once per {_SESSION}",
        f"{_ISSUE.title()} an ImplausibleInputWarning",
        f"as Python {_ISSUE}s it",
        f"{_SESSION}_id = 3; my_{_ISSUE}s = []",
        "wave speed c0 = 5 km/s",
    ):
        assert not _bare(text), text


def test_scan_covers_the_product() -> None:
    files = {p.relative_to(ROOT).as_posix() for p in _files()}
    assert "src/impactlab/__init__.py" in files
    assert "docs/engine/benchmarks.md" in files
    assert "README.md" in files
    assert {"CONTRIBUTING.md", "conftest.py", "tasks.py", "mkdocs.yml"} <= files
    assert "benchmarks/run_all.py" in files and "tools/fingerprint.py" in files
    assert "CHANGELOG.md" not in files
    assert not any(f.startswith(EXCLUDED) for f in files)
    assert "tests/core/test_product_words.py" not in files


def test_no_history_words_in_code_tests_or_user_docs() -> None:
    hits = _hits()
    listed = "\n".join(f"{f}:{no}: {word!r}" for f, no, word in hits)
    assert not hits, (
        "development history in the product (state the fact; history goes to CHANGELOG.md):\n"
        f"{listed}"
    )
