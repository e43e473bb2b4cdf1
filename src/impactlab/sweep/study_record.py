"""The study a store records, read back (its canonical form, ``Study.to_dict``)."""

from __future__ import annotations

import warnings
from collections.abc import Mapping
from typing import Any

from impactlab._validation import ImplausibleInputWarning
from impactlab.sweep.limits import SweepSizeWarning
from impactlab.sweep.study import Study

__all__ = ["recorded_study"]


def recorded_study(data: Mapping[str, Any]) -> Study:
    """The study a store records, read back without the warnings (chunking, an implausible
    speed) it gave when it was built (a store is opened many times)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SweepSizeWarning)
        warnings.simplefilter("ignore", ImplausibleInputWarning)
        return Study.from_dict(data)
