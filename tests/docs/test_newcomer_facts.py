"""What the README and the tutorials tell a newcomer holds, read literally: which commands'
``--help`` shows an example (and where the others' examples are), the DOI of each contact law
in the README's table (as ``impactlab laws`` gives it), and what a sweep's ``status`` 0 means
(the engine finished the case; whether its result is ok is the flags' verdict)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from typer.testing import CliRunner

from impactlab.cli import app
from impactlab.contact import get_law, law_names

ROOT = Path(__file__).resolve().parents[2]
README = (ROOT / "README.md").read_text(encoding="utf-8")
#: where the README's sentence about the commands' help starts
HELP_START = "Every command and subcommand has `--help`"
#: command -> the page that the README says shows its example, and the command line it shows
EXAMPLES_ELSEWHERE = {
    "calibrate": ("docs/calibrate.md", "impactlab calibrate "),
    "fe indent": ("docs/fe.md", "impactlab fe indent "),
    "sweep info": ("docs/tutorials/sweep.md", "impactlab sweep info "),
    "sweep plot": ("docs/tutorials/sweep.md", "impactlab sweep plot "),
    "sweep export": ("docs/tutorials/sweep.md", "impactlab sweep export "),
}


def _help(words: list[str]) -> str:
    result = CliRunner().invoke(app, [*words, "--help"], terminal_width=100)
    assert result.exit_code == 0, (words, result.output)
    return result.output


def _commands(words: list[str]) -> list[list[str]]:
    """Every command and subcommand below ``words``, from the help's "Commands:" lists."""
    text = _help(words)
    if "\nCommands:\n" not in text:
        return [words]
    listed = re.findall(r"^  ([a-z][\w-]*)\s", text.split("\nCommands:\n", 1)[1], re.MULTILINE)
    assert listed, text
    return [c for name in listed for c in _commands([*words, name])]


def test_every_command_has_help_and_the_readme_names_its_example() -> None:
    assert HELP_START in README, "the README no longer says which commands' help has examples"
    claim = " ".join(README[README.index(HELP_START) :].split())
    assert "with examples" not in claim.split(". Every command accepts")[0]
    shown = re.search(r"the help of (.*?) shows an example", claim)
    assert shown is not None, claim
    with_example = re.findall(r"`([a-z][a-z ]*)`", shown.group(1))
    commands = [" ".join(c) for c in _commands([])]
    assert {"simulate", "sweep run", "fe indent"} <= set(commands)
    elsewhere = claim[shown.end() :].split(". Every command accepts")[0]
    for command in commands:
        text = _help(command.split())
        if command in with_example:
            assert "Example" in text, f"README: the help of {command!r} shows an example"
            continue
        # the README names the command and links the page that shows its example
        assert command in EXAMPLES_ELSEWHERE, f"README says nothing of {command!r}'s example"
        named = f"`{command}`" in elsewhere or (
            command.startswith("sweep ") and "`sweep info`/`plot`/`export`" in elsewhere
        )
        page, line = EXAMPLES_ELSEWHERE[command]
        assert named and f"]({page})" in elsewhere, (command, elsewhere)
        assert line in (ROOT / page).read_text(encoding="utf-8"), (command, page)


@pytest.mark.parametrize("name", law_names())
def test_readme_law_table_gives_each_laws_doi(name: str) -> None:
    rows = [ln for ln in README.splitlines() if ln.startswith(f"| `{name}` |")]
    assert len(rows) == 1, f"README's law table has {len(rows)} rows for {name!r}"
    doi = get_law(name).doi
    assert doi and f"doi:{doi}" in rows[0], (name, doi, rows[0])


def test_no_page_says_status_0_is_ok() -> None:
    """``status`` 0 is "finished": a finished case may still be flagged (not ok)."""
    pattern = re.compile(r"`status`\s*\(?\s*0\s*(?:=|:|means|is)\s*`?ok\b", re.IGNORECASE)
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
    wrong = [str(p.relative_to(ROOT)) for p in pages if pattern.search(p.read_text("utf-8"))]
    assert not wrong, f"status 0 called ok in {wrong}"
    sweep = " ".join((ROOT / "docs/tutorials/sweep.md").read_text(encoding="utf-8").split())
    assert "`status` (0 = finished" in sweep
