"""The seed paper (doi:10.1007/s00419-015-1108-2): its data and the one-command reproduction.

``impactlab.paper.data`` holds Table 1, the experiments, the published rows and the recorded
inconsistencies; :func:`reproduce` regenerates the comparison tables, figures and the report
(it imports the impact engine lazily, so the data are usable without it).
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
    from pathlib import Path

    from impactlab.paper.reproduction import ReproductionResult

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


def reproduce(out_dir: str | Path = "reproduction", **kwargs: Any) -> ReproductionResult:
    """Regenerate the paper's tables, figures and the report into ``out_dir``; see
    :func:`impactlab.paper.reproduction.reproduce`."""
    from impactlab.paper.reproduction import reproduce as _reproduce

    return _reproduce(out_dir, **kwargs)


def __getattr__(name: str) -> Any:
    if name == "ReproductionResult":
        from impactlab.paper.reproduction import ReproductionResult

        return ReproductionResult
    raise AttributeError(f"module 'impactlab.paper' has no attribute {name!r}")
