"""ArviZ, imported once without its notice about a future refactor (a FutureWarning that
would otherwise reach every user of ``impactlab.calibrate``), and a context that hides its
advisory warnings."""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from contextlib import contextmanager

with warnings.catch_warnings():
    warnings.filterwarnings("ignore", category=FutureWarning, module="arviz")
    import arviz as az

__all__ = ["az", "quiet"]


@contextmanager
def quiet() -> Iterator[None]:
    """Hide ArviZ's advisory warnings (few draws per chain, Pareto k, pandas deprecations):
    the calibration reports what matters in its own warnings (Pareto k counts, R-hat)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        warnings.simplefilter("ignore", FutureWarning)
        warnings.simplefilter("ignore", DeprecationWarning)
        warnings.filterwarnings("ignore", message=".*inplace.*")
        yield
