"""The seed paper (doi:10.1007/s00419-015-1108-2): its data and the one-command reproduction.

``impactlab.paper.data`` holds Table 1, the experiments, the published rows and the recorded
inconsistencies (in the paper's signs: dent depth and sliding length negative);
:func:`reproduce` regenerates the comparison tables, figures and the report.
"""

from __future__ import annotations

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
from impactlab.paper.reproduction import ReproductionResult, reproduce

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
