"""Settings shared by the whole test suite.

Hypothesis runs without wall-clock deadlines: the suite runs on busy machines (CI shares its
cores), and a test that fails because the machine was slow is a flaky test. Its examples are
still bounded by each test's ``max_examples``.
"""

from __future__ import annotations

from hypothesis import settings

settings.register_profile("impactlab", deadline=None, print_blob=True)
settings.load_profile("impactlab")
