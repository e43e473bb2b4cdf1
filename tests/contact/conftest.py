"""Shared fixtures of the contact-law tests: the paper's pair, and one warm-up of the kernels."""

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


@pytest.fixture(scope="session", autouse=True)
def _warm_kernels() -> None:
    """Compile (or load from the numba cache) every kernel once per session."""
    pair = ContactPair(AISI_201, AISI_1010)
    for name in law_names():
        model = get_law(name).build(pair, R_PAPER)
        model.force([1e-7, 1e-5])
        model.contact_radius([1e-7, 1e-5])
        model.unload(1e-5)


@pytest.fixture(scope="session")
def paper_models(paper_pair: ContactPair) -> dict[str, ContactModel]:
    return {name: get_law(name).build(paper_pair, R_PAPER) for name in law_names()}
