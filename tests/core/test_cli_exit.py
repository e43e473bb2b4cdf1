"""The command line's exit leaves out the collector's passes of Python's finalisation
(``impactlab.cli._freeze_at_exit``): every object alive at exit is frozen first, once per
process however often ``main()`` runs, and what the command printed is unchanged."""

from __future__ import annotations

import subprocess
import sys


def test_objects_alive_at_exit_are_frozen_before_finalisation() -> None:
    code = (
        "import atexit, gc, sys\n"
        # registered before main()'s handler, so it runs after it (atexit runs in reverse order)
        "atexit.register(lambda: print('frozen', gc.get_freeze_count() > 0))\n"
        "from impactlab.cli import main\n"
        "sys.argv = ['impactlab', '--version']\n"
        "main()\n"
        "main()\n"
        "print('frozen before exit', gc.get_freeze_count() > 0)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, timeout=600, check=True
    ).stdout.splitlines()
    assert out[0].startswith("impactlab ") and out[1] == out[0]  # the version, twice
    assert out[2:] == ["frozen before exit False", "frozen True"]
