"""The commands' ``--help`` wrapped between words only: click's formatter breaks a line after a
hyphen, splitting what a user types (``--constant-`` / ``angle``, ``docs/json-`` / ``schema.md``,
``[default: no-`` / ``gravity]``). Here each hyphen is a non-breaking one while click wraps a
text, and an ASCII hyphen again in what is printed."""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

import typer

__all__ = ["HelpContext", "HelpFormatter", "use_help_format"]

#: U+2011 NON-BREAKING HYPHEN: one column wide, never a place to break a line.
_HELD = "\u2011"


class HelpFormatter(typer.Context.formatter_class):  # type: ignore[misc,name-defined,valid-type]
    """The formatter of typer's contexts (click's), with no line broken after a hyphen."""

    def write_text(self, text: str) -> None:
        start = len(self.buffer)
        super().write_text(text.replace("-", _HELD))
        self._release(start)

    def write_dl(
        self, rows: Iterable[tuple[str, str]], col_max: int = 30, col_spacing: int = 2
    ) -> None:
        start = len(self.buffer)
        held = [(a.replace("-", _HELD), b.replace("-", _HELD)) for a, b in rows]
        super().write_dl(held, col_max, col_spacing)
        self._release(start)

    def _release(self, start: int) -> None:
        """The hyphens of what was written since ``start`` back to ASCII ones."""
        self.buffer[start:] = [s.replace(_HELD, "-") for s in self.buffer[start:]]


class HelpContext(typer.Context):
    """A command's context whose help is wrapped by :class:`HelpFormatter`."""

    formatter_class = HelpFormatter


def use_help_format(command: Any) -> None:
    """``command`` and every command under it format their help with :class:`HelpFormatter`."""
    command.context_class = HelpContext
    for sub in getattr(command, "commands", {}).values():
        use_help_format(sub)
