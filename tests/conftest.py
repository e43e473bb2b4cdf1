"""Test-suite settings shared by every directory.

Hypothesis runs derandomized (the examples follow from each test's code, not from a random
seed or a local example database): the suite is deterministic, so a failure reproduces on every
machine and CI never fails by the luck of the draw. Found counterexamples are added as explicit
``@example``s.
"""

from __future__ import annotations

from hypothesis import settings

settings.register_profile("impactlab", derandomize=True, database=None, print_blob=True)
settings.load_profile("impactlab")
