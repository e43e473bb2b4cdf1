"""The paper's three drops as a measurements file (its rod, vy, measured mu, e, dent and scar
with the paper calibration's assumed sigmas) and their explanation, made once per session."""

from __future__ import annotations

from pathlib import Path

import pytest

from impactlab.explain import Explanation, explain
from impactlab.paper.calibration_report import paper_measurements


@pytest.fixture(scope="session")
def paper_file(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The paper's drops written as a user's CSV measurements file."""
    return paper_measurements().to_csv(tmp_path_factory.mktemp("drops") / "paper.csv")


@pytest.fixture(scope="session")
def paper_explained(paper_file: Path) -> Explanation:
    return explain(paper_file)
