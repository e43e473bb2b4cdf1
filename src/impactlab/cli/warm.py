"""``impactlab warm``: compile the engine ahead of its first use, or check that it is cached."""

from __future__ import annotations

import json

import typer

from impactlab.cli._common import UserError, console
from impactlab.cli.printing import versioned


def warm(
    part: list[str] = typer.Option(
        None,
        "--part",
        metavar="PART",
        help="Only this part (repeatable: --part batch --part 'flexible rod'): 'contact laws', "
        "'rigid impact', 'batch', 'partial slip', 'flexible rod', 'flexible partial slip', "
        "'flexible batch'. Default: all.",
    ),
    jobs: int = typer.Option(
        None,
        "--jobs",
        help="Processes compiling side by side (the rigid and the flexible engine); "
        "default: one per core, at most 2. 1: all in this process.",
    ),
    as_json: bool = typer.Option(False, "--json", help="Machine-readable output."),
) -> None:
    """Compile every part of the engine into the cache, so that later runs start at once.

    The first run after installing or updating impactlab compiles (about 1.5 minutes on a
    2-core machine, two processes side by side, said on stderr while it runs); afterwards
    this loads the cache in a few seconds. The cache folder: NUMBA_CACHE_DIR if set, else
    IMPACTLAB_CACHE_DIR/numba, else ~/.cache/impactlab/numba.

    Example: impactlab warm
    """
    from impactlab.dynamics.warm import compiled_cache_dir, warm_in_processes

    if jobs is not None and jobs < 1:
        raise UserError(f"--jobs must be a positive integer, got {jobs}")
    try:
        done = warm_in_processes(tuple(part) if part else None, jobs)
    except (ValueError, RuntimeError) as exc:
        raise UserError(str(exc)) from None
    cache_dir = str(compiled_cache_dir())
    if as_json:
        parts = [
            {
                "name": p.name,
                "wall_time": {"value": p.wall_s, "unit": "s"},
                "cpu_time": {"value": p.cpu_s, "unit": "s"},
            }
            for p in done
        ]
        print(json.dumps(versioned({"cache_dir": cache_dir, "parts": parts}), indent=2))
        return
    for p in done:
        console.print(f"{p.name:<14} {p.wall_s:7.1f} s wall, {p.cpu_s:7.1f} s CPU")
    console.print(f"compiled engine cached in {cache_dir}", soft_wrap=True)  # a path unbroken


def register(app: typer.Typer) -> None:
    """Add ``impactlab warm`` to ``app``."""
    app.command("warm")(warm)
