"""The ``impactlab`` command line. Each command lives in its own module with a ``register(app)``.

User errors (a ValueError; an OSError impactlab raised with its own message, such as a file
not found) and running out of memory (an input that asks for too much) exit with status 2 and
one line naming the bad input, never a traceback; an error of the system on a file, whatever
its errno (no permission, a read-only file system, a full disk), with status 1 and one line in
the words of ``impactlab._oserror`` naming the file (never a writer's temporary file). Set
``IMPACTLAB_DEBUG=1`` to see the traceback. Ctrl-C exits with status 130 and one line
(``interrupted``, or the command's own: ``sweep run``, ``calibrate``).
"""

from __future__ import annotations

import atexit
import gc
import os
import sys
import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any, TextIO

import typer
from typer.core import TyperGroup

from impactlab import _runtime
from impactlab._interrupts import interrupt_inside
from impactlab._oserror import system_error_line as _system_error_line
from impactlab._version import __version__
from impactlab.cli import (
    analyze,
    calibrate,
    drop,
    explain,
    fe,
    invert,
    laws,
    materials,
    reproduce,
    simulate,
    sweep,
    warm,
)
from impactlab.cli._common import refuse_empty_paths
from impactlab.cli.help_format import use_help_format
from impactlab.cli.printing import print_wrapped


class _Commands(TyperGroup):
    """impactlab's commands: Ctrl-C during one prints one line on stderr and exits 130 (typer
    itself would exit 130 without a word); an empty path is refused by name
    (``refuse_empty_paths``); the help never breaks a line after a hyphen (``help_format``)."""

    def main(self, *args: Any, **kwargs: Any) -> Any:
        refuse_empty_paths(self)
        use_help_format(self)
        return super().main(*args, **kwargs)

    def invoke(self, ctx: Any) -> Any:
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt as exc:
            interrupted(exc)
            raise typer.Exit(130) from None
        except SystemError as exc:  # Ctrl-C inside a compiled call, wrapped by numba
            ki = interrupt_inside(exc)
            if ki is None:
                raise
            interrupted(ki)
            raise typer.Exit(130) from None


def interrupted(exc: KeyboardInterrupt) -> None:
    """Say on stderr that a command was interrupted: ``interrupted``, or a sweep's own line
    (``SweepInterrupted``: how many chunks are stored), unless the sweep printed it already
    (not ``--quiet``). A command that prints its own line (``calibrate``) exits 130 itself,
    without reaching here."""
    runner = sys.modules.get("impactlab.sweep.runner")  # not loaded: no sweep ran
    if runner is not None and isinstance(exc, runner.SweepInterrupted):
        if not exc.said:
            print(exc.args[0] if exc.args else "interrupted", file=sys.stderr, flush=True)
        return
    print("interrupted", file=sys.stderr, flush=True)


app = typer.Typer(
    cls=_Commands,
    name="impactlab",
    help="Elastic-plastic oblique impacts with friction: simulate, invert, analyze, sweep, "
    "reproduce the paper.\n\nExit status: 0 done (flagged results too); 2 an input refused, "
    "before any work where it can be checked (an output folder that cannot be written too), or "
    "a sweep in which no case succeeded; 1 an error of the system on a file while working (no "
    "permission, a read-only file system, a full disk), a sweep run --plot whose plot failed "
    "after the sweep was stored, or a sweep whose worker process died; 130 interrupted "
    "(Ctrl-C); 143 a sweep stopped by SIGTERM (README: Exit status).",
    no_args_is_help=True,
    add_completion=False,
    context_settings={"help_option_names": ["-h", "--help"]},
    pretty_exceptions_enable=False,
    rich_markup_mode=None,  # help texts are plain: "[rod]" is a TOML table, not markup
)


def _print_version(value: bool) -> None:
    if value:
        typer.echo(f"impactlab {__version__}")
        raise typer.Exit()


@app.callback()
def _root(
    version: bool = typer.Option(
        False,
        "--version",
        callback=_print_version,
        is_eager=True,
        help="Print the version of impactlab and exit.",
    ),
    law_file: list[Path] = typer.Option(
        [],
        "--law-file",
        metavar="FILE",
        help="A contact law of one's own from measured indentation data (TOML, see "
        "docs/laws/user.md); its name then works as --law NAME. Repeatable: --law-file A.toml "
        "--law-file B.toml.",
    ),
) -> None:
    """Elastic-plastic oblique impacts with friction: simulate, invert, analyze, sweep,
    reproduce the paper."""
    if law_file:
        from impactlab.contact import read_law_file

        for path in law_file:
            read_law_file(path)


# Each command module defines ``register(app)``; registered in this order (the help's order).
for _module in (
    laws,
    materials,
    simulate,
    drop,
    invert,
    analyze,
    calibrate,
    explain,
    sweep,
    reproduce,
    fe,
    warm,
):
    _module.register(app)

#: Each command's line in ``impactlab --help``: whole (click would cut the help's first sentence
#: at 45 characters, mid-phrase), within the 80-column screen.
SHORT_HELP = {
    "laws": "List the contact laws, or show one (DOI, validity).",
    "materials": "List the material library, or show one material.",
    "simulate": "Simulate one impact of a rod or a sphere on a flat.",
    "drop": "Drop a rod on a flat through its whole contact sequence.",
    "invert": "Impact duration T and mean force F from a measured impact.",
    "analyze": "Analyse one drop: marker tracks, dent scan, T and F.",
    "calibrate": "Calibrate models on measured drops and rank them.",
    "explain": "Which physics explains measured drops (nothing tuned).",
    "reproduce": "Reproduce the paper's tables and figures, with a report.",
    "warm": "Compile the engine into the cache, so later runs start at once.",
    "sweep": "Grids and Monte Carlo studies of many impacts (Zarr store).",
    "fe": "Sphere-on-flat indentation by finite elements (CalculiX).",
}
for _command in app.registered_commands:
    _command.short_help = SHORT_HELP[str(_command.name)]
