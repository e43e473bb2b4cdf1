"""The seed paper (doi:10.1007/s00419-015-1108-2): its data and the one-command reproduction.

``impactlab.paper.data`` holds Table 1, the experiments, the published rows and the recorded
inconsistencies (in the paper's signs: dent depth and sliding length negative);
:func:`reproduce` regenerates the comparison tables, figures and the report.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from impactlab.paper.data import (
    CASES,
    CITATION,
    DISCREPANCIES,
    DOI,
    EXPERIMENTS,
    PAPER_LAWS,
    PAPER_ROD,
    TABLE1,
    TABLE_ROWS,
    TEXT_ROWS,
    Experiment,
    PublishedRow,
    get_case,
)

if TYPE_CHECKING:
    from impactlab.paper.reproduction import ReproductionResult, reproduce


def __getattr__(name: str) -> Any:
    """``reproduce`` and ``ReproductionResult``, imported on first use: the reproduction
    imports every report section, and ``python -m impactlab.paper.calibration_report`` (one of
    them) must not find itself imported before it runs."""
    if name in ("reproduce", "ReproductionResult"):
        from impactlab.paper import reproduction

        return getattr(reproduction, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


__all__ = [
    "CASES",
    "CITATION",
    "DISCREPANCIES",
    "DOI",
    "EXPERIMENTS",
    "PAPER_LAWS",
    "PAPER_ROD",
    "TABLE1",
    "TABLE_ROWS",
    "TEXT_ROWS",
    "Experiment",
    "PublishedRow",
    "ReproductionResult",
    "get_case",
    "reproduce",
]
