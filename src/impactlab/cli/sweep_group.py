"""``impactlab sweep``'s command group: ``impactlab sweep STUDY.toml ...`` read as ``sweep run
STUDY.toml ...``, and a first word that is neither a subcommand nor a path refused with the
subcommands; SIGTERM during any of its commands ends it as Ctrl-C does."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import typer
from typer.core import TyperGroup

from impactlab._validation import did_you_mean
from impactlab.cli._common import UserError

#: Words for a subcommand that is spelled otherwise: the one meant.
_MEANT = {"summary": "info", "status": "info", "show": "info", "csv": "export", "plots": "plot"}


class DefaultRun(TyperGroup):
    """``impactlab sweep STUDY.toml ...`` means ``impactlab sweep run STUDY.toml ...``; a first
    word that is no file and no path (``infoo``, ``summary``) is refused with the subcommands
    (and the one it nearly is); a path that is no file (``study.toml``) is the run's to refuse.
    SIGTERM (``kill``, ``timeout``, a batch system's time limit) during any subcommand, an
    export or a plot included, ends it as Ctrl-C does: the file being written is removed, one
    line on stderr, exit status 143."""

    def invoke(self, ctx: Any) -> Any:
        from impactlab.sweep.termination import TERMINATED_EXIT, sigterm_as_interrupt, terminated

        try:
            with sigterm_as_interrupt():
                return super().invoke(ctx)
        except KeyboardInterrupt as exc:
            if not terminated(exc):
                raise
            if not getattr(exc, "said", False):
                print(exc.args[0] if exc.args else "terminated", file=sys.stderr, flush=True)
            raise typer.Exit(TERMINATED_EXIT) from None

    def parse_args(self, ctx: Any, args: list[str]) -> list[str]:
        first = self._first_positional(args)
        if first is not None and first not in self.commands:
            if not Path(first).exists() and not {".", "/", "\\"} & set(first):
                meant = _MEANT.get(first.lower())
                near = f" (did you mean {meant!r}?)" if meant else ""
                near = near or did_you_mean(first, list(self.commands))
                raise UserError(
                    f"no subcommand {first!r}{near} and no study file of that name; "
                    f"subcommands: {', '.join(self.commands)} (impactlab sweep --help)"
                )
            args = ["run", *args]
        return super().parse_args(ctx, args)

    def _first_positional(self, args: list[str]) -> str | None:
        """The first word of ``args`` that is no option and no option's value (``--out runs``:
        ``runs`` is ``--out``'s value); which options take a value, click says (the group's
        own and ``run``'s: the default subcommand)."""
        params = [*self.params, *getattr(self.commands.get("run"), "params", [])]
        takes_value = {
            name
            for p in params
            if p.param_type_name == "option" and not (p.is_flag or p.count)
            for name in (*p.opts, *p.secondary_opts)
        }
        words = iter(args)
        for word in words:
            if word == "--":
                return next(words, None)
            if not word.startswith("-"):
                return word
            if word in takes_value:  # "--out VALUE"; "--out=VALUE" carries its own
                next(words, None)
        return None