for _group in app.registered_groups:
    _group.short_help = SHORT_HELP[str(_group.name)]


def _own(category: type[Warning]) -> bool:
    """True for a warning category defined by impactlab (ImplausibleInputWarning, ...)."""
    return category.__module__.split(".")[0] == "impactlab"


@contextmanager
def _one_line_warnings() -> Iterator[None]:
    """Show impactlab's own warnings as one line ``warning: <message>`` on stderr (no file,
    line number or source line; on a terminal wrapped to its width); other warnings as Python
    shows them."""
    previous = warnings.showwarning

    def show(
        message: Warning | str,
        category: type[Warning],
        filename: str,
        lineno: int,
        file: TextIO | None = None,
        line: str | None = None,
    ) -> None:
        if _own(category):
            print_wrapped(f"warning: {message}", file)
        else:
            previous(message, category, filename, lineno, file, line)

    warnings.showwarning = show
    try:
        yield
    finally:
        warnings.showwarning = previous


def _run() -> Any:
    with _one_line_warnings():
        return app(standalone_mode=False)  # typer.Exit(n) comes back as a return value here


def _freeze_at_exit() -> None:
    """At the interpreter's exit: every object alive moves to the collector's permanent
    generation (``gc.freeze``), so that the collections of Python's finalisation pass over
    none of them. Over the objects of numba and of the loaded engine (about 180,000 after a
    start from the cache, 325,000 after a first compile) they cost 0.5 s of CPU at the end of
    a cached ``impactlab simulate rod`` and 1.2 s after a cold one (docs/engine/first-run.md).
    The process ends right after and its memory goes back to the system as a whole; only
    reference cycles still alive at exit are no longer collected (Python does not promise to
    finalise those either)."""
    gc.freeze()


def _usage_line(exc: Exception, message: str) -> str:
    """click's usage error in one line, with the command whose help says more; an option of
    ``impactlab`` itself given after a command (``--law-file``) says where it goes."""
    text = " ".join(message.split())
    ctx = getattr(exc, "ctx", None)
    path = getattr(ctx, "command_path", None)
    if getattr(exc, "option_name", None) == "--law-file" and ctx is not None:
        names = []  # the command's words below impactlab's own ("sweep run")
        while ctx.parent is not None:
            names.append(str(ctx.info_name))
            ctx = ctx.parent
        command = " ".join(reversed(names)) or "COMMAND"
        return (
            f"{text}; --law-file goes before the command: impactlab --law-file FILE.toml "
            f"{command} ..."
        )
    return f"{text} (see '{path} --help')" if isinstance(path, str) and path else text


def _refused_input(exc: OSError) -> bool:
    """Whether ``exc`` is a refusal of the user's input (exit status 2, as a ValueError): an
    OSError impactlab raised with a message of its own and no errno
    (``FileNotFoundError("calibration file not found: x")``). An OSError of the system, with
    its errno (no permission, a read-only file system, a full disk), is not: status 1."""
    return exc.errno is None and exc.strerror is None


def main() -> None:
    """Entry point: run the app and turn user errors into a one-line message with exit code 2;
    impactlab's own warnings print as one line ``warning: <message>``."""
    _runtime.release_start_interrupt()  # from here a command's Ctrl-C: KeyboardInterrupt
    atexit.unregister(_freeze_at_exit)  # once, however often main() runs in one process
    atexit.register(_freeze_at_exit)
    try:
        rc = _run()
    except SystemExit:
        raise
    except (ValueError, OSError) as exc:
        if os.environ.get("IMPACTLAB_DEBUG"):
            raise
        if not isinstance(exc, OSError) or _refused_input(exc):  # the input refused: status 2
            print_wrapped(f"error: {exc}")
            sys.exit(2)
        # the system's, whatever its errno (no permission, a read-only file system, a full
        # disk, a file where a folder should be): its words and the file named, status 1
        print_wrapped(f"error: {_system_error_line(exc)}")
        sys.exit(1)
    except MemoryError as exc:  # an input that asks for more than the machine has
        if os.environ.get("IMPACTLAB_DEBUG"):
            raise
        said = f": {exc}" if str(exc) else ""
        print_wrapped(
            f"error: out of memory{said}; an input asks for more than this machine has (a "
            "sample count, a grid, a resolution): choose a smaller one"
        )
        sys.exit(2)
    except KeyboardInterrupt as exc:  # outside a command (typer's set-up): no line yet
        interrupted(exc)
        sys.exit(130)
    except Exception as exc:  # usage errors of typer's (vendored) click, and the like
        if type(exc).__name__ == "NoArgsIsHelpError":  # a group without a command: its help
            exc.show()  # type: ignore[attr-defined]  # as click shows it: on stderr, status 2
            sys.exit(exc.exit_code)  # type: ignore[attr-defined]
        message = getattr(exc, "format_message", None)
        code = getattr(exc, "exit_code", None)
        if callable(message) and isinstance(code, int):  # one line, as every other error
            print_wrapped(f"error: {_usage_line(exc, str(message()))}")
            sys.exit(code)
        if type(exc).__name__ == "Abort":
            print("aborted", file=sys.stderr)
            sys.exit(1)
        raise
    if isinstance(rc, int) and rc != 0:
        sys.exit(rc)
