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


def test_the_help_lists_every_exit_status_of_the_readme() -> None:
    """The README's "Exit status" table says ``impactlab --help`` lists the same: every status
    it names (143 too) and every case it adds to one (a sweep in which no case succeeded, a
    ``sweep run --plot`` that failed after the sweep was stored) is in the help."""
    from typer.testing import CliRunner

    from impactlab.cli import app

    text = README.read_text()
    section = text[text.index("## Exit status") :].split("\n## ", 1)[0]
    assert "`impactlab --help` lists the same" in section
    statuses = set(re.findall(r"^\| (\d+) \|", section, re.M)) | set(
        re.findall(r"exits (\d+)", section)
    )
    assert statuses == {"0", "1", "2", "130", "143"}
    result = CliRunner().invoke(app, ["--help"], terminal_width=200)
    help_ = " ".join(result.output.split()).split("Exit status: ", 1)[1].split("Options:")[0]
    for status in statuses:
        assert re.search(rf"(?:^|; ){status} ", help_), (status, help_)
    for case in ("no case succeeded", "sweep run --plot", "stored", "SIGTERM", "Ctrl-C", "worker"):
        assert case in help_ and case in " ".join(section.split()), case
