"""A test hook: stop the sweep process at a named stage, to test recovery from a kill at that
exact moment (no timing involved).

With ``IMPACTLAB_SWEEP_KILL_AT=<stage>`` in the environment, the process sends itself
``IMPACTLAB_SWEEP_KILL_SIGNAL`` (default ``SIGKILL``; ``SIGINT`` for Ctrl-C) when it reaches
``<stage>``. Stages (see :data:`STAGES`): store creation (``create:tempdir``, ``create:arrays``,
``create:built``, ``create:renamed``), a restart (``restart:moved``), and per chunk *k*
``chunk:<k>:data`` (its arrays written, marker not yet) and ``chunk:<k>:done`` (marker written),
and an exported file or plot written under its temporary name, not yet renamed
(``write:partial``).
Without the variable the hook does nothing.
"""

from __future__ import annotations

import os
import signal

#: The environment variables of the hook.
KILL_AT = "IMPACTLAB_SWEEP_KILL_AT"
KILL_SIGNAL = "IMPACTLAB_SWEEP_KILL_SIGNAL"

#: The named stages (``chunk:<k>:data`` and ``chunk:<k>:done`` exist for every chunk k).
STAGES = (
    "create:tempdir",  # the temporary sibling directory exists, empty
    "create:arrays",  # its arrays exist, the root attributes and study.json not yet
    "create:built",  # complete, not yet renamed into place
    "create:renamed",  # the store is in place, no chunk computed
    "restart:moved",  # --restart: the old store moved aside, the new one not yet created
    "write:partial",  # an export or a plot written under its temporary name, not yet renamed
)


def checkpoint(stage: str) -> None:
    """Send this process the hook's signal if ``stage`` is the stage named in the environment."""
    if os.environ.get(KILL_AT) != stage:
        return
    name = os.environ.get(KILL_SIGNAL, "SIGKILL")
    sig = getattr(signal, name, None)
    if not isinstance(sig, signal.Signals):
        raise ValueError(f"{KILL_SIGNAL}={name!r} is not a signal name such as 'SIGKILL'")
    os.kill(os.getpid(), sig)
