"""ArviZ, imported once without its notice about a future refactor (a FutureWarning that
would otherwise reach every user of ``impactlab.calibrate``)."""

from __future__ import annotations

import warnings

with warnings.catch_warnings():
    warnings.filterwarnings("ignore", category=FutureWarning, module="arviz")
    import arviz as az

__all__ = ["az"]
