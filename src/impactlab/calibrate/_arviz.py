"""ArviZ, imported once without its notice about a future refactor (a FutureWarning that
would otherwise reach every user of ``impactlab.calibrate``), and the contexts that hide or
record its advisory warnings.

``warnings.catch_warnings`` swaps process-wide state and restores it on exit, so two such
blocks in two threads (models calibrated on a threaded Dask worker) undo each other: one
thread's exit restored the filters while the other still computed, and ArviZ's Pareto-k
advisory reached the user's stderr. The contexts here hold one lock while they run.
"""

from __future__ import annotations

import logging
import threading
import warnings
from collections.abc import Iterator
from contextlib import contextmanager

with warnings.catch_warnings():
    warnings.filterwarnings("ignore", category=FutureWarning, module="arviz")
    import arviz as az

__all__ = ["az", "quiet", "recording"]

#: Held by ``quiet`` and ``recording`` (re-entrant: ``quiet`` may run inside ``recording``).
_WARNING_STATE = threading.RLock()


@contextmanager
def _arviz_log_quiet() -> Iterator[None]:
    """ArviZ's log records (``Shape validation failed``: too few draws for R-hat) go nowhere:
    the calibration says so in its own warnings (R-hat not assessable)."""
    # ArviZ logs through its own Logger object (``arviz._log``), not one of logging's registry
    logger = getattr(az, "_log", None) or logging.getLogger("arviz")
    level = logger.level
    logger.setLevel(logging.ERROR)
    try:
        yield
    finally:
        logger.setLevel(level)


@contextmanager
def quiet() -> Iterator[None]:
    """Hide ArviZ's advisory warnings and log records (few draws per chain, Pareto k, pandas
    deprecations) and numpy's floating-point warnings raised in ArviZ's code (a constant
    chain's R-hat): the calibration reports what matters in its own warnings (Pareto k counts,
    R-hat, and R-hat that cannot be assessed, a result that is not a number)."""
    with _WARNING_STATE, warnings.catch_warnings(), _arviz_log_quiet():
        warnings.simplefilter("ignore", UserWarning)
        warnings.simplefilter("ignore", FutureWarning)
        warnings.simplefilter("ignore", DeprecationWarning)
        warnings.filterwarnings("ignore", category=RuntimeWarning, module="arviz")
        warnings.filterwarnings("ignore", message=".*inplace.*")
        yield


@contextmanager
def recording() -> Iterator[list[warnings.WarningMessage]]:
    """Record every warning raised inside (none reaches the user; the caller reports them;
    ArviZ's log records are dropped)."""
    with _WARNING_STATE, warnings.catch_warnings(record=True) as caught, _arviz_log_quiet():
        warnings.simplefilter("always")
        yield caught
