"""``python -m impactlab.verification [OUT_DIR] [--out DIR] [--fast]``: run every verification,
write the verification page (``index.md``) and its PNG figures into the output folder
(default ``docs/verification``, relative to the current folder) and exit 1 if a check fails.
``--help`` prints the usage and runs nothing."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from impactlab.verification import page

#: The output folder when none is given (the committed page, from the repository root).
DEFAULT_OUT = "docs/verification"


def parser() -> argparse.ArgumentParser:
    """The command line of ``python -m impactlab.verification``."""
    p = argparse.ArgumentParser(
        prog="python -m impactlab.verification",
        description="Run every verification check, write the verification page (index.md) and "
        "its PNG figures into the output folder, and exit with status 1 if a check fails.",
    )
    p.add_argument(
        "out_dir",
        nargs="?",
        metavar="OUT_DIR",
        help=f"output folder (the same as --out; default {DEFAULT_OUT}, relative to the "
        "current folder: from the repository root it overwrites the committed page)",
    )
    p.add_argument("--out", metavar="DIR", help="output folder (created if needed)")
    p.add_argument(
        "--fast", action="store_true", help="fewer cases and coarser figures (a quick check)"
    )
    return p


def cli(argv: Sequence[str] | None = None) -> int:
    """Parse ``argv`` (default: the process's arguments), run, and return the exit status
    (0: every check passed, 1: one failed; 2 from argparse for a bad command line)."""
    p = parser()
    args = p.parse_args(argv)
    if args.out_dir is not None and args.out is not None and args.out_dir != args.out:
        p.error(f"OUT_DIR {args.out_dir!r} and --out {args.out!r} differ: give one")
    out = args.out or args.out_dir or DEFAULT_OUT
    tables = page.main(out, fast=args.fast)
    return 0 if all(t.passed for t in tables) else 1


if __name__ == "__main__":
    sys.exit(cli())
