"""``impactlab``, ``impactlab sweep`` and ``impactlab fe`` without a command show their help as
click shows it for a group without a command (multi-line, on stderr, exit status 2), never the
help squeezed into one error line."""

from __future__ import annotations

from typing import Any

import pytest


@pytest.mark.parametrize(
    ("args", "usage", "lists"),
    [
        ((), "impactlab [OPTIONS] COMMAND [ARGS]...", "simulate"),
        (("sweep",), "impactlab sweep [OPTIONS] COMMAND [ARGS]...", "uncertainty"),
        (("fe",), "impactlab fe [OPTIONS] COMMAND [ARGS]...", "indent"),
    ],
)
def test_a_group_alone_shows_its_help(
    cli_main: Any, args: tuple[str, ...], usage: str, lists: str
) -> None:
    code, out, err = cli_main(*args)
    assert code == 2 and out == ""
    lines = err.splitlines()
    # (in this process click names the program after pytest: the line's end is compared)
    assert lines[0].startswith("Usage: ") and lines[0].endswith(usage)
    assert "Commands:" in lines and any(line.strip().startswith(lists) for line in lines)
    assert not err.startswith("error:") and "(see '" not in err


def test_a_usage_error_is_still_one_line(cli_main: Any) -> None:
    code, out, err = cli_main("simulate", "--no-such-option")
    assert code == 2 and out == ""
    assert err.startswith("error: No such option: --no-such-option") and err.count("\n") == 1


def test_include_flagged_help_names_every_flag_it_keeps(cli_main) -> None:
    """Formerly the help named three of the five flags the report excludes."""
    from impactlab.flags import invalidating_names

    code, out, _ = cli_main("sweep", "uncertainty", "--help")
    assert code == 0
    text = " ".join(out.replace("│", " ").split())
    assert f"({invalidating_names()})" in text
    assert "beyond the tip, brittle" in invalidating_names()
