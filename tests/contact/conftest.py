"""Shared fixtures of the contact-law tests: the paper's pair and its models (the kernels are
warmed by the suite's one warm-up, ``warm_engine`` in the root conftest)."""

from __future__ import annotations

import pytest

from impactlab.contact import get_law, law_names
from impactlab.contact.base import ContactModel
from impactlab.materials import AISI_201, AISI_1010, ContactPair

#: The paper's tip radius [m].
R_PAPER = 8.8e-3


@pytest.fixture(scope="session")
def paper_pair() -> ContactPair:
    return ContactPair(AISI_201, AISI_1010)


@pytest.fixture(scope="session")
def paper_models(paper_pair: ContactPair) -> dict[str, ContactModel]:
    return {name: get_law(name).build(paper_pair, R_PAPER) for name in law_names()}
